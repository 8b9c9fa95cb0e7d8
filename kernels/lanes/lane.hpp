// Lane types: the one vocabulary every kernel is written in, for `double` (one lane: the scalar
// reference and one GPU thread) and, in the host build, `xsimd::batch<double>` (one SIMD register).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"

#if !defined(__CUDACC__)
#include <vector>
#include <xsimd/xsimd.hpp>
#endif

namespace rotorsweep::kernels {

template <class V>
struct lane_traits;

template <>
struct lane_traits<double> {
  using mask = bool;
  static constexpr std::size_t width = 1;
};

template <class V>
using lane_mask = typename lane_traits<V>::mask;

template <class V>
inline constexpr std::size_t lane_width = lane_traits<V>::width;

// --- the scalar lane: every function is a host/device kernel function ------------------------
// Only IEEE-exact operations (+ - * /, sqrt, floor, nearbyint, frexp, ldexp, comparisons), so
// that the SIMD overloads below give the same bits lane by lane.

ROTORSWEEP_HD inline double lane_select(bool m, double a, double b) { return m ? a : b; }
ROTORSWEEP_HD inline double lane_abs(double x) { return std::fabs(x); }
/// -x by flipping the sign bit (so -(+0) = -0 in every lane type).
ROTORSWEEP_HD inline double lane_neg(double x) { return -x; }
ROTORSWEEP_HD inline double lane_min(double a, double b) { return a < b ? a : b; }
ROTORSWEEP_HD inline double lane_max(double a, double b) { return a > b ? a : b; }
ROTORSWEEP_HD inline double lane_sqrt(double x) { return std::sqrt(x); }
ROTORSWEEP_HD inline double lane_floor(double x) { return std::floor(x); }
/// Nearest integer, ties to even (the default rounding mode).
ROTORSWEEP_HD inline double lane_round(double x) { return std::nearbyint(x); }
ROTORSWEEP_HD inline bool lane_isfinite(double x) { return std::isfinite(x); }
/// Whether the sign bit is set (true for -0.0 too).
ROTORSWEEP_HD inline bool lane_signbit(double x) { return std::signbit(x); }
/// x = m 2^e with m in [1/2, 1); e returned as a double.
ROTORSWEEP_HD inline double lane_frexp(double x, double& e) {
  int exponent = 0;
  const double m = std::frexp(x, &exponent);
  e = double(exponent);
  return m;
}
/// x 2^e for an integer-valued e.
ROTORSWEEP_HD inline double lane_ldexp(double x, double e) { return std::ldexp(x, int(e)); }
ROTORSWEEP_HD inline bool lane_any(bool m) { return m; }

// --- single-lane access (outside hot loops: refill, read-out) --------------------------------

ROTORSWEEP_HD inline double lane_get(double v, std::size_t) { return v; }
ROTORSWEEP_HD inline void lane_set(double& v, std::size_t, double x) { v = x; }
ROTORSWEEP_HD inline bool mask_get(bool m, std::size_t) { return m; }

#if !defined(__CUDACC__)

/// The SIMD lane type of this build: as many doubles as the widest native register holds.
using simd_lane = xsimd::batch<double>;

template <class Arch>
struct lane_traits<xsimd::batch<double, Arch>> {
  using mask = xsimd::batch_bool<double, Arch>;
  static constexpr std::size_t width = xsimd::batch<double, Arch>::size;
};

/// Host storage for lane values, aligned for the lane type.
template <class V>
using lane_vector = std::vector<V, xsimd::aligned_allocator<V>>;

template <class Arch>
inline xsimd::batch<double, Arch> lane_select(const xsimd::batch_bool<double, Arch>& m,
                                              const xsimd::batch<double, Arch>& a,
                                              const xsimd::batch<double, Arch>& b) {
  return xsimd::select(m, a, b);
}
template <class Arch>
inline auto lane_abs(const xsimd::batch<double, Arch>& x) {
  return xsimd::abs(x);
}
// xsimd 8's AVX-512 unary minus computes 0 - x, which gives +0 for +0: flip the sign bit instead.
template <class Arch>
inline auto lane_neg(const xsimd::batch<double, Arch>& x) {
  return xsimd::bitwise_xor(x, xsimd::batch<double, Arch>(-0.0));
}
template <class Arch>
inline auto lane_min(const xsimd::batch<double, Arch>& a, const xsimd::batch<double, Arch>& b) {
  return xsimd::select(a < b, a, b);
}
template <class Arch>
inline auto lane_max(const xsimd::batch<double, Arch>& a, const xsimd::batch<double, Arch>& b) {
  return xsimd::select(a > b, a, b);
}
template <class Arch>
inline auto lane_sqrt(const xsimd::batch<double, Arch>& x) {
  return xsimd::sqrt(x);
}
template <class Arch>
inline auto lane_floor(const xsimd::batch<double, Arch>& x) {
  return xsimd::floor(x);
}
template <class Arch>
inline auto lane_round(const xsimd::batch<double, Arch>& x) {
  return xsimd::nearbyint(x);
}
template <class Arch>
inline auto lane_signbit(const xsimd::batch<double, Arch>& x) {
  using Integers = xsimd::batch<xsimd::as_integer_t<double>, Arch>;
  return xsimd::bool_cast(xsimd::bitwise_cast<Integers>(x) < Integers(0));
}
template <class Arch>
inline auto lane_isfinite(const xsimd::batch<double, Arch>& x) {
  return xsimd::isfinite(x);
}
template <class Arch>
inline bool lane_any(const xsimd::batch_bool<double, Arch>& m) {
  return xsimd::any(m);
}

template <class Arch>
inline double lane_get(const xsimd::batch<double, Arch>& v, std::size_t lane) {
  alignas(Arch::alignment()) std::array<double, xsimd::batch<double, Arch>::size> tmp;
  v.store_aligned(tmp.data());
  return tmp[lane];
}
template <class Arch>
inline void lane_set(xsimd::batch<double, Arch>& v, std::size_t lane, double x) {
  alignas(Arch::alignment()) std::array<double, xsimd::batch<double, Arch>::size> tmp;
  v.store_aligned(tmp.data());
  tmp[lane] = x;
  v = xsimd::batch<double, Arch>::load_aligned(tmp.data());
}
template <class Arch>
inline bool mask_get(const xsimd::batch_bool<double, Arch>& m, std::size_t lane) {
  return lane_get(xsimd::select(m, xsimd::batch<double, Arch>(1.0), xsimd::batch<double, Arch>(0.0)), lane) !=
         0.0;
}

template <class Arch>
inline auto lane_frexp(const xsimd::batch<double, Arch>& x, xsimd::batch<double, Arch>& e) {
  using B = xsimd::batch<double, Arch>;
  auto exponent = xsimd::batch<xsimd::as_integer_t<double>, Arch>(0);
  const B m = xsimd::frexp(x, exponent);
  e = xsimd::to_float(exponent);
  return m;
}
template <class Arch>
inline auto lane_ldexp(const xsimd::batch<double, Arch>& x, const xsimd::batch<double, Arch>& e) {
  return xsimd::ldexp(x, xsimd::to_int(e));
}

#endif  // !__CUDACC__

/// Every lane of v, in one store.
template <class V>
ROTORSWEEP_HD inline std::array<double, lane_width<V>> lane_values(const V& v) {
  if constexpr (lane_width<V> == 1) {
    return {v};
  } else if constexpr (requires { typename V::arch_type; }) {
    alignas(V::arch_type::alignment()) std::array<double, lane_width<V>> values;
    v.store_aligned(values.data());
    return values;
  } else {
    std::array<double, lane_width<V>> values;
    for (std::size_t l = 0; l < lane_width<V>; ++l) values[l] = lane_get(v, l);
    return values;
  }
}

/// A lane value whose lanes are taken from a per-lane function f(lane).
template <class V, class F>
ROTORSWEEP_HD inline V lane_from(F&& f) {
  if constexpr (lane_width<V> == 1) {
    return V(f(std::size_t(0)));
  } else if constexpr (requires { typename V::arch_type; }) {
    alignas(V::arch_type::alignment()) std::array<double, lane_width<V>> values;
    for (std::size_t l = 0; l < lane_width<V>; ++l) values[l] = f(l);
    return V::load_aligned(values.data());
  } else {
    V v;
    for (std::size_t l = 0; l < lane_width<V>; ++l) lane_set(v, l, f(l));
    return v;
  }
}

}  // namespace rotorsweep::kernels
