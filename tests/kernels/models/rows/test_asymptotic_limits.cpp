// The small-A (AFM) and large-A (FM) dissipation laws of docs/model.md §4: the ratio numeric /
// analytic approaches 1 monotonically as A → 0 (resp. A → ∞) over a few decades.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "landscape/dissipation_laws.hpp"
#include "support/member_run.hpp"

using rotorsweep::testing::run_member;
using rotorsweep::testing::Start;

namespace {

constexpr std::size_t rows = 20;
constexpr double g = 0.0011;

double numeric(double A, Start start) {
  return run_member(rows, A, g, start, 2, 1, 1e-10, 1e-16).dissipation();
}

void check_monotone_approach(const std::vector<double>& deviations) {
  for (std::size_t i = 1; i < deviations.size(); ++i) {
    INFO("step " << i << ": |ratio - 1| " << deviations[i - 1] << " -> " << deviations[i]);
    CHECK(deviations[i] < deviations[i - 1]);
  }
}

}  // namespace

TEST_CASE("small-A AFM law D = N pi A^2 g / (100 + g^2)", "[kernels][limits]") {
  std::vector<double> deviations;
  for (double A : {1.0, 0.3, 0.1, 0.03, 0.01}) {
    const double analytic = rotorsweep::landscape::small_A_dissipation(A, g, rows);
    deviations.push_back(std::fabs(numeric(A, Start::afm) / analytic - 1));
  }
  check_monotone_approach(deviations);
  CHECK(deviations.back() < 1e-3);
}

TEST_CASE("large-A FM law D = 2 pi N g + 36 pi N g / A^2", "[kernels][limits]") {
  std::vector<double> deviations;
  for (double A : {15.0, 30.0, 60.0, 120.0, 240.0}) {
    const double analytic = rotorsweep::landscape::large_A_dissipation(A, g, rows);
    deviations.push_back(std::fabs(numeric(A, Start::fm) / analytic - 1));
  }
  check_monotone_approach(deviations);
  CHECK(deviations.back() < 1e-4);
}
