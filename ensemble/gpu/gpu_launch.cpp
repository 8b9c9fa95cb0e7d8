// The GPU backend's launch (docs/architecture.md "Teams"): the shape and the mapping from the
// environment, which scenes run on teams, and the team's size by N.
#include "ensemble/gpu/gpu_launch.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>

#include "ensemble/gpu/device_drivers.hpp"
#include "ensemble/gpu/gpu_register_shapes.hpp"
#include "ensemble/gpu/gpu_registers.hpp"
#include "ensemble/rows/symmetry_probe.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

namespace {

int positive_from_environment(const char* name, int fallback) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*end != '\0' || value < 1 || value > (1 << 20))
    throw GpuLaunchError(std::string(name) + " = '" + text + "': must be a positive integer");
  return int(value);
}

GpuScratch scratch_from_environment() {
  const char* text = std::getenv("ROTORSWEEP_GPU_SCRATCH");
  if (!text || !*text) return GpuScratch::automatic;
  const std::string value = text;
  if (value == "shared") return GpuScratch::shared;
  if (value == "global") return GpuScratch::global;
  throw GpuLaunchError("ROTORSWEEP_GPU_SCRATCH = '" + value + "': allowed: shared, global");
}

}  // namespace

int gpu_device_index(int devices) {
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_RANK", "SLURM_LOCALID"}) {
    const char* text = std::getenv(name);
    if (!text || !*text) continue;
    char* end = nullptr;
    const long rank = std::strtol(text, &end, 10);
    if (*end != '\0' || rank < 0 || rank > (1 << 24))
      throw GpuLaunchError(std::string(name) + " = '" + text +
                           "': not a local rank (a non-negative integer)");
    return devices > 0 ? int(rank % devices) : 0;
  }
  return 0;
}

GpuLaunch gpu_launch() {
  GpuLaunch launch;
  launch.threads_per_block = positive_from_environment("ROTORSWEEP_GPU_BLOCK", launch.threads_per_block);
  if (launch.threads_per_block > 1024 || launch.threads_per_block % 32 != 0)
    throw GpuLaunchError("ROTORSWEEP_GPU_BLOCK: must be a multiple of 32 from 32 to 1024");
  launch.blocks = positive_from_environment("ROTORSWEEP_GPU_BLOCKS", 0);
  const int team = positive_from_environment("ROTORSWEEP_GPU_TEAM", 0);
  if (team > 32 || (team & (team - 1)) != 0)
    throw GpuLaunchError("ROTORSWEEP_GPU_TEAM = " + std::to_string(team) +
                         ": allowed: 1, 2, 4, 8, 16 or 32 (1: a member per thread, 2 … 32: a team of a "
                         "warp's threads)");
  launch.team = unsigned(team);
  launch.scratch = scratch_from_environment();
  return launch;
}

bool gpu_teams_fit(const Scene& scene) {
  if (scene.thermal.on()) return true;  // the Langevin stepper, whatever numerics.stepper says
  return kernels::with_stepper_family(scene.stepper, [&]<kernels::StepperFamily family>() {
    return !std::is_void_v<
        DeviceTeamStepper<family, kernels::HostTeam, kernels::NearestNeighbourRows<double>>>;
  });
}

unsigned gpu_team_size(const Scene& scene, std::size_t rows, const GpuLaunch& launch) {
  if (!gpu_teams_fit(scene)) return 1;
  if (launch.team) return launch.team;
  if (rows <= 4) return 1;
  unsigned team = 1;
  while (team < 32 && 3 * team < rows) team *= 2;
  return team;
}

std::span<const RegisterShape> gpu_register_shapes() { return compiled_register_shapes; }

std::optional<RegisterShape> choose_register_shape(std::span<const RegisterShape> shapes, const Scene& scene,
                                                   std::size_t rows, const GpuLaunch& launch) {
  const kernels::Integrals q = scene.observables.quadratures();
  if (launch.team || scene.thermal.on() || !scene.couplings.nearest_neighbour() || scene.row_profiles ||
      kernels::stepper_family(scene.stepper) != kernels::StepperFamily::rosenbrock)
    return std::nullopt;
  // members that may run symmetry probes carry A's deviations in their rerun chunks: a shape that keeps
  // factors per row runs them (ensemble/rows/symmetry_probe.hpp)
  const bool probes = std::any_of(scene.rtol_values.begin(), scene.rtol_values.end(),
                                  [&](double rtol) { return runs_probes(scene, false, rtol); });
  const bool disordered = scene.disorder.any() || probes;
  const std::size_t stages =
      std::size_t(kernels::stepper_method<kernels::RosenbrockTableau>(scene.stepper).stages);
  std::optional<RegisterShape> best;
  for (const RegisterShape& shape : shapes) {
    if (shape.disordered != disordered || !shape.holds(rows) || shape.stages < stages ||
        (q | shape.carriable()) != shape.carriable() ||
        launch.threads_per_block > shape.max_threads_per_block())
      continue;
    const auto rank = [](const RegisterShape& s) {  // smaller is better
      return std::tuple{s.capacity(), -std::ptrdiff_t(s.lanes), s.stages, s.every_quadrature, -int(s.blocks)};
    };
    if (!best || rank(shape) < rank(*best)) best = shape;
  }
  return best;
}

}  // namespace rotorsweep::ensemble
