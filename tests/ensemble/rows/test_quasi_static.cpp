// The quasi-static limit g → 0 (stiffness up to 1e7): steps per period stay bounded, and the
// CP regime keeps its slips: implicit stages must not turn the strict-FM saddle into a false
// attractor (steps are rejected until they resolve every unstable direction); in CP, D/N falls
// towards the landscape's quasi-static friction J(A) from above as g → 0, also with dipolar rows
// (range 4), where J_M is the friction of the two-angle reduction's quasi-static cycle.
#include <catch2/catch.hpp>
#include <map>

#include "ensemble/rows/coupling_table.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "landscape/jump_friction.hpp"
#include "landscape/quasi_static_cycle.hpp"
#include "test_paths.hpp"

using namespace rotorsweep::ensemble;

TEST_CASE("small g: bounded steps and CP kept", "[ensemble][quasi-static]") {
  const Scene scene =
      rotorsweep::io::parse_scene_file(ROTORSWEEP_SOURCE_DIR "/scripts/stress/g_to_zero.toml");
  Scene single = scene;
  single.rtol_values = {1e-6};
  single.atol_values = {1e-9};
  const auto members = plan_members(single);
  const auto outcome = run_sweep(single, members, {.threads = 2});
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

TEST_CASE("dipolar rows: D/N falls towards the quasi-static cycle's J_M from above",
          "[ensemble][quasi-static]") {
  const Scene scene = rotorsweep::io::parse_scene_text(
      "[model]\nrows = 20\ncouplings = \"dipolar\"\nrange = 4\n[drive]\ng = [1e-5, 1e-4, 1e-3]\n[sweep]\n"
      "A = [6.0, 10.0]\n[initial]\nkinds = [\"AFM\"]\n[numerics]\nrtol = 1e-6\natol = 1e-9\n",
      "test.toml");
  const auto k = two_angle_coefficients(scene.couplings.for_rows(20));
  const auto members = plan_members(scene);
  const auto outcome = run_sweep(scene, members, {.threads = 2});
  std::map<double, std::map<double, double>> friction;  // A → g → D/N
  for (std::size_t i = 0; i < members.size(); ++i) {
    REQUIRE(outcome.results[i].status == rotorsweep::kernels::LaneStatus::ok);
    friction[members[i].A][members[i].g] = outcome.results[i].dissipation() / 20;
  }
  for (double A : {6.0, 10.0}) {
    const double J = rotorsweep::landscape::quasi_static_cycle(A, k).J;
    INFO("A = " << A << ", J_M = " << J);
    REQUIRE(J > 1);
    double previous = 0;
    for (const auto& [g, d] : friction.at(A)) {  // g ascending: D/N rises from J_M upwards
      INFO("g = " << g << ": D/N = " << d);
      CHECK(d > J);
      CHECK(d > previous);
      previous = d;
    }
    CHECK(friction.at(A).begin()->second < 1.15 * J);  // measured 1.09 (A = 6) and 1.07 (A = 10) at g = 1e-5
  }
}
