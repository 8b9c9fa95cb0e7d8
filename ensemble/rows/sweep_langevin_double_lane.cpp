// The Langevin stepper's members on the double lane (docs/model.md §7), compiled once for every
// instruction set's sweeps (run_double_lane_thermal_row_sweep, sweep_runner.hpp).
#include "ensemble/rows/sweep_langevin.hpp"

namespace rotorsweep::ensemble {

SweepOutcome run_double_lane_thermal_row_sweep(const Scene& scene, const VariantRange& range,
                                               const RunControl& control, const ResultSink& sink) {
  return with_double_lane_model<RowModelForm::langevin>(scene.model, [&]<class Model>() {
    return run_langevin_on<Model>(scene, range, control, sink);
  });
}

}  // namespace rotorsweep::ensemble
