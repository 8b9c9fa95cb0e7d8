// The row model's members with the Langevin stepper (the Leimkuhler-Matthews step, docs/model.md §7) on
// lane type Model::lane_type: what the SIMD and the double-lane units of thermal sweeps instantiate.
#pragma once

#include "ensemble/rows/sweep_runner.hpp"
#include "kernels/steppers/leimkuhler_matthews.hpp"

namespace rotorsweep::ensemble {

template <class Model>
SweepOutcome run_langevin_on(const Scene& scene, const VariantRange& range, const RunControl& control,
                             const ResultSink& sink) {
  return run_lane_schedulers<Model, kernels::LeimkuhlerMatthews<Model>>(scene, range, RowSetup<Model>(&scene),
                                                                        control, sink);
}

}  // namespace rotorsweep::ensemble
