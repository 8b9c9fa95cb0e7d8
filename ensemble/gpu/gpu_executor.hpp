// The GPU as an executor (docs/architecture.md "Backends", "Teams"): the launch settings it was given,
// each variant's or slider size's GpuPlan, and the members run by that plan, as the sweeps' device.
#pragma once

#include <cstddef>
#include <string>

#include "ensemble/gpu/gpu_launch.hpp"
#include "ensemble/gpu/gpu_plan.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/sweep.hpp"
#include "ensemble/slider/slider_scene.hpp"
#include "ensemble/slider/slider_slot_sweep.hpp"

namespace rotorsweep::ensemble {

class GpuExecutor final : public RowDevice, public SliderDevice {
 public:
  explicit GpuExecutor(const GpuLaunch& launch = {}) : launch_(launch) {}

  const GpuLaunch& launch() const { return launch_; }
  GpuPlan plan(const Scene& scene, std::size_t rows) const { return plan_row_variant(scene, rows, launch_); }
  GpuPlan plan(SliderSize size) const { return plan_slider_size(size, launch_); }

  /// The result file's "device" of a GPU scene: "gpu (<name>; 8 threads per member)", the threads per
  /// member at each N (each size of a slider) where the scene has several.
  std::string label(const Scene& scene) const;
  std::string label(const SliderScene& scene) const;

  /// The most rows one member may have with the scene's model and stepper: its model's team_max_rows
  /// (row_models.hpp: a team's scratch lives in global or shared memory, sized at launch; the caps keep
  /// one team's well below a GPU's memory: about 60 N values for nearest neighbours, 65 536 rows, and
  /// for a coupling table its two dense N × N matrices, 268 MB at 4 096 rows) where it runs on teams,
  /// else what a thread's scratch of a fixed size holds (an even number like every row count).
  std::size_t max_rows(const Scene& scene) const;

  /// The variant's members by its plan; results go to `sink` as each chunk returns. Throws
  /// std::runtime_error where there is no GPU backend or no GPU.
  SweepOutcome run_variant(const Scene& scene, const VariantRange& range, const RunControl& control,
                           const ResultSink& sink) const override;

  /// Slider members by their sizes' plans, each chunk's members to `finished` as it returns. Throws
  /// std::runtime_error where there is no GPU backend or no GPU.
  RunOutcome run_members(const SliderScene& scene, const std::vector<std::size_t>& plan_indices,
                         const RunControl& control,
                         const std::function<void(std::vector<SliderMember>&&)>& finished,
                         const SliderTableBuilder& build_table) const override;

 private:
  GpuLaunch launch_;
};

/// The process's GPU executor: the launch from the environment (gpu_launch), read at its first call (a
/// bad value throws GpuLaunchError then, and again at the next call).
const GpuExecutor& gpu_executor();

/// gpu_executor() for a scene on the GPU, else none (the CPU's lanes run it): the sweeps' device argument.
inline const GpuExecutor* device_for(Device device) { return device == Device::gpu ? &gpu_executor() : nullptr; }

/// "cpu", or a GPU scene's label by gpu_executor().
std::string device_label(const Scene& scene);
std::string slider_device_label(const SliderScene& scene);

}  // namespace rotorsweep::ensemble
