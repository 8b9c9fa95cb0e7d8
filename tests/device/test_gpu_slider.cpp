// The slider on a GPU (ctest label gpu; skipped where none is present): a member per warp team gives a
// host team's bits (tests/support/slider_slot_runs.hpp) at every team size, in both dynamics, with every
// optional series and on the experiment's 7 × 7 slider, and a member that fails is flagged as on the CPU.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "io/slider_scene_parser.hpp"
#include "support/scoped_variable.hpp"
#include "support/slider_slot_runs.hpp"
#include "test_paths.hpp"

using namespace rotorsweep;
using ensemble::SliderMember;

namespace {

/// The same bits: every summary and series, NaN where NaN.
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!(a[k] == b[k] || (std::isnan(a[k]) && std::isnan(b[k])))) return false;
  return true;
}

void check_same_members(const std::vector<SliderMember>& gpu, const std::vector<SliderMember>& host) {
  REQUIRE(gpu.size() == host.size());
  for (std::size_t k = 0; k < host.size(); ++k) {
    INFO("member " << k);
    CHECK(gpu[k].status == host[k].status);
    CHECK(same_bits({gpu[k].friction, gpu[k].order_x, gpu[k].order_y, gpu[k].steps_accepted},
                    {host[k].friction, host[k].order_x, host[k].order_y, host[k].steps_accepted}));
    CHECK(same_bits(gpu[k].period_balance, host[k].period_balance));
    CHECK(same_bits(gpu[k].period_force_y, host[k].period_force_y));
    for (const auto series :
         {&SliderMember::friction_series, &SliderMember::order_x_series, &SliderMember::order_y_series,
          &SliderMember::energy_series, &SliderMember::angles, &SliderMember::torques,
          &SliderMember::substrate_energy_series, &SliderMember::pair_energy_series,
          &SliderMember::field_axis_series, &SliderMember::field_z_series,
          &SliderMember::moment_axis_even_series, &SliderMember::moment_z_even_series,
          &SliderMember::torque_even_series, &SliderMember::moment_axis_odd_series,
          &SliderMember::moment_z_odd_series, &SliderMember::torque_odd_series, &SliderMember::force_x_series,
          &SliderMember::force_y_series, &SliderMember::force_z_series})
      CHECK(same_bits(gpu[k].*series, host[k].*series));
  }
}

/// The scan on the GPU with the environment's launch as it is now.
std::vector<SliderMember> on_gpu(const ensemble::SliderScene& scene) {
  const ensemble::GpuExecutor gpu(ensemble::gpu_launch());
  return ensemble::run_slider_scan(scene, {}, &gpu).members;
}

/// A 3 × 2 slider at two speeds, dampings and separations, two replicas, every optional series.
ensemble::SliderScene small_scene(const std::string& extra) {
  return io::parse_slider_scene_text(
      "[slider]\ncolumns = 3\nrows = 2\ndamping = [2.5e-6, 1e-5]\n" + extra +
          "[substrate]\ncolumns = 11\nrows = 11\n[drive]\nrest = 0.5\nperiods = 2\nspeed = [8e-3, 16e-3]\n"
          "[sweep]\nseparation = [7e-3, 9e-3]\n[initial]\nreplicas = 2\n[observables]\nsamples_per_period = "
          "20\nangles = true\nenergies = true\nfield = true\nsublattices = true\ntorques = true\nforces = "
          "true\n"
          "[numerics]\ndevice = \"gpu\"\n",
      "gpu-slider");
}

}  // namespace

TEST_CASE("the GPU's slider members give a host team's bits at every team size, in both dynamics", "[gpu]") {
  for (const std::string dynamics : {"", "dynamics = \"overdamped\"\n"}) {
    const auto scene = small_scene(dynamics);
    for (const std::string team : {"2", "4", "32"}) {
      INFO((dynamics.empty() ? "inertial" : "overdamped") << ", teams of " << team);
      const testing::ScopedVariable mapping("ROTORSWEEP_GPU_TEAM", team);
      check_same_members(on_gpu(scene), testing::slider_on_host_teams(scene, std::stoul(team), 1000));
    }
  }
}

TEST_CASE("the experiment's 7 x 7 slider on the GPU gives a host team's bits; a failing member is flagged",
          "[gpu]") {
  auto scene = io::parse_slider_scene_file(ROTORSWEEP_SOURCE_DIR "/examples/experiment_7x7_gpu.toml");
  scene.separations = {6e-3, 8e-3, 12e-3};
  scene.replicas = 3;
  scene.end = 4.5;
  check_same_members(on_gpu(scene), testing::slider_on_host_teams(scene, 32, 1000));
  scene.max_steps = 60;
  const auto failing = on_gpu(scene);
  for (const auto& m : failing) {
    CHECK(m.status == "step_budget");
    CHECK(std::isnan(m.friction));
  }
}
