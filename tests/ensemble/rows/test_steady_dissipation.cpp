// The row problem's steady test (ensemble/rows/steady_dissipation.hpp, docs/scenes.md "Row scenes", key
// schedule.steady_tol):
// successive periods' dissipations agree to a relative tolerance, each against the period before.
#include <catch2/catch.hpp>

#include "ensemble/rows/steady_dissipation.hpp"

using namespace rotorsweep::ensemble;

TEST_CASE("successive periods agree to a relative tolerance", "[ensemble][steady]") {
  CHECK(dissipations_agree(1.0, 1.05, 0.1));
  CHECK_FALSE(dissipations_agree(1.0, 1.2, 0.1));
  CHECK(dissipations_agree(0.0, 0.0, 1e-9));
  CHECK(dissipations_agree(-1.0, -1.05, 0.1));
  CHECK_FALSE(dissipations_agree(1.0, -1.0, 0.5));
}

TEST_CASE("the steady test compares each period's D with the one before", "[ensemble][steady]") {
  SteadyDissipation test{0.01};
  CHECK(test.close(0.0));  // against the 0 before the first period (which MemberProgress never settles)
  CHECK_FALSE(test.close(1.0));
  CHECK_FALSE(test.close(2.0));
  CHECK_FALSE(test.close(1.5));
  CHECK(test.close(1.501));
  CHECK(test.last == 1.501);
}
