// The parts of the GPU executor every build has (gpu_executor.hpp): the result file's device label (the
// threads per member, and whether its rows live in registers), the row limit, and the process's executor.
#include "ensemble/gpu/gpu_executor.hpp"

#include "ensemble/gpu/device_drivers.hpp"
#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/rows/row_models.hpp"

namespace rotorsweep::ensemble {

std::string GpuExecutor::label(const Scene& scene) const {
  if (scene.row_counts.size() == 1)
    return "gpu (" + gpu_info().name + "; " + plan(scene, scene.row_counts.front()).threads_per_member() + ")";
  std::string mappings;
  for (const std::size_t n : scene.row_counts)
    mappings += (mappings.empty() ? "" : "; ") + plan(scene, n).threads_per_member() + " at N = " + std::to_string(n);
  return "gpu (" + gpu_info().name + "; " + mappings + ")";
}

std::string GpuExecutor::label(const SliderScene& scene) const {
  std::string teams;
  for (const SliderSize& size : scene.sizes)
    teams += (teams.empty() ? "" : ", ") + std::to_string(plan(size).team) +
             (scene.sizes.size() == 1 ? " threads per member"
                                      : " at " + std::to_string(size.columns) + " × " + std::to_string(size.rows));
  return "gpu (" + gpu_info().name + "; " + (scene.sizes.size() == 1 ? "" : "threads per member: ") + teams +
         ")";
}

std::size_t GpuExecutor::max_rows(const Scene& scene) const {
  if (gpu_team_size(scene, std::size_t(1) << 16, launch_) > 1) return row_model_traits(scene.model).team_max_rows;
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

const GpuExecutor& gpu_executor() {
  static const GpuExecutor executor(gpu_launch());
  return executor;
}

std::string device_label(const Scene& scene) {
  return scene.device == Device::cpu ? "cpu" : gpu_executor().label(scene);
}

std::string slider_device_label(const SliderScene& scene) {
  return scene.device == Device::cpu ? "cpu" : gpu_executor().label(scene);
}

}  // namespace rotorsweep::ensemble
