// The quasi-static limit g → 0 (stiffness up to 1e7): steps per period stay bounded, and the
// CP regime keeps its slips: implicit stages must not turn the strict-FM saddle into a false
// attractor (steps are rejected until they resolve every unstable direction); in CP, D/N falls
// towards the landscape's quasi-static friction J(A) from above as g → 0.
#include <catch2/catch.hpp>
#include <map>

#include "ensemble/sweep.hpp"
#include "io/scene_parser.hpp"
#include "landscape/jump_friction.hpp"

using namespace rotorsweep::ensemble;

TEST_CASE("small g: bounded steps and CP kept", "[ensemble][quasi-static]") {
  const Scene scene =
      rotorsweep::io::parse_scene_file(ROTORSWEEP_SOURCE_DIR "/scripts/stress/g_to_zero.toml");
  Scene single = scene;
  single.rtol_values = {1e-6};
  single.atol_values = {1e-9};
  const auto members = plan_members(single);
  const auto outcome = run_sweep(single, members, 2, nullptr);
  std::map<std::pair<double, double>, double> steps_per_period;  // (A, g) → attempts per period
  std::map<double, std::map<double, double>> friction;           // A → g → D/N
  for (std::size_t i = 0; i < members.size(); ++i) {
    const auto& r = outcome.results[i];
    REQUIRE(r.status == rotorsweep::kernels::LaneStatus::ok);
    steps_per_period[{members[i].A, members[i].g}] = (r.steps_accepted + r.steps_rejected) / r.periods_run;
    friction[members[i].A][members[i].g] = r.dissipation() / 20;
    if (members[i].A == 8.0 && members[i].g <= 1e-5) {
      INFO("A = 8, g = " << members[i].g);
      CHECK(r.regime == Regime::cp);
      CHECK(r.dissipation() / 20 > 0.01);
    }
  }
  for (double A : scene.A_values) {
    INFO("A = " << A);
    const double at_1e5 = steps_per_period.at({A, scene.g_values[1]});
    const double at_1e3 = steps_per_period.at({A, scene.g_values[3]});
    CHECK(at_1e5 < 2 * at_1e3);
    CHECK(at_1e5 < 2000);
  }

  for (double A : {6.0, 8.0}) {
    const double J = rotorsweep::landscape::jump_friction(A);
    double previous = 1e300;
    for (const auto& [g, d] : friction.at(A)) {  // g ascending: D/N rises from J upwards
      INFO("A = " << A << ", g = " << g << ": D/N = " << d << ", J = " << J);
      if (g > 1e-3) continue;
      CHECK(d > J);
      if (previous < 1e300) CHECK(d > previous);
      previous = d;
    }
    INFO("A = " << A);
    CHECK(friction.at(A).begin()->second < (A == 6.0 ? 1.05 : 2.0) * J);
  }
}
