// Tests of the initial conditions and random streams (ensemble/rows/initial_conditions.hpp,
// model.md §2): structure of each kind, reproducibility per member, uniformity of draws.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "ensemble/rows/initial_conditions.hpp"
#include "kernels/lanes/counter_random.hpp"

using namespace rotorsweep::ensemble;
using rotorsweep::kernels::RandomStream;

TEST_CASE("FM and AFM angles lie within the noise of their pattern", "[ensemble][initial]") {
  const double pi = std::numbers::pi;
  const auto fm = initial_angles({InitialKind::fm, 0.01, 0.3, {}}, 20, 1, 5);
  const auto afm = initial_angles({InitialKind::afm, 0.01, 0.0, {}}, 20, 1, 5);
  for (std::size_t j = 0; j < 20; ++j) {
    CHECK(std::fabs(fm[j] - 0.3) <= 0.01);
    CHECK(std::fabs(afm[j] - pi * double(j % 2)) <= 0.01);
  }
  const auto quiet = initial_angles({InitialKind::fm, 0.0, 0.0, {}}, 6, 1, 5);
  for (double x : quiet) CHECK(x == 0.0);
}

TEST_CASE("random and exact kinds", "[ensemble][initial]") {
  const auto random = initial_angles({InitialKind::random, 0.0, 0.0, {}}, 64, 3, 0);
  for (double x : random) CHECK((x >= 0.0 && x < 2 * std::numbers::pi));
  const auto exact = initial_angles({InitialKind::exact, 0.0, 0.0, {0.5, 1.5}}, 5, 3, 0);
  CHECK(exact == std::vector<double>{0.5, 1.5, 0.5, 1.5, 0.5});
}

TEST_CASE("each member's draws depend only on (seed, member)", "[ensemble][random]") {
  const InitialCondition ic{InitialKind::afm, 0.01, 0.0, {}};
  CHECK(initial_angles(ic, 8, 42, 17) == initial_angles(ic, 8, 42, 17));
  CHECK(initial_angles(ic, 8, 42, 17) != initial_angles(ic, 8, 42, 18));
  CHECK(initial_angles(ic, 8, 42, 17) != initial_angles(ic, 8, 43, 17));
  // a longer array extends a shorter one: row j always takes draw j
  const auto short_rows = initial_angles(ic, 4, 42, 17), long_rows = initial_angles(ic, 8, 42, 17);
  for (std::size_t j = 0; j < 4; ++j) CHECK(short_rows[j] == long_rows[j]);
}

TEST_CASE("stream draws are uniform on the unit interval", "[ensemble][random]") {
  const RandomStream stream(9, 123);
  const int n = 200000;
  double mean = 0, second = 0;
  int bins[10] = {};
  for (int k = 0; k < n; ++k) {
    const double u = stream.draw(std::uint64_t(k));
    REQUIRE((u >= 0.0 && u < 1.0));
    mean += u / n;
    second += u * u / n;
    ++bins[int(u * 10)];
  }
  CHECK(mean == Approx(0.5).margin(0.005));
  CHECK(second - mean * mean == Approx(1.0 / 12).margin(0.002));
  double chi2 = 0;
  for (int b : bins) chi2 += (b - n / 10.0) * (b - n / 10.0) / (n / 10.0);
  CHECK(chi2 < 27.9);  // 99.9 % quantile of chi-squared with 9 degrees of freedom
}
