// Long runs: with numerics.wrap_angles, D per period of a FM member stays the same to 1e-9
// over 10⁴ drive periods although the rows turn 10⁴ times (no precision loss in sincos).
#include <catch2/catch.hpp>
#include <cmath>

#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"

using namespace rotorsweep::ensemble;

TEST_CASE("D per period is unchanged over 10^4 periods with wrapped angles", "[ensemble][long]") {
  const Scene scene = rotorsweep::io::parse_scene_text(
      "[model]\nrows = 4\n[drive]\ng = [0.0011]\n[sweep]\nA = [11]\n[initial]\nkinds = [\"FM\"]\n"
      "[schedule]\nrelax_periods = 0\naverage_periods = 10000\n[observables]\nperiod_series = true\n"
      "alignment = false\nslips = false\n[numerics]\nlanes = \"scalar\"\nwrap_angles = true\n",
      "long.toml");
  const auto outcome = run_sweep(scene, plan_members(scene), {.threads = 1});
  const auto& periods = outcome.results[0].periods;
  REQUIRE(periods.size() == 10000);
  const double reference = periods[10].dissipation();
  double worst = 0;
  for (std::size_t k = 10; k < periods.size(); ++k)
    worst = std::max(worst, std::fabs(periods[k].dissipation() / reference - 1));
  CHECK(worst < 1e-9);
}
