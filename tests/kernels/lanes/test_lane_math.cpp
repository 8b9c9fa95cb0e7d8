// The portable sincos, exp, log and pow (kernels/lanes/lane_math.hpp): a lane's bits depend on its own
// argument alone, in blocks that mix the three sincos range reductions, and stay within ulps of libm.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <vector>

#include "kernels/lanes/lane_math.hpp"

using namespace rotorsweep::kernels;

namespace {

constexpr std::size_t W = lane_width<simd_lane>;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// Arguments of every size class: below 20π, between 20π and 2^19 π, beyond; signed and zero.
const std::vector<double> sincos_arguments{0.0,  -0.0,  0.3,    -1.2,   3.14159, 20.0,    62.8,
                                           62.9, -70.0, 1000.5, 1.0e5,  -1.6e6,  1.7e6,   2.0e6,
                                           1e10, -1e15, 1e300,  0.7854, 40.0,    -55.123, 1.0e-300};

/// Every window of W consecutive arguments (cyclically) as one SIMD block, so each argument
/// meets neighbours of every other size class in every lane position.
template <class F>
void for_each_block(const std::vector<double>& args, F&& check) {
  for (std::size_t start = 0; start < args.size(); ++start) {
    const simd_lane x = lane_from<simd_lane>([&](std::size_t l) { return args[(start + l) % args.size()]; });
    check(x);
  }
}

}  // namespace

TEST_CASE("sincos of a lane depends on its own argument, whatever its neighbours", "[kernels][lane_math]") {
  for_each_block(sincos_arguments, [](const simd_lane& x) {
    simd_lane s, c;
    lane_sincos(x, s, c);
    for (std::size_t l = 0; l < W; ++l) {
      double ss = 0, cs = 0;
      lane_sincos(lane_get(x, l), ss, cs);
      INFO("x = " << lane_get(x, l));
      CHECK(same_bits(lane_get(s, l), ss));
      CHECK(same_bits(lane_get(c, l), cs));
    }
  });
}

TEST_CASE("sincos is within two ulps of libm for every reduction", "[kernels][lane_math]") {
  for (double x : sincos_arguments) {
    if (std::fabs(x) > 1e9) continue;  // libm itself differs by platform there
    double s = 0, c = 0;
    lane_sincos(x, s, c);
    INFO("x = " << x);
    CHECK(std::fabs(s - std::sin(x)) <= 2 * 0x1p-53);
    CHECK(std::fabs(c - std::cos(x)) <= 2 * 0x1p-53);
  }
  // a dense scan across the 20π and 2^19 π boundaries
  for (double x = 60.0; x < 66.0; x += 1e-3) {
    double s = 0, c = 0;
    lane_sincos(x, s, c);
    REQUIRE(std::fabs(s - std::sin(x)) <= 2 * 0x1p-53);
  }
  for (double x = 1646000.0; x < 1648000.0; x += 0.37) {
    double s = 0, c = 0;
    lane_sincos(x, s, c);
    REQUIRE(std::fabs(c - std::cos(x)) <= 2 * 0x1p-53);
  }
}

TEST_CASE("exp, log and pow of a lane depend on its own argument and match libm", "[kernels][lane_math]") {
  const std::vector<double> args{1e-300, 1e-10, 0.5, 0.999, 1.0, 1.5, 2.0, 10.0, 700.0, 1e10, 1e300, 3.7};
  for_each_block(args, [](const simd_lane& x) {
    const simd_lane lg = lane_log(x), pw = lane_pow(x, -0.2);
    const simd_lane ex = lane_exp(lane_log(x) * simd_lane(0.5));
    for (std::size_t l = 0; l < W; ++l) {
      const double xl = lane_get(x, l);
      INFO("x = " << xl);
      CHECK(same_bits(lane_get(lg, l), lane_log(xl)));
      CHECK(same_bits(lane_get(pw, l), lane_pow(xl, -0.2)));
      CHECK(same_bits(lane_get(ex, l), lane_exp(lane_log(xl) * 0.5)));
      CHECK(std::fabs(lane_log(xl) - std::log(xl)) <= 2 * 0x1p-52 * std::max(1.0, std::fabs(std::log(xl))));
      // e^(p ln x) carries ln x's rounding times |p ln x|
      CHECK(std::fabs(lane_pow(xl, -0.2) / std::pow(xl, -0.2) - 1) <=
            (2 + 0.2 * std::fabs(std::log(xl))) * 0x1p-52);
    }
  });
  CHECK(lane_exp(-800.0) == 0.0);
  CHECK(std::isinf(lane_exp(800.0)));
}
