// Portable sin/cos, exp, log and pow on any lane type, built from exactly rounded lane operations
// only, so that a lane's bits depend on its own argument alone: scalar, SIMD and GPU lanes agree.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"

namespace rotorsweep::kernels {

// The algorithms and coefficients are those of xsimd 8's double-precision sincos, exp and log
// (after Cephes, fdlibm and Boost.SIMD), written once for every lane type. The difference is the
// range reduction of sincos: xsimd picks one method for a whole batch from its largest argument,
// so a lane's bits changed with its neighbours; here every lane picks by its own argument.
namespace lane_math_detail {

inline constexpr double pio2_1 = 0x1.921fb544p+0, pio2_1t = 0x1.0b4611a626331p-34;
inline constexpr double pio2_2 = 0x1.0b4611a6p-34, pio2_2t = 0x1.3198a2e037073p-69;
inline constexpr double pio2_3 = 0x1.3198a2ep-69, pio2_3t = 0x1.b839a252049c1p-104;
inline constexpr double two_over_pi = 0x1.45f306dc9c883p-1;
inline constexpr double twenty_pi = 0x1.f6a7a2955385ep+5;
inline constexpr double medium_pi = 0x1.921fb54442d18p+19;  ///< 2^19 π: limit of the 3-part reduction

/// c0 + x (c1 + x (c2 + ...)), every product and sum rounded on its own (no fused multiply-add:
/// the host build turns contraction off, a CUDA build must pass --fmad=false).
template <class V, std::size_t n>
ROTORSWEEP_HD inline V horner(const V& x, const std::array<double, n>& c) {
  V sum(c[n - 1]);
  for (std::size_t i = n - 1; i-- > 0;) sum = x * sum + V(c[i]);
  return sum;
}

inline constexpr std::array<double, 6> sin_c{-0x1.5555555555548p-3,  0x1.111111110f7dp-7,
                                             -0x1.a01a019bfdf03p-13, 0x1.71de3567d4896p-19,
                                             -0x1.ae5e5a9291691p-26, 0x1.5d8fd1fcf0ec1p-33};
inline constexpr std::array<double, 7> cos_c{0x1p-1,
                                             -0x1.5555555555551p-5,
                                             0x1.6c16c16c15d47p-10,
                                             -0x1.a01a019ddbcd9p-16,
                                             0x1.27e4f8e06d9a5p-22,
                                             -0x1.1eea7c1e514d4p-29,
                                             0x1.8ff831ad9b219p-37};

inline constexpr double ln2_hi = 0x1.62e42feep-1, ln2_lo = 0x1.a39ef35793c76p-33;
inline constexpr double inv_ln2 = 1.442695040888963407359924681001892137426645954152986;
inline constexpr double max_log = 709.78271289338400, min_log = -708.3964185322641;
inline constexpr std::array<double, 5> exp_c{0x1.555555555553ep-3, -0x1.6c16c16bebd93p-9,
                                             0x1.1566aaf25de2cp-14, -0x1.bbd41c5d26bf1p-20,
                                             0x1.6376972bea4dp-25};
inline constexpr std::array<double, 3> log_c_odd{0x1.999999997fa04p-2, 0x1.c71c51d8e78afp-3,
                                                 0x1.39a09d078c69fp-3};
inline constexpr std::array<double, 4> log_c_even{0x1.5555555555593p-1, 0x1.2492494229359p-2,
                                                  0x1.7466496cb03dep-3, 0x1.2f112df3e5244p-3};

/// Lanes beyond 2^19 π: the platform's sin and cos, lane by lane (the same call for a scalar and
/// a SIMD lane, so they still agree; a physical run never gets there).
ROTORSWEEP_HD inline void far_sincos(double x, double& s, double& c) {
  s = std::sin(x);
  c = std::cos(x);
}

}  // namespace lane_math_detail

/// s = sin x, c = cos x. Each lane reduces its own |x| to r in [-π/4, π/4] and a quadrant:
/// up to 20π with a three-part π/2, up to 2^19 π with the compensated
/// three-part reduction, beyond that by the platform's functions.
template <class V>
ROTORSWEEP_HD ROTORSWEEP_INLINE void lane_sincos(const V& self, V& s, V& c) {
  using namespace lane_math_detail;
  const V x = lane_abs(self);
  V n = lane_round(x * V(two_over_pi));
  V r = x - n * V(pio2_1);
  r = r - n * V(pio2_2);
  r = r - n * V(pio2_3);
  const auto medium = x > V(twenty_pi);
  if (lane_any(medium)) {
    V t = x - n * V(pio2_1);
    V w = n * V(pio2_2);
    V u = t - w;
    w = n * V(pio2_2t) - ((t - u) - w);
    t = u;
    w = n * V(pio2_3);
    u = t - w;
    w = n * V(pio2_3t) - ((t - u) - w);
    r = lane_select(medium, u - w, r);
  }
  const V a = n * V(0.25);
  const V quadrant = (a - lane_floor(a)) * V(4.0);
  const V upper = lane_select(quadrant >= V(2.0), V(1.0), V(0.0));
  const V swap = V(-2.0) * upper + quadrant;
  const V z = r * r;
  constexpr auto sin_k = sin_c;  // local copies: device code never reads the host tables
  constexpr auto cos_k = cos_c;
  const V sin_r = (horner(z, sin_k) * z) * r + r;
  const V cos_r = V(1.0) - horner(z, cos_k) * z;
  const V sin_x = lane_select(swap == V(0.0), sin_r, cos_r);
  const V cos_x = lane_select(swap != V(0.0), sin_r, cos_r);
  // two flips, not a comparison of two masks: xsimd 8's SSE2 compares masks as doubles (NaNs)
  s = lane_select(upper != V(0.0), lane_neg(sin_x), sin_x);
  s = lane_select(lane_signbit(self), lane_neg(s), s);
  c = lane_select(swap != upper, lane_neg(cos_x), cos_x);

  const auto far = x > V(medium_pi);
  if (lane_any(far)) {
    for (std::size_t l = 0; l < lane_width<V>; ++l) {
      if (!mask_get(far, l)) continue;
      double sl = 0, cl = 0;
      far_sincos(lane_get(self, l), sl, cl);
      lane_set(s, l, sl);
      lane_set(c, l, cl);
    }
  }
}

/// e^x (0 below -708.4, infinity above 709.8).
template <class V>
ROTORSWEEP_HD inline V lane_exp(const V& self) {
  using namespace lane_math_detail;
  const V k = lane_round(V(inv_ln2) * self);
  const V hi = self - k * V(ln2_hi);
  const V lo = k * V(ln2_lo);
  const V x = hi - lo;
  const V t = x * x;
  constexpr auto exp_k = exp_c;
  const V c = x - t * horner(t, exp_k);
  const V y = V(1.0) - ((lo - (x * c) / (V(2.0) - c)) - hi);
  const V result = lane_select(self <= V(min_log), V(0.0), lane_ldexp(y, k));
  return lane_select(self >= V(max_log), V(INFINITY), result);
}

/// ln x for finite normal x > 0.
template <class V>
ROTORSWEEP_HD inline V lane_log(const V& self) {
  using namespace lane_math_detail;
  V k(0.0);
  V m = lane_frexp(self, k);  // self = m 2^k, m in [1/2, 1)
  const auto low = m < V(0x1.6a09ep-1);
  m = lane_select(low, m + m, m);
  k = lane_select(low, k - V(1.0), k);
  const V f = m - V(1.0);
  const V half_f2 = V(0.5) * f * f;
  const V s = f / (V(2.0) + f);
  const V z = s * s, w = z * z;
  constexpr auto odd = log_c_odd;
  constexpr auto even = log_c_even;
  const V t1 = w * horner(w, odd);
  const V t2 = z * horner(w, even);
  const V R = t2 + t1;
  return k * V(ln2_hi) + ((s * (half_f2 + R) + k * V(ln2_lo)) - half_f2 + f);
}

/// x^p = e^(p ln x) for finite normal x > 0 (the step-size controller's error^(-1/(q+1))).
template <class V>
ROTORSWEEP_HD inline V lane_pow(const V& x, double p) {
  return lane_exp(V(p) * lane_log(x));
}

}  // namespace rotorsweep::kernels
