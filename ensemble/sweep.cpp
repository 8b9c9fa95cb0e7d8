// run_sweep: dispatch from the scene's stepper name to its instantiation (sweep_<stepper>.cpp).
#include "ensemble/sweep.hpp"

#include "kernels/stepper_choice.hpp"

namespace rotorsweep::ensemble {

template <kernels::StepperKind kind>
SweepOutcome run_sweep_with(const Scene&, const std::vector<Member>&, int, const ProgressCallback&);

SweepOutcome run_sweep(const Scene& scene, const std::vector<Member>& members, int threads,
                       const ProgressCallback& progress) {
  switch (scene.stepper) {
    case kernels::StepperKind::ros2:
      return run_sweep_with<kernels::StepperKind::ros2>(scene, members, threads, progress);
    case kernels::StepperKind::dopri5:
      return run_sweep_with<kernels::StepperKind::dopri5>(scene, members, threads, progress);
    case kernels::StepperKind::rodas4: break;
  }
  return run_sweep_with<kernels::StepperKind::rodas4>(scene, members, threads, progress);
}

}  // namespace rotorsweep::ensemble
