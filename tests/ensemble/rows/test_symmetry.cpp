// Symmetry protection (paper appendix on strict-FM states): an exactly strict-FM start stays
// strict FM in every stepper, with slips only where the single-rotor landscape has jumps
// (3 ≤ A ≤ 6); with noise the CP regime leaves the strict-FM set.
#include <catch2/catch.hpp>
#include <cmath>

#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "kernels/steppers/stepper_list.hpp"

using namespace rotorsweep::ensemble;

namespace {

SweepOutcome strict_fm_sweep(const std::string& stepper, double noise) {
  const Scene scene = rotorsweep::io::parse_scene_text(
      "[model]\nrows = 4\n[drive]\ng = [0.001]\n[sweep]\nA = { from = 0.25, to = 10, count = 40 }\n"
      "[initial]\nkinds = [\"FM\"]\nnoise = " +
          std::to_string(noise) + "\n[numerics]\nstepper = \"" + stepper + "\"\n",
      "symmetry.toml");
  return run_sweep(scene, plan_members(scene), {.threads = 2});
}

}  // namespace

TEST_CASE("an exact strict-FM start stays strict FM in every stepper", "[ensemble][symmetry]") {
  for (const std::string_view stepper : rotorsweep::kernels::stepper_names) {
    const auto outcome = strict_fm_sweep(std::string(stepper), 0.0);
    for (const auto& r : outcome.results) {
      const double A = 0.25 * double(r.index + 1);
      INFO(stepper << " A = " << A);
      REQUIRE(r.status == rotorsweep::kernels::LaneStatus::ok);
      for (double theta : r.theta_final) CHECK(theta == r.theta_final[0]);
      CHECK(r.alignment_min() == Approx(1.0).margin(1e-14));  // cos²+sin² to rounding
      // Jumps of the single-rotor landscape exist for 3 <= A <= 6. Above 6 the state turns
      // smoothly, at most A/(A - 6) times the drive's rate, which the slip threshold of 10
      // counts as a slip only up to A = 6⅔.
      if (A < 3 || A > 6.0 + 6.0 / 9.0) CHECK(r.slips_per_period() == 0);
      if (A > 3 && A <= 6) CHECK(r.slips_per_period() > 0);
    }
  }
}

TEST_CASE("with noise the CP regime leaves the strict-FM set", "[ensemble][symmetry]") {
  const auto outcome = strict_fm_sweep("rodas4", 0.01);
  int cp = 0;
  for (const auto& r : outcome.results) {
    INFO("A = " << 0.25 * double(r.index + 1));
    if (r.regime != Regime::cp) continue;
    ++cp;
    CHECK(r.alignment_min() < 0.99);
  }
  CHECK(cp >= 10);
}
