// A reduced copy of examples/stress.toml (N = 2 and 64, the extreme A and g): every member
// ends ok or with a documented failure, NaN appears only where the status says so, and
// members that fail leave all others bit-identical to a run without them.
#include <catch2/catch.hpp>
#include <cmath>

#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "support/same_results.hpp"
#include "test_paths.hpp"

using namespace rotorsweep::ensemble;
using rotorsweep::kernels::LaneStatus;
using rotorsweep::testing::same_bits;

namespace {

Scene reduced_stress_scene() {
  Scene scene = rotorsweep::io::parse_scene_file(ROTORSWEEP_SOURCE_DIR "/examples/stress.toml");
  scene.row_counts = {2, 64};
  scene.A_values = {0.0, 0.01, 1.0, 10.0, 1000.0};
  scene.g_values = {scene.g_values.front(), scene.g_values[2], scene.g_values.back()};
  return scene;
}

}  // namespace

TEST_CASE("the reduced stress scene ends ok or flagged, never with a silent NaN", "[ensemble][stress]") {
  const Scene scene = reduced_stress_scene();
  const auto members = plan_members(scene);
  REQUIRE(members.size() == 2 * 2 * 5 * 3 * 2);
  const auto outcome = run_sweep(scene, members, {.threads = 2});
  for (const auto& r : outcome.results) {
    const auto& m = members[r.index];
    INFO("N " << m.rows << " rtol " << m.rtol << " A " << m.A << " g " << m.g);
    CHECK(r.status == LaneStatus::ok);
    CHECK(std::isfinite(r.dissipation()));
    CHECK(std::isfinite(r.alignment_mean()));
    for (double theta : r.theta_final) CHECK(std::isfinite(theta));
  }
}

TEST_CASE("failing stress members leave the others bit-identical", "[ensemble][stress]") {
  Scene scene = reduced_stress_scene();
  scene.max_steps = 20000;  // the tight-tolerance CP members need more
  const auto members = plan_members(scene);
  const auto outcome = run_sweep(scene, members, {.threads = 2});
  std::vector<Member> survivors;
  std::vector<MemberResult> expected;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const auto& r = outcome.results[i];
    if (r.status == LaneStatus::ok) {
      survivors.push_back(members[i]);
      expected.push_back(r);
      continue;
    }
    INFO("member " << i);
    CHECK(r.status == LaneStatus::step_budget);
    CHECK(std::isnan(r.dissipation()));
    CHECK(r.regime == Regime::unsettled);
  }
  REQUIRE(survivors.size() < members.size());
  const auto alone = run_sweep(scene, survivors, {.threads = 1});
  for (std::size_t i = 0; i < survivors.size(); ++i) {
    INFO("member " << survivors[i].index);
    CHECK(same_bits(alone.results[i].dissipation(), expected[i].dissipation()));
    CHECK(alone.results[i].steps_accepted == expected[i].steps_accepted);
    CHECK(alone.results[i].theta_final == expected[i].theta_final);
  }
}
