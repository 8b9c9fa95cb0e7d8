// The row model with the Langevin stepper, for scenes with thermal.temperature > 0 (docs/model.md
// §7), in its own translation unit.
#include "ensemble/sweep_runner.hpp"
#include "kernels/langevin_euler.hpp"

namespace rotorsweep::ensemble {

SweepOutcome run_thermal_row_sweep(const Scene& scene, const std::vector<Member>& members, int threads,
                                   const ProgressCallback& progress) {
  return with_flag(scene.lanes == LaneKind::simd, [&]<bool simd>() {
    using V = std::conditional_t<simd, kernels::simd_lane, double>;
    return with_integrals(scene.observables.quadratures(), [&]<kernels::Integrals Q>() {
      using Model = kernels::NearestNeighbourRows<V, Q>;
      return run_lane_schedulers<Model, kernels::LangevinEuler<Model>>(
          scene, members, RowSetup<Model>(&scene), threads, progress);
    });
  });
}

}  // namespace rotorsweep::ensemble
