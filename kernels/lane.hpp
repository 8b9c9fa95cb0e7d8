// Lane types: the one vocabulary every kernel is written in, for `double` (one lane, the
// scalar reference) and `xsimd::batch<double>` (one SIMD register of independent members).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>
#include <xsimd/xsimd.hpp>

namespace rotorsweep::kernels {

/// The SIMD lane type of this build: as many doubles as the widest native register holds.
using simd_lane = xsimd::batch<double>;

template <class V>
struct lane_traits;

template <>
struct lane_traits<double> {
  using mask = bool;
  static constexpr std::size_t width = 1;
};

template <class Arch>
struct lane_traits<xsimd::batch<double, Arch>> {
  using mask = xsimd::batch_bool<double, Arch>;
  static constexpr std::size_t width = xsimd::batch<double, Arch>::size;
};

template <class V>
using lane_mask = typename lane_traits<V>::mask;

template <class V>
inline constexpr std::size_t lane_width = lane_traits<V>::width;

/// Storage for lane values, aligned for the lane type.
template <class V>
using lane_vector = std::vector<V, xsimd::aligned_allocator<V>>;

// --- element-wise operations that exist for both lane types -------------------------------

/// The scalar sincos runs xsimd's SIMD polynomial and keeps lane 0, so that scalar and SIMD
/// instantiations round identically and agree bit for bit.
inline void lane_sincos(double x, double& s, double& c) {
  const auto sc = xsimd::sincos(simd_lane(x));
  s = sc.first.get(0);
  c = sc.second.get(0);
}

template <class Arch>
inline void lane_sincos(const xsimd::batch<double, Arch>& x, xsimd::batch<double, Arch>& s,
                        xsimd::batch<double, Arch>& c) {
  auto sc = xsimd::sincos(x);
  s = sc.first;
  c = sc.second;
}

inline double lane_select(bool m, double a, double b) { return m ? a : b; }
template <class Arch>
inline xsimd::batch<double, Arch> lane_select(const xsimd::batch_bool<double, Arch>& m,
                                              const xsimd::batch<double, Arch>& a,
                                              const xsimd::batch<double, Arch>& b) {
  return xsimd::select(m, a, b);
}

/// Like lane_sincos: the scalar pow runs xsimd's SIMD algorithm, so step sizes match bit for bit.
inline double lane_pow(double x, double p) { return xsimd::pow(simd_lane(x), simd_lane(p)).get(0); }

inline double lane_abs(double x) { return std::fabs(x); }
inline double lane_min(double a, double b) { return a < b ? a : b; }
inline double lane_max(double a, double b) { return a > b ? a : b; }
inline double lane_sqrt(double x) { return std::sqrt(x); }
inline bool lane_isfinite(double x) { return std::isfinite(x); }

template <class Arch>
inline auto lane_abs(const xsimd::batch<double, Arch>& x) {
  return xsimd::abs(x);
}
template <class Arch>
inline auto lane_min(const xsimd::batch<double, Arch>& a, const xsimd::batch<double, Arch>& b) {
  return xsimd::min(a, b);
}
template <class Arch>
inline auto lane_max(const xsimd::batch<double, Arch>& a, const xsimd::batch<double, Arch>& b) {
  return xsimd::max(a, b);
}
template <class Arch>
inline auto lane_sqrt(const xsimd::batch<double, Arch>& x) {
  return xsimd::sqrt(x);
}
template <class Arch>
inline auto lane_pow(const xsimd::batch<double, Arch>& x, double p) {
  return xsimd::pow(x, xsimd::batch<double, Arch>(p));
}
template <class Arch>
inline auto lane_isfinite(const xsimd::batch<double, Arch>& x) {
  return xsimd::isfinite(x);
}

// --- masks -----------------------------------------------------------------------------------

inline bool lane_any(bool m) { return m; }
template <class Arch>
inline bool lane_any(const xsimd::batch_bool<double, Arch>& m) {
  return xsimd::any(m);
}

// --- single-lane access (outside hot loops: refill, read-out) --------------------------------

inline double lane_get(double v, std::size_t) { return v; }
inline void lane_set(double& v, std::size_t, double x) { v = x; }
inline bool mask_get(bool m, std::size_t) { return m; }

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

/// A lane value whose lanes are taken from a per-lane function f(lane).
template <class V, class F>
inline V lane_from(F&& f) {
  if constexpr (lane_width<V> == 1) {
    return V(f(std::size_t(0)));
  } else {
    alignas(V::arch_type::alignment()) std::array<double, lane_width<V>> values;
    for (std::size_t l = 0; l < lane_width<V>; ++l) values[l] = f(l);
    return V::load_aligned(values.data());
  }
}

}  // namespace rotorsweep::kernels
