// run_sweep_with for the rodas4p2 stepper (one translation unit per stepper keeps builds parallel).
#include "ensemble/sweep_runner.hpp"

namespace rotorsweep::ensemble {

template SweepOutcome run_sweep_with<kernels::StepperKind::rodas4p2>(const Scene&, const std::vector<Member>&,
                                                                     int, const ProgressCallback&);

}  // namespace rotorsweep::ensemble
