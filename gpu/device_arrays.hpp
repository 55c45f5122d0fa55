// The gpu port's device storage (in the backend's namespace: included by gpu/solver_impl.hpp): Thrust
// vectors, the state of a stage as arrays and as the raw pointers the kernels capture, and the reductions.
#pragma once
#include <thrust/device_vector.h>

#include "common/particle_set.hpp"
#include "common/stages.hpp"

namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND {

template <class T> using DVec = thrust::device_vector<T>;
template <class T> T* raw(DVec<T>& v) { return thrust::raw_pointer_cast(v.data()); }

template <class Real>
struct StateArrays {
  DVec<Vec3p> pos;
  DVec<Vec3<Real>> vel;
  DVec<Real> rho, energy;
  DVec<Sym3<Real>> S;
  void resize(std::size_t n) { pos.resize(n); vel.resize(n); rho.resize(n); energy.resize(n); S.resize(n); }
};
template <class Real>
struct StateView {
  Vec3p* pos;
  Vec3<Real>* vel;
  Real* rho;
  Real* energy;
  Sym3<Real>* S;
};
template <class Real> StateView<Real> view(StateArrays<Real>& s) {
  return {raw(s.pos), raw(s.vel), raw(s.rho), raw(s.energy), raw(s.S)};
}

// The device element of a field kept on the host as Host (common/particle_set.hpp): positions in double, the
// other reals in the port's precision, integers as they are.
template <class Host, class Real, FieldKind K> struct DeviceElement { using type = Host; };
template <class Real, FieldKind K> struct DeviceElement<double, Real, K> { using type = Real; };
template <class Real> struct DeviceElement<Vec3d, Real, FieldKind::Position> { using type = Vec3p; };
template <class Real> struct DeviceElement<Vec3d, Real, FieldKind::Evolving> { using type = Vec3<Real>; };
template <class Real> struct DeviceElement<Sym3d, Real, FieldKind::Evolving> { using type = Sym3<Real>; };

// The ParticleSet on the device, in the order of the last sort: one array per field of
// IMPACTSPH_PARTICLE_FIELDS with the same name, so that for_each_field and for_each_field_pair visit it.
template <class Real>
struct DeviceParticles {
#define IMPACTSPH_DEVICE_FIELD(member, vtu, kind) \
  DVec<typename DeviceElement<typename decltype(ParticleSet::member)::value_type, Real, FieldKind::kind>::type> member;
  IMPACTSPH_PARTICLE_FIELDS(IMPACTSPH_DEVICE_FIELD)
#undef IMPACTSPH_DEVICE_FIELD
};

// The state of the step start (x, v, rho, e, S) within the device particles.
template <class Real> StateView<Real> state_view(DeviceParticles<Real>& d) {
  return {raw(d.pos), raw(d.vel), raw(d.rho), raw(d.energy), raw(d.dev_stress)};
}
// Makes `s` the state of the step start and gives the old one to s (O(1): the arrays swap).
template <class Real> void swap_state(DeviceParticles<Real>& d, StateArrays<Real>& s) {
  d.pos.swap(s.pos); d.vel.swap(s.vel); d.rho.swap(s.rho); d.energy.swap(s.energy); d.dev_stress.swap(s.S);
}

// A host value as the device keeps it, and back.
template <class D, class H> D to_device(const H& h) { return static_cast<D>(h); }
template <> inline Vec3<float> to_device<Vec3<float>, Vec3d>(const Vec3d& h) { return cast3<float>(h); }
template <> inline Vec3d to_device<Vec3d, Vec3d>(const Vec3d& h) { return h; }
template <> inline Sym3<float> to_device<Sym3<float>, Sym3d>(const Sym3d& s) {
  return {float(s.xx), float(s.yy), float(s.zz), float(s.xy), float(s.yz), float(s.zx)};
}
template <> inline Sym3d to_device<Sym3d, Sym3d>(const Sym3d& s) { return s; }
template <class H, class D> H to_host(const D& d) { return static_cast<H>(d); }
template <> inline Vec3d to_host<Vec3d, Vec3<float>>(const Vec3<float>& d) { return cast3<double>(d); }
template <> inline Vec3d to_host<Vec3d, Vec3d>(const Vec3d& d) { return d; }
template <> inline Sym3d to_host<Sym3d, Sym3<float>>(const Sym3<float>& s) {
  return {double(s.xx), double(s.yy), double(s.zz), double(s.xy), double(s.yz), double(s.zx)};
}
template <> inline Sym3d to_host<Sym3d, Sym3d>(const Sym3d& s) { return s; }

struct MinOf {
  template <class T> IMPACTSPH_HD T operator()(T a, T b) const { return a < b ? a : b; }
};
struct MaxOf {
  template <class T> IMPACTSPH_HD T operator()(T a, T b) const { return a > b ? a : b; }
};

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND
