// The gpu port's device storage (in the backend's namespace: included by gpu/solver_impl.hpp): Thrust
// vectors, the state of a stage as arrays and as the raw pointers the kernels capture, and the reductions.
#pragma once
#include <thrust/device_vector.h>

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

struct MinOf {
  template <class T> IMPACTSPH_HD T operator()(T a, T b) const { return a < b ? a : b; }
};
struct MaxOf {
  template <class T> IMPACTSPH_HD T operator()(T a, T b) const { return a > b ? a : b; }
};

}  // namespace impactsph::gpu::IMPACTSPH_GPU_BACKEND
