// The GPU sweep at temperature T > 0 (docs/model.md §7): the Langevin stepper on the row model
// (nearest neighbours or a coupling table), a member per thread or per team, in its own translation unit.
#include "ensemble/gpu/gpu_runner.cuh"
#include "kernels/steppers/team_leimkuhler_matthews.hpp"

namespace rotorsweep::ensemble::gpu {

SweepOutcome run_langevin(const Scene& scene, const VariantRange& range, const GpuPlan& plan,
                          const RunControl& control, const ResultSink& sink) {
  return with_device_model<RowModelForm::device_langevin>(scene, [&]<class Model>() {
    return run_planned<Model, kernels::LeimkuhlerMatthews<Model>,
                       kernels::TeamLeimkuhlerMatthews<const kernels::WarpTeam, Model>>(scene, range, plan,
                                                                                          control, sink);
  });
}

}  // namespace rotorsweep::ensemble::gpu
