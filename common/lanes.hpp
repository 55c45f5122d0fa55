// Lanes<T>: kLanes<T> values of T held in one SIMD register of the building machine (a GCC vector type: 8
// doubles or 16 floats with AVX-512, 4 or 8 with AVX, 2 or 4 with SSE2), for the pair loops of the gpu port's
// host build over cluster pairs (gpu/solver_clusters.hpp). The common/ pair functions are templates on Real;
// with Real = Lanes<T> each lane is one neighbour, and the overloads below (choose, any_true, min_of, max_of,
// sqrt, norm, exp) stand where the scalar functions compare, take a root or an exponential. A comparison gives
// a LaneMask. Lanes<double, kLanes<float>> holds the double positions of the float lanes (two registers).
// Host only.
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

// Bytes in one SIMD register of the building machine. A GCC vector wider than the machine's registers is
// split by the compiler, and its comparisons and masks partly lane by lane through memory: with 16 float
// lanes on an AVX2 machine, the cluster pairs took 1.9x the time of the rows (gpu/README.md).
#if defined(__AVX512F__)
inline constexpr int kSimdBytes = 64;
#elif defined(__AVX__)
inline constexpr int kSimdBytes = 32;
#else
inline constexpr int kSimdBytes = 16;
#endif

// Values of T in one SIMD register.
template <class T> inline constexpr int kLanes = static_cast<int>(kSimdBytes / sizeof(T));

// The integer lane type of the same width as T, which GCC's vector comparisons return.
template <class T> using LaneInt = std::conditional_t<sizeof(T) == 8, std::int64_t, std::int32_t>;

// One flag per lane, as GCC vector comparisons give it: all bits set (true) or none (false).
template <class T, int N = kLanes<T>>
struct LaneMask {
  typedef LaneInt<T> V __attribute__((vector_size(N * sizeof(LaneInt<T>))));
  V v;
  static LaneMask every(bool b) { return {V{} + (b ? -1 : 0)}; }  // every lane b
  friend LaneMask operator&(LaneMask a, LaneMask b) { return {a.v & b.v}; }
  friend LaneMask operator|(LaneMask a, LaneMask b) { return {a.v | b.v}; }
  friend LaneMask operator!(LaneMask a) { return {~a.v}; }
};

template <class T, int N = kLanes<T>>
struct Lanes {
  typedef T V __attribute__((vector_size(N * sizeof(T))));
  using Mask = LaneMask<T, N>;
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
  friend Mask operator<(Lanes a, Lanes b) { return {a.v < b.v}; }
  friend Mask operator<=(Lanes a, Lanes b) { return {a.v <= b.v}; }
  friend Mask operator>(Lanes a, Lanes b) { return {a.v > b.v}; }
  friend Mask operator>=(Lanes a, Lanes b) { return {a.v >= b.v}; }
  friend Mask operator==(Lanes a, Lanes b) { return {a.v == b.v}; }
};

template <class T, int N> struct ScalarType<Lanes<T, N>> { using type = T; };

template <class T, int N>
struct Constants<Lanes<T, N>> {
  static inline const Lanes<T, N> pi = Lanes<T, N>(Constants<T>::pi);
};

// N integers from p, widened to the lane width of T (for masks against LaneMask<T, N>).
template <class T, int N = kLanes<T>> inline typename LaneMask<T, N>::V load_lane_ints(const std::int32_t* p) {
  typedef std::int32_t V32 __attribute__((vector_size(N * sizeof(std::int32_t))));
  V32 a;
  std::memcpy(&a, p, sizeof(V32));
  return __builtin_convertvector(a, typename LaneMask<T, N>::V);
}

// Lane by lane a where m, else b: the lane form of `m ? a : b`.
template <class T, int N> inline Lanes<T, N> choose(LaneMask<T, N> m, Lanes<T, N> a, Lanes<T, N> b) {
  return Lanes<T, N>(m.v ? a.v : b.v);
}
template <class T, int N>
inline Vec3<Lanes<T, N>> choose(LaneMask<T, N> m, const Vec3<Lanes<T, N>>& a, const Vec3<Lanes<T, N>>& b) {
  return {choose(m, a.x, b.x), choose(m, a.y, b.y), choose(m, a.z, b.z)};
}
template <class T, int N>
inline Mat3<Lanes<T, N>> choose(LaneMask<T, N> m, const Mat3<Lanes<T, N>>& a, const Mat3<Lanes<T, N>>& b) {
  Mat3<Lanes<T, N>> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = choose(m, a.m[i][j], b.m[i][j]);
  return r;
}
template <class T, int N> inline bool any_true(LaneMask<T, N> m) {
  for (int k = 0; k < N; ++k)
    if (m.v[k]) return true;
  return false;
}
template <class T, int N> inline Lanes<T, N> min_of(Lanes<T, N> a, Lanes<T, N> b) { return choose(a < b, a, b); }
template <class T, int N> inline Lanes<T, N> max_of(Lanes<T, N> a, Lanes<T, N> b) { return choose(a > b, a, b); }

// Square root of each lane, correctly rounded as std::sqrt is (one instruction where the lanes fill a
// 512-bit register and the machine has AVX-512, the masked form, as GCC 12 warns on _mm512_sqrt_pd; one per
// 256-bit half with AVX).
template <class T, int N> inline Lanes<T, N> sqrt(Lanes<T, N> a) {
#if defined(__AVX__)
  if constexpr (sizeof(a.v) % 32 == 0 && kSimdBytes == 32 && (std::is_same_v<T, double> || std::is_same_v<T, float>)) {
    Lanes<T, N> r;
    for (std::size_t k = 0; k < sizeof(a.v) / 32; ++k) {
      if constexpr (std::is_same_v<T, double>) {
        __m256d x;
        std::memcpy(&x, reinterpret_cast<const char*>(&a.v) + 32 * k, 32);
        x = _mm256_sqrt_pd(x);
        std::memcpy(reinterpret_cast<char*>(&r.v) + 32 * k, &x, 32);
      } else {
        __m256 x;
        std::memcpy(&x, reinterpret_cast<const char*>(&a.v) + 32 * k, 32);
        x = _mm256_sqrt_ps(x);
        std::memcpy(reinterpret_cast<char*>(&r.v) + 32 * k, &x, 32);
      }
    }
    return r;
  }
#endif
#if defined(__AVX512F__)
  if constexpr (sizeof(a.v) == 64 && std::is_same_v<T, double>) {
    const __m512d x = reinterpret_cast<__m512d>(a.v);
    return Lanes<T, N>(reinterpret_cast<typename Lanes<T, N>::V>(_mm512_mask_sqrt_pd(x, 0xff, x)));
  }
  if constexpr (sizeof(a.v) == 64 && std::is_same_v<T, float>) {
    const __m512 x = reinterpret_cast<__m512>(a.v);
    return Lanes<T, N>(reinterpret_cast<typename Lanes<T, N>::V>(_mm512_mask_sqrt_ps(x, 0xffff, x)));
  }
#endif
  Lanes<T, N> r;
  for (int k = 0; k < N; ++k) r.v[k] = std::sqrt(a.v[k]);
  return r;
}
template <class T, int N> inline Lanes<T, N> norm(Vec3<Lanes<T, N>> a) { return sqrt(dot(a, a)); }

// e^x of each lane by std::exp, lane by lane: the same bits as the scalar path (the limited viscosity's
// close-approach fade, common/viscosity.hpp, the one exponential of the pair terms).
template <class T, int N> inline Lanes<T, N> exp(Lanes<T, N> a) {
  Lanes<T, N> r;
  for (int k = 0; k < N; ++k) r.v[k] = std::exp(a.v[k]);
  return r;
}

// Each lane rounded to another type (double positions to the Real of the pair terms).
template <class To, class From, int N> inline Lanes<To, N> lanes_cast(Lanes<From, N> a) {
  if constexpr (std::is_same_v<To, From>) return a;
  else return Lanes<To, N>(__builtin_convertvector(a.v, typename Lanes<To, N>::V));
}
template <class To, class From, int N> inline Vec3<Lanes<To, N>> lanes_cast(Vec3<Lanes<From, N>> a) {
  return {lanes_cast<To>(a.x), lanes_cast<To>(a.y), lanes_cast<To>(a.z)};
}

// The lanes summed in order 0, 1, ..., N - 1 (a fixed order: the same bits on every run).
template <class T, int N> inline T lane_sum(Lanes<T, N> a) {
  T s = a.v[0];
  for (int k = 1; k < N; ++k) s += a.v[k];
  return s;
}
template <class T, int N> inline Vec3<T> lane_sum(const Vec3<Lanes<T, N>>& a) {
  return {lane_sum(a.x), lane_sum(a.y), lane_sum(a.z)};
}
template <class T, int N> inline Mat3<T> lane_sum(const Mat3<Lanes<T, N>>& a) {
  Mat3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = lane_sum(a.m[i][j]);
  return r;
}

}  // namespace impactsph
