// One member per team (ensemble/rows/team_member.hpp) on host teams of 1, 3 and 8 ranks against the
// one-thread driver DeviceMember on the same slots: the same periods, slips, regimes and attractors, D
// and ρ̄ within the integration error (AFM, CP, FM; nearest neighbours and coupling tables; at T > 0
// the same path), and the examples' labels.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "ensemble/gpu/device_drivers.hpp"
#include "ensemble/rows/device_member.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/sweep.hpp"
#include "ensemble/rows/team_member.hpp"
#include "io/scene_parser.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/leimkuhler_matthews.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "kernels/steppers/team_leimkuhler_matthews.hpp"
#include "kernels/steppers/team_rosenbrock.hpp"
#include "support/member_follows.hpp"
#include "support/slot_runs.hpp"
#include "test_paths.hpp"

using namespace rotorsweep;
using Catch::Detail::Approx;
using Model = kernels::NearestNeighbourRows<double>;
using Coupled = kernels::CoupledRows<double>;

namespace {

/// The scene's Rosenbrock stepper on Rows, on one lane and on a host team.
template <class Rows>
using Lanes = kernels::AdaptiveIntegrator<Rows, kernels::RosenbrockStepper<Rows>>;
template <class Rows>
using TeamLanes =
    kernels::TeamIntegrator<kernels::HostTeam, kernels::TeamRosenbrock<kernels::HostTeam, Rows>>;

/// A team's members against one thread's: the same labels, D and the other means within 1e-8 (1e-10
/// outside CP). Where rounding decides CP (`cp_rounding`: uniform rows, whose symmetry only rounding
/// breaks at each slip), CP members keep their labels and D within 1 %: a team, whose sums differ from
/// the lanes' only in order, moves D by up to 0.5 % there (docs/numerics.md "The stage solve on a team").
template <class Rows = Model>
void check_teams_follow(const std::string& text, bool cp_rounding = false) {
  const auto scene = io::parse_scene_text(text, "team-member");
  const auto thread = testing::on_one_thread<Rows, Lanes<Rows>>(scene);
  for (std::size_t ranks : {1u, 3u, 8u}) {
    const auto team = testing::on_host_team<Lanes<Rows>, TeamLanes<Rows>>(scene, ranks);
    for (std::size_t k = 0; k < thread.size(); ++k) {
      const auto &a = thread[k], &b = team[k];
      INFO("ranks " << ranks << ", member " << k << ": D " << a.dissipation() << ", "
                    << a.final_state.attractor);
      if (cp_rounding && a.regime == ensemble::Regime::cp) {
        REQUIRE(b.status == a.status);
        CHECK(b.periods_run == a.periods_run);
        CHECK(b.regime == a.regime);
        CHECK(b.final_state.attractor == a.final_state.attractor);
        CHECK(b.dissipation() == Approx(a.dissipation()).epsilon(0.01));
        continue;
      }
      testing::check_member_follows(a, b, 1e-10);
      REQUIRE(b.row_dissipation.size() == a.row_dissipation.size());
      REQUIRE(b.link_alignment.size() == a.link_alignment.size());
      for (std::size_t j = 0; j < a.row_dissipation.size(); ++j) {
        INFO("row " << j);
        CHECK(b.row_dissipation[j] == Approx(a.row_dissipation[j]).epsilon(1e-8).margin(1e-12));
      }
      for (std::size_t j = 0; j < a.link_alignment.size(); ++j) {
        INFO("link " << j);
        CHECK(b.link_alignment[j] == Approx(a.link_alignment[j]).epsilon(1e-9));
      }
    }
  }
}

/// 20 rows from one noisy AFM start at each A (its regime: AFM, CP or FM), at the tight tolerance
/// the team's agreement is stated for.
const std::string rows_20 =
    "[model]\nrows = 20\n[drive]\ng = 0.0011\n[initial]\nkinds = [\"AFM\"]\nnoise = 0.01\nreplicas = 1\n"
    "[schedule]\nrelax_periods = 2\naverage_periods = 2\n[numerics]\nrtol = 1e-10\natol = 1e-13\n";

/// The coupling tables' rows, whose stage solve is dense: 12 as above over 1 + 1 periods (their members keep
/// the regimes of 20 over 2 + 2 and slip as often), so that a rank of a team of 8 holds one or two rows and
/// a pair of range 4 reaches across up to four ranks.
const std::string coupled_rows =
    "[model]\nrows = 12\n[drive]\ng = 0.0011\n[initial]\nkinds = [\"AFM\"]\nnoise = 0.01\nreplicas = 1\n"
    "[schedule]\nrelax_periods = 1\naverage_periods = 1\n[numerics]\nrtol = 1e-10\natol = 1e-13\n";

/// The rows of the thermal paths: 20 as above, but at g = 0.05, where the Langevin stepper's steps (no
/// longer than g/(2κ), docs/scenes.md thermal.step_fraction) number some 4000 a period rather than
/// 180 000 at g = 0.0011; the path's bits are the same question at any g. At T = 1e-3 the CP member at A = 6
/// slips (5 to 19 times a period) above the noise's threshold, which at T = 0.05 no slip reaches.
const std::string thermal_rows =
    "[model]\nrows = 20\n[drive]\ng = 0.05\n[initial]\nkinds = [\"AFM\"]\nnoise = 0.01\nreplicas = 2\n"
    "[schedule]\nrelax_periods = 2\naverage_periods = 2\n";

template <class Rows>
void check_thermal_path(const std::string& text) {
  using Langevin = kernels::LeimkuhlerMatthews<Rows>;
  const auto scene = io::parse_scene_text(text, "team-thermal");
  REQUIRE(scene.thermal.on());
  const auto thread = testing::on_one_thread<Rows, Langevin>(scene);
  // members that slip, so that the slips compared below are the noise's and the path's
  CHECK(std::any_of(thread.begin(), thread.end(), [](const auto& r) { return r.slips_per_period() > 0; }));
  for (std::size_t ranks : {1u, 3u, 8u}) {
    const auto team =
        testing::on_host_team<Langevin, kernels::TeamLeimkuhlerMatthews<kernels::HostTeam, Rows>>(scene,
                                                                                                  ranks);
    for (std::size_t k = 0; k < thread.size(); ++k) {
      const auto &a = thread[k], &b = team[k];
      INFO("ranks " << ranks << ", member " << k << ": D " << a.dissipation());
      REQUIRE(b.status == a.status);
      CHECK(b.periods_run == a.periods_run);
      CHECK(b.steps_accepted == a.steps_accepted);
      CHECK(b.theta_final == a.theta_final);  // the path's bits: only the quadratures are summed otherwise
      CHECK(b.row_dissipation == a.row_dissipation);  // and the row profiles, per row, with them
      CHECK(b.link_alignment == a.link_alignment);
      CHECK_FALSE(a.row_dissipation.empty());
      CHECK(b.slips_per_period() == a.slips_per_period());
      CHECK(b.regime == a.regime);
      CHECK(b.dissipation() == Approx(a.dissipation()).epsilon(1e-12).margin(1e-14));
      CHECK(b.alignment_mean() == Approx(a.alignment_mean()).epsilon(1e-12));
      for (const auto channel :
           {ensemble::Channel::work, ensemble::Channel::stokes, ensemble::Channel::energy_mean}) {
        INFO("channel " << std::size_t(channel));
        CHECK(b.mean(channel) == Approx(a.mean(channel)).epsilon(1e-12).margin(1e-14));
      }
    }
  }
}

}  // namespace

TEST_CASE("a team runs a disordered member as one thread does: AFM, CP and FM", "[team][device_member]") {
  check_teams_follow(rows_20 + "[sweep]\nA = [1.0, 6.0, 12.0]\n[disorder]\nA = 1e-6\n");
}

TEST_CASE("a team runs uniform rows as one thread does, the period wrapped", "[team][device_member]") {
  check_teams_follow(rows_20 + "wrap_angles = true\n[sweep]\nA = [1.0, 12.0]\n");
}

TEST_CASE("a team carries every quadrature and the row profiles as one thread does: W, S, H, the moments",
          "[team][device_member]") {
  check_teams_follow(rows_20 +
                     "[sweep]\nA = [1.0, 6.0, 12.0]\n[disorder]\nA = 1e-6\n[observables]\nestimators = true\n"
                     "energy = true\nmoments = true\nrow_profiles = true\n");
}

TEST_CASE(
    "a team runs a coupling table as one thread does: dipolar rows, periodic and open (disordered), every "
    "quadrature",
    "[team][device_member]") {
  const std::string observables =
      "[observables]\nestimators = true\nenergy = true\nmoments = true\nrow_profiles = true\n";
  const std::string dipolar = coupled_rows + "[sweep]\nA = [1.0, 6.0, 12.0]\n" + observables;
  check_teams_follow<Coupled>("[model]\ncouplings = \"dipolar\"\nrange = 4\n" + dipolar.substr(8), true);
  check_teams_follow<Coupled>(
      "[model]\nboundary = \"open\"\n" + dipolar.substr(8) + "[disorder]\nA = 1e-3\nanisotropy = 1e-3\n", true);
}

TEST_CASE("a team of eight gives the CPU lanes' labels on the examples but where rounding decides them",
          "[team][device_member]") {
  // the examples with fewer replicas and every `stride`-th A of their range (its ends kept), 125 members
  // (every A of basins.toml, every start kind and noise of robustness.toml): a host team takes some 50 to
  // 100 ms a member; every member but the symmetry-limited ones keeps its labels
  const struct {
    const char* path;
    int replicas;
    std::size_t stride;
  } examples[] = {{ROTORSWEEP_SOURCE_DIR "/examples/friction_curve.toml", 1, 10},
                  {ROTORSWEEP_SOURCE_DIR "/examples/basins.toml", 1, 1},
                  {ROTORSWEEP_SOURCE_DIR "/examples/robustness.toml", 1, 14},
                  {ROTORSWEEP_SOURCE_DIR "/examples/experiment_rows.toml", 1, 10}};
  for (const auto& [path, replicas, stride] : examples) {
    INFO(path);
    auto scene = io::parse_scene_file(path);
    scene.replicas = replicas;
    std::vector<double> A;
    for (std::size_t i = 0; i < scene.A_values.size(); i += stride) A.push_back(scene.A_values[i]);
    if (A.back() != scene.A_values.back()) A.push_back(scene.A_values.back());
    scene.A_values = A;
    const auto lanes = ensemble::run_sweep(scene, ensemble::plan_members(scene), {.threads = 2}).results;
    const auto team = testing::on_host_team(scene, 8);
    REQUIRE(team.size() == lanes.size());
    for (std::size_t k = 0; k < lanes.size(); ++k) {
      INFO("member " << k << ": " << lanes[k].final_state.attractor);
      if (lanes[k].symmetry_limited) continue;
      CHECK(team[k].regime == lanes[k].regime);
      CHECK(team[k].final_state.attractor == lanes[k].final_state.attractor);
    }
  }
}

TEST_CASE("at T > 0 a team steps a member along the lanes' path: the same noise, angles and slips",
          "[team][device_member]") {
  const std::string thermal =
      "[sweep]\nA = [1.0, 6.0]\n[thermal]\ntemperature = 1e-3\nsteps_per_period = 200\nseed = 3\n"
      "[observables]\nenergy = true\nrow_profiles = true\n";
  SECTION("disordered nearest neighbours") {
    check_thermal_path<Model>(thermal_rows + "[disorder]\nA = 1e-3\n" + thermal);
  }
  SECTION("a coupling table") {
    check_thermal_path<Coupled>("[model]\nrows = 8\ncouplings = \"dipolar\"\nrange = 3" +
                                thermal_rows.substr(17) + thermal);
  }
}
