// The GPU sweep at temperature T > 0 (docs/model.md §7): the Langevin stepper on the row model
// (nearest neighbours or a coupling table), in its own translation unit.
#include "ensemble/gpu/gpu_runner.cuh"

namespace rotorsweep::ensemble::gpu {

SweepOutcome run_langevin(const Scene& scene, const VariantRange& range, int host_threads,
                          const SweepControl& control, const ResultSink& sink) {
  return with_device_model(scene, [&]<class Model>() {
    return run_slots<Model, kernels::LeimkuhlerMatthews<Model>>(scene, range, host_threads, control, sink);
  });
}

}  // namespace rotorsweep::ensemble::gpu
