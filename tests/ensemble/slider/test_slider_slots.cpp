// The slider through slots on teams (ensemble/slider/slider_slots.cpp, slider_slot_sweep.cpp,
// slider_team_member.hpp): on host teams it follows the CPU's lanes, sample by sample and period by
// period, in both dynamics and over speeds, dampings, separations and replicas; chunks do not change a
// member's bits; every optional series follows the lanes; a member that fails is flagged as on the
// CPU; the GPU's scenes are checked.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "ensemble/slider/slider_sweep.hpp"
#include "io/slider_scene_parser.hpp"
#include "support/slider_slot_runs.hpp"
#include "test_paths.hpp"

using namespace rotorsweep;
using ensemble::SliderMember;

namespace {

/// A 3 × 2 slider over 11 × 11 at two speeds and two dampings, two separations × two replicas, rodas5p;
/// `extra` adds keys to [slider], `numerics` replaces the tolerances.
std::string scene_text(const std::string& extra,
                       const std::string& numerics = "rtol = 1e-10\natol = 1e-10\n") {
  return "[slider]\ncolumns = 3\nrows = 2\ndamping = [2.5e-6, 1e-5]\n" + extra +
         "[substrate]\ncolumns = 11\nrows = 11\n[drive]\nrest = 0.5\nperiods = 2\nspeed = [8e-3, 16e-3]\n"
         "[sweep]\nseparation = [7e-3, 9e-3]\n[initial]\nreplicas = 2\n[observables]\nsamples_per_period = "
         "20\n[numerics]\n" +
         numerics;
}

ensemble::SliderScene parse(const std::string& text) {
  return io::parse_slider_scene_text(text, "slots-test");
}

std::vector<SliderMember> on_lanes(const ensemble::SliderScene& scene) {
  return ensemble::run_slider_scan(scene, {.threads = 1}).members;
}

double largest(const std::vector<SliderMember>& members, double SliderMember::*value) {
  double m = 0.0;
  for (const auto& member : members) m = std::max(m, std::fabs(member.*value));
  return m;
}

/// Whether two series agree within `tolerance` · scale, with NaN in the same columns.
bool series_close(const std::vector<double>& a, const std::vector<double>& b, double tolerance) {
  if (a.size() != b.size()) return false;
  double scale = 0.0;
  for (const double v : b)
    if (!std::isnan(v)) scale = std::max(scale, std::fabs(v));
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (std::isnan(a[k]) != std::isnan(b[k])) return false;
    if (!std::isnan(b[k]) && std::fabs(a[k] - b[k]) > tolerance * std::max(scale, 1e-300)) return false;
  }
  return true;
}

/// Each member on teams against the lanes: at rtol 1e-10 the two integrations differ by rounding
/// (the team's sums), so friction, work, series and order parameters agree far below the tolerance's
/// own error (measured: friction within 5e-13 of the scan's largest, series within 1.1e-11, the same
/// steps) and the step counts nearly match.
void check_follows_lanes(const std::vector<SliderMember>& teams, const std::vector<SliderMember>& lanes) {
  REQUIRE(teams.size() == lanes.size());
  const double friction_scale = largest(lanes, &SliderMember::friction);
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    const SliderMember &t = teams[k], &l = lanes[k];
    INFO("member " << k << ": speed " << l.speed << ", damping " << l.damping << ", separation "
                   << l.separation << ", replica " << l.index.replica);
    REQUIRE(l.status == "ok");
    CHECK(t.status == l.status);
    CHECK(t.plan_index == l.plan_index);
    CHECK(std::fabs(t.friction - l.friction) < 1e-10 * friction_scale);
    if (std::isnan(l.friction_error))  // no shadow runs
      CHECK(std::isnan(t.friction_error));
    else
      CHECK(std::fabs(t.friction_error - l.friction_error) < 1e-10 * friction_scale);  // the shadows' too
    REQUIRE(t.period_work.size() == l.period_work.size());
    for (std::size_t p = 0; p < l.period_work.size(); ++p) {
      CHECK(std::fabs(t.period_work[p] - l.period_work[p]) < 1e-10 * friction_scale * 16e-3);
      CHECK(t.period_dissipation[p] == Approx(l.period_dissipation[p]).epsilon(1e-9));
      CHECK(std::fabs(t.period_balance[p]) < 1e-6);
    }
    CHECK(series_close(t.friction_series, l.friction_series, 1e-9));
    CHECK(series_close(t.energy_series, l.energy_series, 1e-9));
    CHECK(series_close(t.order_x_series, l.order_x_series, 1e-9));
    CHECK(series_close(t.order_y_series, l.order_y_series, 1e-9));
    CHECK(t.order_x == Approx(l.order_x).margin(1e-9));
    CHECK(t.steps_accepted == Approx(l.steps_accepted).epsilon(0.02));
  }
}

}  // namespace

TEST_CASE("slider slots: members on host teams follow the CPU's lanes, inertial and overdamped",
          "[ensemble][slider][team]") {
  for (const std::string dynamics : {"", "dynamics = \"overdamped\"\n"}) {
    const auto scene = parse(scene_text(dynamics));
    REQUIRE(scene.member_count() == 16);
    const auto lanes = on_lanes(scene);
    for (const std::size_t ranks : {1, 4}) {
      INFO((dynamics.empty() ? "inertial" : "overdamped") << " on a team of " << ranks);
      check_follows_lanes(testing::slider_on_host_teams(scene, ranks, 5), lanes);
    }
  }
}

TEST_CASE("slider slots: a member's bits do not depend on its chunk", "[ensemble][slider][team]") {
  const auto scene = parse(scene_text("", "rtol = 1e-7\natol = 1e-7\n"));
  const auto whole = testing::slider_on_host_teams(scene, 2, 64);
  const auto chunked = testing::slider_on_host_teams(scene, 2, 3);
  for (std::size_t k = 0; k < whole.size(); ++k) {
    CHECK(chunked[k].friction == whole[k].friction);
    CHECK(series_close(chunked[k].friction_series, whole[k].friction_series, 0.0));
    CHECK(chunked[k].period_balance == whole[k].period_balance);
    CHECK(chunked[k].steps_accepted == whole[k].steps_accepted);
  }
}

TEST_CASE("slider slots: a member that runs out of steps is flagged with NaN summaries and a frozen state",
          "[ensemble][slider][team]") {
  const auto scene = parse(scene_text("", "rtol = 1e-7\natol = 1e-7\nmax_steps = 50\n"));
  const auto lanes = on_lanes(scene);
  const auto teams = testing::slider_on_host_teams(scene, 4, 16);
  for (std::size_t k = 0; k < teams.size(); ++k) {
    const SliderMember& m = teams[k];
    CHECK(m.status == "step_budget");
    CHECK(lanes[k].status == "step_budget");
    CHECK(std::isnan(m.friction));
    CHECK(std::isnan(m.order_x));
    CHECK(std::isnan(m.period_balance.front()));
    CHECK(m.energy_series.back() == m.energy_series[m.energy_series.size() - 2]);
    CHECK(m.steps_accepted + m.steps_rejected == 50);
  }
}

TEST_CASE("slider slots: every optional series on host teams follows the lanes", "[ensemble][slider][team]") {
  std::string text = scene_text("", "rtol = 1e-10\natol = 1e-10\nglobal_error = \"local\"\n");
  text.insert(
      text.find("samples_per_period"),
      "angles = true\nenergies = true\nfield = true\nsublattices = true\ntorques = true\nforces = true\n");
  const auto scene = parse(text);
  const auto lanes = on_lanes(scene);
  const auto teams = testing::slider_on_host_teams(scene, 4, 5);
  check_follows_lanes(teams, lanes);
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    const SliderMember &t = teams[k], &l = lanes[k];
    INFO("member " << k);
    for (const auto series :
         {&SliderMember::angles, &SliderMember::torques, &SliderMember::substrate_energy_series,
          &SliderMember::pair_energy_series, &SliderMember::field_axis_series, &SliderMember::field_z_series,
          &SliderMember::moment_axis_even_series, &SliderMember::moment_z_even_series,
          &SliderMember::torque_even_series, &SliderMember::moment_axis_odd_series,
          &SliderMember::moment_z_odd_series, &SliderMember::torque_odd_series, &SliderMember::force_x_series,
          &SliderMember::force_y_series, &SliderMember::force_z_series}) {
      REQUIRE(!(l.*series).empty());
      CHECK(series_close(t.*series, l.*series, 1e-9));
    }
    // the period means of F_y vanish by symmetry up to rounding: against the series' scale
    for (const auto& [means, series] :
         {std::pair{&SliderMember::period_force_y, &SliderMember::force_y_series},
          std::pair{&SliderMember::period_force_z, &SliderMember::force_z_series}}) {
      double scale = 0.0;
      for (const double v : l.*series)
        if (!std::isnan(v)) scale = std::max(scale, std::fabs(v));
      REQUIRE((t.*means).size() == (l.*means).size());
      for (std::size_t p = 0; p < (l.*means).size(); ++p)
        CHECK(std::fabs((t.*means)[p] - (l.*means)[p]) <= 1e-9 * scale);
    }
  }
}

TEST_CASE("slider scenes on the GPU: every linearly implicit stepper runs, an explicit one is named",
          "[ensemble][slider][scene]") {
  const auto error_of = [](const std::string& text) {
    try {
      parse(text);
    } catch (const io::SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK(parse(scene_text("", "device = \"gpu\"\n")).device == ensemble::Device::gpu);
  CHECK(parse(scene_text("")).device == ensemble::Device::cpu);
  CHECK(error_of(scene_text("", "device = \"gpu\"\nstepper = \"rodas4p2\"\n")).empty());
  CHECK_THAT(error_of(scene_text("", "device = \"gpu\"\nstepper = \"dopri5\"\n")),
             Catch::Contains("numerics.stepper") && Catch::Contains("rodas5p") && Catch::Contains("dopri5"));
  std::string forces = scene_text("", "device = \"gpu\"\n");
  forces.insert(forces.find("samples_per_period"), "forces = true\nangles = true\n");
  CHECK(error_of(forces).empty());
  CHECK_THAT(error_of(scene_text("", "device = \"tpu\"\n")), Catch::Contains("numerics.device"));
}

TEST_CASE("slider slots: the GPU's example scan is the experiment's, and its 7 x 7 members follow the lanes",
          "[ensemble][slider][team]") {
  const auto gpu = io::parse_slider_scene_file(ROTORSWEEP_SOURCE_DIR "/examples/experiment_7x7_gpu.toml");
  const auto cpu = io::parse_slider_scene_file(ROTORSWEEP_SOURCE_DIR "/examples/experiment_7x7.toml");
  CHECK(gpu.device == ensemble::Device::gpu);
  CHECK(gpu.member_count() == 8100);
  CHECK(gpu.separations == cpu.separations);
  CHECK(gpu.sizes == cpu.sizes);
  // two of its separations, one period of sliding, at the scene's tolerance, on a warp's 32 ranks
  ensemble::SliderScene scene = cpu;
  scene.separations = {7e-3, 11e-3};
  scene.replicas = 2;
  scene.end = 2.5;
  const auto lanes = on_lanes(scene);
  const auto teams = testing::slider_on_host_teams(scene, 32, 4);
  const double scale = largest(lanes, &SliderMember::friction);
  for (std::size_t k = 0; k < lanes.size(); ++k) {
    INFO("member " << k);
    REQUIRE(lanes[k].status == "ok");
    CHECK(teams[k].status == "ok");
    CHECK(std::fabs(teams[k].friction - lanes[k].friction) < 1e-10 * scale);  // measured: 2.5e-14
    CHECK(series_close(teams[k].energy_series, lanes[k].energy_series, 1e-8));
    CHECK(teams[k].steps_accepted == Approx(lanes[k].steps_accepted).epsilon(0.02));
  }
}
