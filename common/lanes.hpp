// Lanes<T>: kLanes values of T held in one SIMD register (a GCC vector type), for the pair loops of the gpu
// port's host build over cluster pairs (gpu/solver_clusters.hpp). The common/ pair functions are templates on Real;
// with Real = Lanes<T> each lane is one neighbour, and the overloads below (choose, any_true, min_of, max_of,
// sqrt, norm, exp) stand where the scalar functions compare, take a root or an exponential. A comparison
// gives a LaneMask. Host only.
#pragma once
#if defined(__CUDACC__)
#error "common/lanes.hpp is for host builds only"
#endif
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>
#if defined(__AVX__)
#include <immintrin.h>
#endif

#include "common/tensor.hpp"

namespace impactsph {

inline constexpr int kLanes = 8;

// The integer lane type of the same width as T, which GCC's vector comparisons return.
template <class T> using LaneInt = std::conditional_t<sizeof(T) == 8, std::int64_t, std::int32_t>;

// One flag per lane, as GCC vector comparisons give it: all bits set (true) or none (false).
template <class T>
struct LaneMask {
  typedef LaneInt<T> V __attribute__((vector_size(kLanes * sizeof(LaneInt<T>))));
  V v;
  friend LaneMask operator&(LaneMask a, LaneMask b) { return {a.v & b.v}; }
  friend LaneMask operator|(LaneMask a, LaneMask b) { return {a.v | b.v}; }
  friend LaneMask operator!(LaneMask a) { return {~a.v}; }
};

template <class T>
struct Lanes {
  typedef T V __attribute__((vector_size(kLanes * sizeof(T))));
  V v;
  Lanes() = default;
  Lanes(T s) : v(V{} + s) {}  // every lane s
  explicit Lanes(const V& a) : v(a) {}
  static Lanes load(const T* p) {
    Lanes r;
    std::memcpy(&r.v, p, sizeof(V));
    return r;
  }

  friend Lanes operator+(Lanes a, Lanes b) { return Lanes(a.v + b.v); }
  friend Lanes operator-(Lanes a, Lanes b) { return Lanes(a.v - b.v); }
  friend Lanes operator*(Lanes a, Lanes b) { return Lanes(a.v * b.v); }
  friend Lanes operator/(Lanes a, Lanes b) { return Lanes(a.v / b.v); }
  friend Lanes operator-(Lanes a) { return Lanes(-a.v); }
  Lanes& operator+=(Lanes b) { v += b.v; return *this; }
  Lanes& operator-=(Lanes b) { v -= b.v; return *this; }
  Lanes& operator*=(Lanes b) { v *= b.v; return *this; }
  friend LaneMask<T> operator<(Lanes a, Lanes b) { return {a.v < b.v}; }
  friend LaneMask<T> operator<=(Lanes a, Lanes b) { return {a.v <= b.v}; }
  friend LaneMask<T> operator>(Lanes a, Lanes b) { return {a.v > b.v}; }
  friend LaneMask<T> operator>=(Lanes a, Lanes b) { return {a.v >= b.v}; }
  friend LaneMask<T> operator==(Lanes a, Lanes b) { return {a.v == b.v}; }
};

template <class T> struct ScalarType<Lanes<T>> { using type = T; };

template <class T>
struct Constants<Lanes<T>> {
  static inline const Lanes<T> pi = Lanes<T>(Constants<T>::pi);
};

// kLanes integers from p, widened to the lane width of T (for masks against LaneMask<T>).
template <class T> inline typename LaneMask<T>::V load_lane_ints(const std::int32_t* p) {
  typedef std::int32_t V32 __attribute__((vector_size(kLanes * sizeof(std::int32_t))));
  V32 a;
  std::memcpy(&a, p, sizeof(V32));
  return __builtin_convertvector(a, typename LaneMask<T>::V);
}

// Lane by lane a where m, else b: the lane form of `m ? a : b`.
template <class T> inline Lanes<T> choose(LaneMask<T> m, Lanes<T> a, Lanes<T> b) { return Lanes<T>(m.v ? a.v : b.v); }
template <class T> inline Vec3<Lanes<T>> choose(LaneMask<T> m, const Vec3<Lanes<T>>& a, const Vec3<Lanes<T>>& b) {
  return {choose(m, a.x, b.x), choose(m, a.y, b.y), choose(m, a.z, b.z)};
}
template <class T> inline Mat3<Lanes<T>> choose(LaneMask<T> m, const Mat3<Lanes<T>>& a, const Mat3<Lanes<T>>& b) {
  Mat3<Lanes<T>> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = choose(m, a.m[i][j], b.m[i][j]);
  return r;
}
template <class T> inline bool any_true(LaneMask<T> m) {
  for (int k = 0; k < kLanes; ++k)
    if (m.v[k]) return true;
  return false;
}
template <class T> inline Lanes<T> min_of(Lanes<T> a, Lanes<T> b) { return choose(a < b, a, b); }
template <class T> inline Lanes<T> max_of(Lanes<T> a, Lanes<T> b) { return choose(a > b, a, b); }

// Square root of each lane, correctly rounded as std::sqrt is.
inline Lanes<float> sqrt(Lanes<float> a) {
#if defined(__AVX__)
  return Lanes<float>(reinterpret_cast<Lanes<float>::V>(_mm256_sqrt_ps(reinterpret_cast<__m256>(a.v))));
#else
  Lanes<float> r;
  for (int k = 0; k < kLanes; ++k) r.v[k] = std::sqrt(a.v[k]);
  return r;
#endif
}
inline Lanes<double> sqrt(Lanes<double> a) {
#if defined(__AVX512F__)
  const __m512d x = reinterpret_cast<__m512d>(a.v);
  return Lanes<double>(reinterpret_cast<Lanes<double>::V>(_mm512_mask_sqrt_pd(x, 0xff, x)));  // (GCC 12 warns
                                                                                                  // on _mm512_sqrt_pd)
#else
  Lanes<double> r;
  for (int k = 0; k < kLanes; ++k) r.v[k] = std::sqrt(a.v[k]);
  return r;
#endif
}
template <class T> inline Lanes<T> norm(Vec3<Lanes<T>> a) { return sqrt(dot(a, a)); }

// e^x of each lane by std::exp, lane by lane: the same bits as the scalar path (the limited viscosity's
// close-approach fade, common/viscosity.hpp, the one exponential of the pair terms).
template <class T> inline Lanes<T> exp(Lanes<T> a) {
  Lanes<T> r;
  for (int k = 0; k < kLanes; ++k) r.v[k] = std::exp(a.v[k]);
  return r;
}

// Each lane rounded to another type (double positions to the Real of the pair terms).
template <class To, class From> inline Lanes<To> lanes_cast(Lanes<From> a) {
  if constexpr (std::is_same_v<To, From>) return a;
  else return Lanes<To>(__builtin_convertvector(a.v, typename Lanes<To>::V));
}
template <class To, class From> inline Vec3<Lanes<To>> lanes_cast(Vec3<Lanes<From>> a) {
  return {lanes_cast<To>(a.x), lanes_cast<To>(a.y), lanes_cast<To>(a.z)};
}

// The lanes summed in order 0, 1, ..., kLanes - 1 (a fixed order: the same bits on every run).
template <class T> inline T lane_sum(Lanes<T> a) {
  T s = a.v[0];
  for (int k = 1; k < kLanes; ++k) s += a.v[k];
  return s;
}
template <class T> inline Vec3<T> lane_sum(const Vec3<Lanes<T>>& a) { return {lane_sum(a.x), lane_sum(a.y), lane_sum(a.z)}; }
template <class T> inline Mat3<T> lane_sum(const Mat3<Lanes<T>>& a) {
  Mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = lane_sum(a.m[i][j]);
  return r;
}

}  // namespace impactsph
