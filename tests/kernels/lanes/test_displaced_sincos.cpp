// sin and cos of x + δ by angle addition (kernels/lanes/displaced_sincos.hpp): within ulps of the exact
// values on both sides of the Taylor reach, and a lane's bits depend on its own x and δ alone.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <vector>

#include "kernels/lanes/displaced_sincos.hpp"

using namespace rotorsweep::kernels;

namespace {

constexpr std::size_t W = lane_width<simd_lane>;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

const std::vector<double> starts{0.0, 0.3, -1.2, 3.14159, 20.0, -55.123, 62.9, 1000.5, 0.7854, 1.0e5};
/// Inside the reach (zero, tiny, large, at the edge) and beyond it.
const std::vector<double> displacements{0.0,    -0.0,    1e-12,  -3e-7, 1e-3, -0.02, 0.05,
                                        0.0625, -0.0625, 0.0626, -0.07, 0.5,  -2.0,  7.0};

struct Displaced {
  double s, c;
};

Displaced displaced(double x, double delta) {
  double sx = 0, cx = 0;
  lane_sincos(x, sx, cx);
  Displaced d{};
  lane_sincos_displaced(x, delta, sx, cx, d.s, d.c);
  return d;
}

}  // namespace

TEST_CASE("within the reach the displaced sincos is within two ulps of 1 of sin and cos of x + delta",
          "[kernels][lane_math]") {
  // exact x + δ in long double (64-bit mantissa) up to |x| ~ 1000; beyond the reach the result is
  // lane_sincos(x + δ) (next case), whose argument is x + δ rounded to double
  for (double x : starts)
    for (double delta : displacements) {
      if (std::fabs(x) > 1001.0 || std::fabs(delta) > displaced_sincos_reach) continue;
      const Displaced d = displaced(x, delta);
      const long double exact = static_cast<long double>(x) + static_cast<long double>(delta);
      const double error_s = std::fabs(double(static_cast<long double>(d.s) - std::sin(exact)));
      const double error_c = std::fabs(double(static_cast<long double>(d.c) - std::cos(exact)));
      INFO("x = " << x << ", delta = " << delta);
      CHECK(error_s <= 0x1p-51);
      CHECK(error_c <= 0x1p-51);
    }
}

TEST_CASE("beyond the Taylor reach the displaced sincos is lane_sincos of x + delta",
          "[kernels][lane_math]") {
  for (double x : starts)
    for (double delta : {0.0626, -0.07, 0.5, -2.0, 7.0}) {
      const Displaced d = displaced(x, delta);
      double s = 0, c = 0;
      lane_sincos(x + delta, s, c);
      CHECK(same_bits(d.s, s));
      CHECK(same_bits(d.c, c));
    }
}

TEST_CASE("displaced sincos of a lane depends on its own x and delta, whatever its neighbours",
          "[kernels][lane_math]") {
  // every window of W consecutive (x, δ) pairs as one block: near and far lanes side by side
  std::vector<std::pair<double, double>> pairs;
  for (double x : starts)
    for (double delta : displacements) pairs.emplace_back(x, delta);
  for (std::size_t start = 0; start < pairs.size(); ++start) {
    const auto at = [&](std::size_t l) { return pairs[(start + l * 13) % pairs.size()]; };
    const simd_lane x = lane_from<simd_lane>([&](std::size_t l) { return at(l).first; });
    const simd_lane delta = lane_from<simd_lane>([&](std::size_t l) { return at(l).second; });
    simd_lane sx, cx, s, c;
    lane_sincos(x, sx, cx);
    lane_sincos_displaced(x, delta, sx, cx, s, c);
    for (std::size_t l = 0; l < W; ++l) {
      const Displaced d = displaced(at(l).first, at(l).second);
      CHECK(same_bits(lane_get(s, l), d.s));
      CHECK(same_bits(lane_get(c, l), d.c));
    }
  }
}
