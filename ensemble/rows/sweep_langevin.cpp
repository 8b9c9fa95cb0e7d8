// The row model with the Langevin stepper, for scenes with thermal.temperature > 0 (docs/model.md
// §7), in its own translation unit: on this instruction set's SIMD lanes, or on the double lane.
#include "ensemble/rows/sweep_langevin.hpp"

namespace rotorsweep::ensemble {

SweepOutcome run_thermal_row_sweep(const Scene& scene, const VariantRange& range, const RunControl& control,
                                   const ResultSink& sink) {
  if (!on_simd_lanes(scene)) return run_double_lane_thermal_row_sweep(scene, range, control, sink);
  return with_simd_lane_model<RowModelForm::langevin, SweepOutcome>(scene, [&]<class Model>() {
    return run_langevin_on<Model>(scene, range, control, sink);
  });
}

}  // namespace rotorsweep::ensemble
