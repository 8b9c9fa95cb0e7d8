// sin and cos of x + δ from sin x and cos x by angle addition (docs/numerics.md "Stage
// trigonometry"): Taylor polynomials of δ for |δ| <= 1/16, the full lane_sincos in other lanes.
#pragma once

#include <array>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_math.hpp"

namespace rotorsweep::kernels {

/// Largest |δ| that the Taylor polynomials cover: their truncation error there is below 1e-20.
inline constexpr double displaced_sincos_reach = 0.0625;

/// s = sin(x + δ), c = cos(x + δ), given sin_x = sin x and cos_x = cos x:
///   sin(x + δ) = sin x + (cos x · sin δ + sin x · (cos δ − 1)),
///   cos(x + δ) = cos x + (cos x · (cos δ − 1) − sin x · sin δ),
/// with sin δ to δ⁹ and cos δ − 1 to δ¹⁰ (a NaN δ gives NaN). Lanes with |δ| > 1/16 take
/// lane_sincos(x + δ); each lane's choice and bits depend on its own x and δ alone.
template <class V>
ROTORSWEEP_HD ROTORSWEEP_INLINE void lane_sincos_displaced(const V& x, const V& delta, const V& sin_x, const V& cos_x,
                                                V& s, V& c) {
  constexpr std::array<double, 4> sin_k{-1.0 / 6, 1.0 / 120, -1.0 / 5040, 1.0 / 362880};
  constexpr std::array<double, 5> cos_k{-1.0 / 2, 1.0 / 24, -1.0 / 720, 1.0 / 40320, -1.0 / 3628800};
  const V z = delta * delta;
  const V sin_delta = delta + (delta * z) * lane_math_detail::horner(z, sin_k);
  const V cos_delta_minus_1 = z * lane_math_detail::horner(z, cos_k);
  // both as sums (a + (−b) is a − b exactly): GCC 12's vectoriser fuses an adjacent pair p + q,
  // p − q of products into one vfmsubadd even under -ffp-contract=off, which changes the bits
  s = sin_x + (cos_x * sin_delta + sin_x * cos_delta_minus_1);
  c = cos_x + (cos_x * cos_delta_minus_1 + lane_neg(sin_x) * sin_delta);
  const auto far = lane_abs(delta) > V(displaced_sincos_reach);
  if (lane_any(far)) {
    V s_far(0.0), c_far(0.0);
    lane_sincos(x + delta, s_far, c_far);
    s = lane_select(far, s_far, s);
    c = lane_select(far, c_far, c);
  }
}

}  // namespace rotorsweep::kernels
