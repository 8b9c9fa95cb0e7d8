// The GPU backend on a GPU (ctest label gpu; skipped with a message where none is present): a member
// per thread gives the CPU lanes' bits (paper, every scene kind; the examples under "[long]"), a member
// per team a host team's bits, no mapping depends on the launch shape, a failing member stays alone.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include "ensemble/engine/thread_count.hpp"
#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/paper_table.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "kernels/models/rows/row_models_on_teams.hpp"
#include "kernels/steppers/leimkuhler_matthews.hpp"
#include "kernels/steppers/team_leimkuhler_matthews.hpp"
#include "support/same_results.hpp"
#include "support/scoped_variable.hpp"
#include "support/slot_runs.hpp"
#include "test_paths.hpp"

using namespace rotorsweep;

namespace {

using testing::ScopedVariable;

/// The members on `device` (the GPU with the environment's launch as it is now), on every core
/// (OMP_NUM_THREADS where set) for the CPU's part.
std::vector<ensemble::MemberResult> run_on(ensemble::Scene scene, ensemble::Device device,
                                           const std::vector<ensemble::Member>& members) {
  scene.device = device;
  const ensemble::GpuExecutor gpu(ensemble::gpu_launch());
  return ensemble::run_sweep(scene, members, {.threads = ensemble::thread_count(0)}, &gpu).results;
}

/// A member per GPU thread against the CPU lanes: the same bits.
void check_gpu_matches_cpu(const ensemble::Scene& scene) {
  const ScopedVariable per_thread("ROTORSWEEP_GPU_TEAM", "1");
  const auto members = ensemble::plan_members(scene);
  const auto cpu = run_on(scene, ensemble::Device::cpu, members);
  const auto gpu = run_on(scene, ensemble::Device::gpu, members);
  std::string first;
  CHECK(testing::count_differences(cpu, gpu, first) == 0);
  INFO(first);
  CHECK(first.empty());
}

/// 12 × `points` members over the curve; one relaxed and one averaged period and no shadow runs
/// (global_error "local"; the paper's case keeps them), since a GPU thread takes a member's whole run at
/// its own pace and the shadows' chunks are a second such run (a case's time is its slowest member's on
/// one thread: H100, 2 + 2 periods with shadows, "every stepper" 66 s, the mappings 61 s; 1 + 1 without
/// shadows 16 s and 27 s).
std::string curve_scene(const std::string& stepper, int rows, const std::string& rtol, int points = 32) {
  return "[model]\nrows = " + std::to_string(rows) +
         "\n[drive]\ng = [0.01, 0.1]\n[sweep]\nA = {from = 0.25, to = 16, count = " + std::to_string(points) +
         "}\n"
         "[initial]\nkinds = [\"AFM\", \"random\", \"FM\"]\nreplicas = 2\n[schedule]\nrelax_periods = 1\n"
         "average_periods = 1\n[numerics]\nstepper = \"" +
         stepper + "\"\nrtol = " + rtol + "\natol = 1e-12\nglobal_error = \"local\"\n";
}

}  // namespace

TEST_CASE("the GPU gives the CPU lanes' bits for every stepper at N = 2, 20", "[gpu]") {
  // tight tolerances for the higher-order methods; ros2 (order 2) and dopri5 (explicit) at looser ones
  for (const auto& [stepper, rtol] :
       {std::pair{"rodas4", "1e-8"}, std::pair{"ros2", "1e-5"}, std::pair{"dopri5", "1e-6"},
        std::pair{"rodas4p2", "1e-8"}, std::pair{"rodas5p", "1e-8"}})
    for (int rows : {2, 20}) {
      INFO(stepper << " N = " << rows);
      check_gpu_matches_cpu(io::parse_scene_text(curve_scene(stepper, rows, rtol), "gpu"));
    }
}

TEST_CASE("the GPU gives the CPU's bits for the paper's table", "[gpu]") {
  const auto paper = io::parse_scene_text(
      "[model]\nrows = 20\n[drive]\ng = [0.0011]\n[sweep]\nA = [1, 4, 6, 8, 11]\n"
      "[initial]\nkinds = [\"FM\", \"AFM\"]\n[schedule]\nrelax_periods = 2\naverage_periods = 2\n"
      "[numerics]\nrtol = 1e-10\natol = 1e-12\n",
      "paper");
  check_gpu_matches_cpu(paper);
  const auto members = ensemble::plan_members(paper);
  const auto gpu = run_on(paper, ensemble::Device::gpu, members);
  for (const auto& entry : ensemble::paper_table::entries) {
    if (entry.cp) continue;  // the CP values depend on the noise draw
    for (std::size_t i = 0; i < members.size(); ++i)
      if (members[i].A == entry.A && members[i].kind == entry.kind) {
        INFO("A = " << entry.A);
        CHECK(gpu[i].dissipation() == Approx(entry.paper_R).epsilon(1e-5));
      }
  }
}

// The long comparisons with the CPU (hidden: `test_gpu "[long]"`; the host suite checks the host's
// emulations against the CPU lanes, and the cases above the device against them).
TEST_CASE("a member per GPU thread gives the CPU's bits for the example scenes", "[.][long]") {
  for (const char* path : {ROTORSWEEP_SOURCE_DIR "/examples/friction_curve.toml",
                           ROTORSWEEP_SOURCE_DIR "/examples/robustness.toml",
                           ROTORSWEEP_SOURCE_DIR "/examples/disorder_curve.toml",
                           ROTORSWEEP_SOURCE_DIR "/examples/basins.toml"}) {
    INFO(path);
    check_gpu_matches_cpu(io::parse_scene_file(path));
  }
}

TEST_CASE(
    "the GPU gives the CPU's bits for every scene kind: disorder, T > 0, couplings, open rows, "
    "row profiles",
    "[gpu]") {
  const std::string base = curve_scene("rodas4p2", 8, "1e-8");
  const std::string model = "[model]\nrows = 8\n";
  const std::string rest = base.substr(model.size());
  for (const std::string& scene :
       {base + "[disorder]\nA = 1e-3\nanisotropy = 1e-3\ncoupling = 1e-3\n",
        base + "[thermal]\ntemperature = 0.05\nsteps_per_period = 400\n[observables]\nrow_profiles = true\n",
        model + "couplings = \"dipolar\"\nrange = \"all\"\n" + rest,
        model + "couplings = \"dipolar\"\nrange = 3\nboundary = \"open\"\n" + rest,
        base + "[observables]\nrow_profiles = true\nenergy = true\nestimators = true\n"}) {
    INFO(scene);
    check_gpu_matches_cpu(io::parse_scene_text(scene, "kinds"));
  }
}

TEST_CASE("the GPU's results do not depend on the launch shape or a team's scratch", "[gpu][mappings]") {
  const auto scene = io::parse_scene_text(curve_scene("rodas4", 20, "1e-6"), "launch");
  const auto members = ensemble::plan_members(scene);
  for (const char* team : {"", "8"}) {  // "": in registers (8 × 3); a member per thread: every other case
    const ScopedVariable mapping("ROTORSWEEP_GPU_TEAM", team);
    const auto reference = run_on(scene, ensemble::Device::gpu, members);
    for (const auto& [block, blocks, scratch] :
         {std::tuple{"32", "1", "global"}, std::tuple{"64", "7", "shared"},
          std::tuple{"256", "1000", "global"}}) {
      const ScopedVariable b("ROTORSWEEP_GPU_BLOCK", block), bs("ROTORSWEEP_GPU_BLOCKS", blocks),
          sc("ROTORSWEEP_GPU_SCRATCH", scratch);
      const auto other = run_on(scene, ensemble::Device::gpu, members);
      std::string first;
      INFO("team " << team << ": " << block << " threads × " << blocks << " blocks, scratch " << scratch);
      CHECK(testing::count_differences(reference, other, first) == 0);
      INFO(first);
      CHECK(first.empty());
    }
  }
}

TEST_CASE(
    "a member per GPU team gives a host team's bits, for every team size, stepper, coupling tables and "
    "at T > 0",
    "[gpu]") {
  // the host team's run through one chunk has no shadow runs (which run the same kernel again)
  // the smallest team and a warp's (teams of 8 in the launch mappings' and the thermal checks)
  const auto check_sizes = [&]<kernels::StepperId id>(ensemble::Scene scene,
                                                      std::vector<int> teams = {2, 32}) {
    scene.shadow_runs = false;
    const auto members = ensemble::plan_members(scene);
    for (const int team : teams) {
      const ScopedVariable mapping("ROTORSWEEP_GPU_TEAM", std::to_string(team));
      const auto gpu = run_on(scene, ensemble::Device::gpu, members);
      const auto host = testing::on_host_team(scene, std::size_t(team));
      std::string first;
      INFO(kernels::stepper_names[id] << ", team " << team);
      CHECK(testing::count_differences(host, gpu, first) == 0);
      INFO(first);
      CHECK(first.empty());
    }
  };
  check_sizes.template operator()<*kernels::parse_stepper("rodas4p2")>(
      io::parse_scene_text(curve_scene("rodas4p2", 20, "1e-8", 8) +
                               "[disorder]\nA = 1e-4\n[observables]\nestimators = true\nenergy = "
                               "true\nmoments = true\nrow_profiles = true\n",
                           "teams"));
  // a coupling table, periodic, and the experiment's open dipolar rows (TeamDenseSymmetric)
  check_sizes.template operator()<*kernels::parse_stepper("rodas4p2")>(io::parse_scene_text(
      "[model]\nrows = 20\ncouplings = \"dipolar\"\nrange = 4\n" +
          curve_scene("rodas4p2", 20, "1e-8", 8).substr(17) +
          "[observables]\nestimators = true\nenergy = true\nmoments = true\nrow_profiles = true\n",
      "teams-coupled"));
  check_sizes.template operator()<*kernels::parse_stepper("rodas4p2")>(
      io::parse_scene_file(ROTORSWEEP_SOURCE_DIR "/examples/experiment_rows.toml"));
  const auto thermal = io::parse_scene_text(
      "[model]\nrows = 20\n[drive]\ng = [0.01]\n[sweep]\nA = [1, 6, 12]\n[initial]\nkinds = [\"random\"]\n"
      "replicas = 2\n[thermal]\ntemperature = 0.05\nsteps_per_period = 200\n[observables]\nenergy = true\n"
      "row_profiles = true\n",
      "teams-thermal");
  const auto members = ensemble::plan_members(thermal);
  for (const int team : {8}) {
    const ScopedVariable mapping("ROTORSWEEP_GPU_TEAM", std::to_string(team));
    const auto gpu = run_on(thermal, ensemble::Device::gpu, members);
    using Model = kernels::NearestNeighbourRows<double>;
    const auto host = testing::on_host_team<kernels::LeimkuhlerMatthews<Model>,
                                            kernels::TeamLeimkuhlerMatthews<kernels::HostTeam, Model>>(
        thermal, std::size_t(team));
    std::string first;
    INFO("T > 0, team " << team);
    CHECK(testing::count_differences(host, gpu, first) == 0);
    INFO(first);
    CHECK(first.empty());
  }
  check_sizes.template operator()<*kernels::parse_stepper("rodas5p")>(
      io::parse_scene_text(curve_scene("rodas5p", 20, "1e-8", 8), "teams"), {8});
}

TEST_CASE(
    "the GPU's default mapping agrees with the CPU: labels on the examples but where rounding decides them, "
    "D "
    "to 1e-10 at rtol 1e-10",
    "[.][long]") {
  for (const char* path :
       {ROTORSWEEP_SOURCE_DIR "/examples/friction_curve.toml", ROTORSWEEP_SOURCE_DIR "/examples/basins.toml",
        ROTORSWEEP_SOURCE_DIR "/examples/robustness.toml"}) {
    INFO(path);
    const auto scene = io::parse_scene_file(path);
    const auto members = ensemble::plan_members(scene);
    const auto cpu = run_on(scene, ensemble::Device::cpu, members);
    const auto gpu = run_on(scene, ensemble::Device::gpu, members);  // N = 20: in registers (8 × 3), or teams of 8
    for (std::size_t i = 0; i < members.size(); ++i) {
      INFO("member " << i);
      // rounding decides these (docs/regimes.md "Errors in CP, and symmetry-limited members")
      if (cpu[i].symmetry_limited) continue;
      CHECK(gpu[i].regime == cpu[i].regime);
      CHECK(gpu[i].final_state.attractor == cpu[i].final_state.attractor);
    }
  }
  const auto paper = io::parse_scene_text(
      "[model]\nrows = 20\n[drive]\ng = [0.0011]\n[sweep]\nA = {from = 0.5, to = 14, count = 28}\n"
      "[initial]\nkinds = [\"FM\", \"AFM\"]\nnoise = 0.01\n[disorder]\nA = 1e-6\n[schedule]\n"
      "relax_periods = 2\naverage_periods = 2\n[numerics]\nrtol = 1e-10\natol = 1e-13\n",
      "paper");
  const auto members = ensemble::plan_members(paper);
  const auto cpu = run_on(paper, ensemble::Device::cpu, members);
  const auto gpu = run_on(paper, ensemble::Device::gpu, members);
  for (std::size_t i = 0; i < members.size(); ++i) {
    INFO("A = " << members[i].A);
    CHECK(gpu[i].regime == cpu[i].regime);
    if (cpu[i].regime == ensemble::Regime::cp) continue;
    CHECK(gpu[i].dissipation() == Approx(cpu[i].dissipation()).epsilon(1e-10).margin(1e-14));
  }
}

TEST_CASE("a member that fails on the GPU leaves the others' bits alone", "[gpu][mappings]") {
  auto scene = io::parse_scene_text(curve_scene("rodas4", 20, "1e-6"), "failure");
  scene.device = ensemble::Device::gpu;
  auto members = ensemble::plan_members(scene);
  const auto clean = run_on(scene, ensemble::Device::gpu, members);
  const std::size_t broken = members.size() / 3;
  members[broken].A = std::numeric_limits<double>::quiet_NaN();
  const auto with_failure = run_on(scene, ensemble::Device::gpu, members);
  CHECK(with_failure[broken].status == kernels::LaneStatus::non_finite);
  CHECK(std::isnan(with_failure[broken].dissipation()));
  std::size_t differ = 0;
  for (std::size_t i = 0; i < members.size(); ++i)
    if (i != broken) differ += !testing::result_difference(clean[i], with_failure[i]).empty();
  CHECK(differ == 0);
}
