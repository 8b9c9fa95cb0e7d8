// The row model with the Langevin stepper, for scenes with thermal.temperature > 0 (docs/model.md
// §7), in its own translation unit.
#include "ensemble/rows/sweep_runner.hpp"
#include "kernels/steppers/leimkuhler_matthews.hpp"

namespace rotorsweep::ensemble {

SweepOutcome run_thermal_row_sweep(const Scene& scene, const VariantRange& range, const RunControl& control,
                                   const ResultSink& sink) {
  return with_row_model<RowModelForm::langevin>(scene, [&]<class Model>() {
    return run_lane_schedulers<Model, kernels::LeimkuhlerMatthews<Model>>(
        scene, range, RowSetup<Model>(&scene), control, sink);
  });
}

}  // namespace rotorsweep::ensemble
