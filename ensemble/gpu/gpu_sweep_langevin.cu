// The GPU sweep at temperature T > 0 (docs/model.md §7): the Langevin stepper on the row model
// (nearest neighbours or a coupling table), a member per thread or per team, in its own translation unit.
#include "ensemble/gpu/gpu_runner.cuh"
#include "kernels/steppers/team_leimkuhler_matthews.hpp"

namespace rotorsweep::ensemble::gpu {

SweepOutcome run_langevin(const Scene& scene, const VariantRange& range, const RunControl& control,
                          const ResultSink& sink) {
  return with_device_model(scene, [&]<class Model>() {
    using Integrator = kernels::LeimkuhlerMatthews<Model>;
    const unsigned team = gpu_team_size(scene, range.source->at(range.begin).rows, gpu_launch());
    if (team > 1)
      return run_slots_on_teams<Integrator, kernels::TeamLeimkuhlerMatthews<const kernels::WarpTeam, Model>>(
          scene, range, team, control, sink);
    return run_slots<Model, Integrator>(scene, range, control, sink);
  });
}

}  // namespace rotorsweep::ensemble::gpu
