// The slider on the GPU (docs/architecture.md "Teams"): SliderTeamMember with a Rosenbrock stepper on warp teams,
// inertial or overdamped; the substrate tables copied to device memory once per size and speed.
#include <limits>
#include <memory>
#include <vector>

#include "ensemble/gpu/gpu_runner.cuh"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/slider/slider_slot_sweep.hpp"
#include "ensemble/slider/slider_team_member.hpp"
#include "kernels/models/slider/slider_on_teams.hpp"
#include "kernels/steppers/team_rosenbrock.hpp"

namespace rotorsweep::ensemble {

namespace gpu {

/// The slider's team integrator: a linearly implicit stepper (its tableau the scene's) on a warp team.
template <bool Inertial>
using SliderTeamIntegrator = kernels::TeamIntegrator<
    const kernels::WarpTeam, kernels::TeamRosenbrock<const kernels::WarpTeam, kernels::SliderModel<double, Inertial>>>;

/// Chunks of slider slots on the GPU, two in flight on the rows' ChunkStream, a member per team of a
/// warp's threads, by the plan of the chunk's size (plan_slider_size).
template <bool Inertial>
class GpuSliderDevice final : public SliderSlotDevice {
 public:
  explicit GpuSliderDevice(const GpuLaunch& launch) : launch_settings_(launch) {}

  using Integrator = SliderTeamIntegrator<Inertial>;
  using Driver = SliderTeamMember<const kernels::WarpTeam, Integrator>;
  static_assert(TeamMemberForm<Driver, const kernels::WarpTeam, SliderSlotSchedule, SliderSlotViews>);

  std::size_t chunk_members(const SliderSlotSchedule& schedule) override {
    chunks_.reset();  // another size's buffers
    const GpuPlan plan = plan_slider_size({schedule.grid.columns, schedule.grid.rows}, launch_settings_);
    team_ = plan.team;
    launch_ = std::make_unique<TeamLaunch>(team_launch(kernel(), plan, Driver::storage_size(schedule, team_)));
    return plan.chunk_members(launch_->grid.resident, std::numeric_limits<std::size_t>::max());
  }

  std::vector<kernels::SubstrateTableView> place_tables(
      const std::vector<const kernels::SubstrateTable*>& tables) override {
    tables_.clear();
    std::vector<kernels::SubstrateTableView> views;
    for (const kernels::SubstrateTable* table : tables) {
      if (!table) {
        views.emplace_back();
        continue;
      }
      kernels::SubstrateTableView view = table->view();
      const std::size_t bytes = view.coefficient_count() * sizeof(double);
      tables_.push_back(std::make_unique<DeviceBuffer>(bytes, "allocating a substrate table"));
      check(cudaMemcpy(tables_.back()->data(), view.coefficients, bytes, cudaMemcpyHostToDevice),
            "copying a substrate table");
      view.coefficients = static_cast<const double*>(tables_.back()->data());
      views.push_back(view);
    }
    return views;
  }

  void start(SliderSlotChunk& chunk, std::size_t slot) override {
    const TeamLaunch& l = *launch_;
    chunks_.start(chunk, slot,
                  [&](cudaStream_t stream, const SliderSlotViews& views, unsigned long long count,
                      unsigned long long* counter) {
                    kernel()<<<l.grid.blocks, l.grid.threads_per_block, l.grid.shared_bytes, stream>>>(
                        chunk.schedule(), views, count, counter, team_, l.global(), l.per_team);
                  });
  }

  double finish(SliderSlotChunk& chunk, std::size_t slot) override { return chunks_.finish(chunk, slot); }

 private:
  static auto kernel() {
    return sweep_slots_on_teams<SliderTeamMember, Integrator, SliderSlotSchedule, SliderSlotViews>;
  }

  GpuLaunch launch_settings_;
  unsigned team_ = 32;
  std::unique_ptr<TeamLaunch> launch_;
  std::vector<std::unique_ptr<DeviceBuffer>> tables_;
  ChunkStream<SliderSlotChunk, slider_slot_views> chunks_;
};

}  // namespace gpu

RunOutcome GpuExecutor::run_members(const SliderScene& scene, const std::vector<std::size_t>& plan_indices,
                                    const RunControl& control,
                                    const std::function<void(std::vector<SliderMember>&&)>& finished,
                                    const SliderTableBuilder& build_table) const {
  gpu::available_gpu();
  if (scene.overdamped) {
    gpu::GpuSliderDevice<false> device(launch_);
    return run_slider_members_in_slots(scene, plan_indices, control, finished, device, build_table);
  }
  gpu::GpuSliderDevice<true> device(launch_);
  return run_slider_members_in_slots(scene, plan_indices, control, finished, device, build_table);
}

}  // namespace rotorsweep::ensemble
