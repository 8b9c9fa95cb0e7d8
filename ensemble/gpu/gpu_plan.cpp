// One GPU plan (gpu_plan.hpp; docs/architecture.md "Teams"): which scenes run on teams, a team's size by N,
// the register shape by N, where a team's vectors live and the chunk's size, for rows and the slider.
#include "ensemble/gpu/gpu_plan.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <tuple>
#include <type_traits>

#include "ensemble/gpu/device_drivers.hpp"
#include "ensemble/gpu/gpu_register_shapes.hpp"
#include "ensemble/rows/row_models.hpp"
#include "ensemble/rows/symmetry_probe.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

std::size_t GpuPlan::chunk_members(std::size_t resident, std::size_t members) const {
  return std::min(members, std::max(chunk_per_resident * resident, chunk_floor));
}

std::string GpuPlan::threads_per_member() const {
  return std::to_string(team) + (team == 1 ? " thread" : " threads") + " per member" +
         (mapping == GpuMapping::registers ? ", rows in registers" : "");
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
  if (launch.team || scene.thermal.on() || !row_model_traits(scene.model).register_form || scene.row_profiles ||
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

GpuPlan plan_row_variant(const Scene& scene, std::size_t rows, const GpuLaunch& launch,
                         std::span<const RegisterShape> shapes) {
  GpuPlan plan;
  plan.threads_per_block = launch.threads_per_block;
  plan.blocks = launch.blocks;
  plan.scratch = launch.scratch == GpuScratch::global ? GpuScratch::global : GpuScratch::shared;
  plan.scratch_asked = launch.scratch != GpuScratch::automatic;
  if (scene.thermal.on()) {  // the Langevin stepper has no register kernel
    plan.team = gpu_team_size(scene, rows, launch);
  } else if (const auto shape = choose_register_shape(shapes, scene, rows, launch)) {
    plan.shape = shape;
    plan.team = unsigned(shape->lanes);
    plan.mapping = GpuMapping::registers;
    return plan;
  } else {
    plan.team = gpu_team_size(scene, rows, launch);
  }
  plan.mapping = plan.team > 1 ? GpuMapping::team : GpuMapping::thread;
  return plan;
}

unsigned gpu_slider_team_size(SliderSize size, const GpuLaunch& launch) {
  if (launch.team) {
    if (launch.team < 2 || launch.team > 32)
      throw GpuLaunchError("ROTORSWEEP_GPU_TEAM = " + std::to_string(launch.team) +
                           ": a slider member runs on a team of 2, 4, 8, 16 or 32 threads");
    return launch.team;
  }
  unsigned team = 2;
  while (team < 32 && 3 * team < size.rotors()) team *= 2;
  return team;
}

GpuPlan plan_slider_size(SliderSize size, const GpuLaunch& launch) {
  GpuPlan plan;
  plan.mapping = GpuMapping::team;
  plan.team = gpu_slider_team_size(size, launch);
  plan.threads_per_block = launch.threads_per_block;
  plan.blocks = launch.blocks;
  plan.scratch = launch.scratch == GpuScratch::shared ? GpuScratch::shared : GpuScratch::global;
  plan.scratch_asked = launch.scratch != GpuScratch::automatic;
  plan.chunk_per_resident = 4;
  plan.chunk_floor = 1024;
  return plan;
}

}  // namespace rotorsweep::ensemble
