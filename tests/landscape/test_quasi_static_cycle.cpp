// The quasi-static cycle (landscape/quasi_static_cycle): the paper's recipe J(A) reproduced by following
// the minimum and the gradient flow, no friction outside the CP interval, and beyond nearest neighbours
// the recipe where it applies and positive drops where it does not.
#include <catch2/catch.hpp>
#include <cmath>

#include "landscape/bifurcation_curves.hpp"
#include "landscape/jump_friction.hpp"
#include "landscape/quasi_static_cycle.hpp"
#include "support/dipolar_range_4.hpp"

using namespace rotorsweep::landscape;
using rotorsweep::testing::dipolar_range_4;

namespace {

void check_drops(const QuasiStaticCycle& cycle) {
  CHECK(cycle.periodic);
  for (const auto& jump : cycle.jumps) CHECK(jump.energy_before > jump.energy_after);
}

}  // namespace

TEST_CASE("nearest neighbours: the cycle's friction is the recipe's J on [A_-, A_*] and 0 outside",
          "[landscape][cycle]") {
  for (int i = 1; i < 40; ++i) {
    const double A = A_minus() + (A_star() - A_minus()) * i / 40;
    INFO("A = " << A);
    const auto cycle = quasi_static_cycle(A);
    check_drops(cycle);
    CHECK(cycle.jumps.size() >= 4);  // two per half period
    CHECK(cycle.J == Approx(jump_friction(A)).margin(1e-7));
    CHECK(cycle.mean_rho > 0.5);
    CHECK(cycle.mean_rho < 1);
  }
  for (double A : {1.0, 3.0, 4.5, 9.0, 12.0}) {
    INFO("A = " << A);
    const auto cycle = quasi_static_cycle(A);
    check_drops(cycle);
    CHECK(cycle.J == 0);
    CHECK((A < A_minus() ? cycle.mean_rho < 0.2 : cycle.mean_rho > 0.98));
  }
}

TEST_CASE("dipolar coefficients: the recipe where its sequence occurs, slips of strict FM where not",
          "[landscape][cycle]") {
  int recipe = 0, fm_slips = 0;
  for (int i = 1; i < 30; ++i) {
    const double A = A_minus(dipolar_range_4) + (A_star(dipolar_range_4) - A_minus(dipolar_range_4)) * i / 30;
    INFO("A = " << A);
    const auto cycle = quasi_static_cycle(A, dipolar_range_4);
    check_drops(cycle);
    CHECK(cycle.J > 0);
    const double J = jump_friction(A, dipolar_range_4);
    if (std::isfinite(J)) {
      ++recipe;
      CHECK(cycle.J == Approx(J).margin(1e-6));
    } else {
      ++fm_slips;  // the strict-FM minimum ends in a fold and the flow lands on the next one
      for (const auto& jump : cycle.jumps) CHECK(jump.rho_after > 0.999);
    }
  }
  CHECK(recipe > 10);
  CHECK(fm_slips > 5);
  CHECK(quasi_static_cycle(A_star(dipolar_range_4) + 0.5, dipolar_range_4).J == 0);
  CHECK(quasi_static_cycle(A_minus(dipolar_range_4) - 0.5, dipolar_range_4).J == 0);
}
