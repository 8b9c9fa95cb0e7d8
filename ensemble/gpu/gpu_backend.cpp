// The parts of the GPU backend every build has: the result file's device label (the threads per
// member, and whether its rows live in registers) and the row limit (of a thread's scratch, or of a team's).
#include "ensemble/gpu/gpu_backend.hpp"

#include <stdexcept>

#include "ensemble/gpu/device_drivers.hpp"
#include "ensemble/gpu/gpu_registers.hpp"
#include "ensemble/gpu/gpu_slider.hpp"

namespace rotorsweep::ensemble {

namespace {

/// "8 threads per member, rows in registers" (a register kernel) or "8 threads per member".
std::string threads_per_member(const Scene& scene, std::size_t rows, const GpuLaunch& launch) {
  if (const auto shape = choose_register_shape(gpu_register_shapes(), scene, rows, launch))
    return std::to_string(shape->lanes) + (shape->lanes == 1 ? " thread" : " threads") +
           " per member, rows in registers";
  const unsigned team = gpu_team_size(scene, rows, launch);
  return std::to_string(team) + (team == 1 ? " thread" : " threads") + " per member";
}

}  // namespace

std::string device_label(const Scene& scene) {
  if (scene.device == Device::cpu) return "cpu";
  const GpuLaunch launch = gpu_launch();
  if (scene.row_counts.size() == 1)
    return "gpu (" + gpu_info().name + "; " + threads_per_member(scene, scene.row_counts.front(), launch) + ")";
  std::string mappings;
  for (const std::size_t n : scene.row_counts)
    mappings += (mappings.empty() ? "" : "; ") + threads_per_member(scene, n, launch) + " at N = " + std::to_string(n);
  return "gpu (" + gpu_info().name + "; " + mappings + ")";
}

std::size_t gpu_max_rows(const Scene& scene) {
  if (gpu_team_size(scene, gpu_team_max_rows, gpu_launch()) > 1)
    return scene.couplings.nearest_neighbour() ? gpu_team_max_rows : gpu_coupled_team_max_rows;
  return with_device_driver(scene, [&]<class Model, class Integrator>() {
    SlotSchedule s;  // what the scratch depends on: rows, quadratures, row profiles
    s.quadratures = scene.observables.quadratures();
    s.row_profiles = scene.row_profiles;
    const auto fits = [&](std::size_t rows) {
      s.rows = rows;
      return DeviceMember<Model, Integrator>::storage_size(s) <= gpu_thread_scratch;
    };
    std::size_t n = 2;
    while (fits(n + 1)) ++n;
    return n - n % 2;  // rows come in even numbers
  });
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

std::string slider_device_label(const SliderScene& scene) {
  if (scene.device == Device::cpu) return "cpu";
  const GpuLaunch launch = gpu_launch();
  std::string teams;
  for (const SliderSize& size : scene.sizes)
    teams +=
        (teams.empty() ? "" : ", ") + std::to_string(gpu_slider_team_size(size, launch)) +
        (scene.sizes.size() == 1 ? " threads per member"
                                 : " at " + std::to_string(size.columns) + " × " + std::to_string(size.rows));
  return "gpu (" + gpu_info().name + "; " + (scene.sizes.size() == 1 ? "" : "threads per member: ") + teams +
         ")";
}

}  // namespace rotorsweep::ensemble
