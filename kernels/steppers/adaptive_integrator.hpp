// Adaptive lockstep integration of a block of lanes (AdaptiveSteps over LaneMemberForm): each lane has its
// own t, h, stopping time and status; accept/reject is a mask, and a failing lane freezes alone.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/adaptive_steps.hpp"
#include "kernels/steppers/lane_member_form.hpp"
#include "kernels/steppers/model_concept.hpp"

namespace rotorsweep::kernels {

/// One step attempt per lane (AdaptiveSteps::attempt(system, state)) with any Stepper of the model.
template <LaneModel System, class Stepper>
class AdaptiveIntegrator : public AdaptiveSteps<LaneMemberForm<System>, Stepper> {
  using Steps = AdaptiveSteps<LaneMemberForm<System>, Stepper>;

 public:
  using V = typename System::lane_type;
  using Method = typename Stepper::Method;

  /// What a driver configures: the stepper's tableau, tolerances and step limits.
  struct Settings {
    Method method;
    Tolerances tolerances;
    StepLimits limits;
  };

  ROTORSWEEP_HD AdaptiveIntegrator(const System& system, const Settings& settings, LaneArena<V>& arena)
      : AdaptiveIntegrator(system, settings.method, settings.tolerances, settings.limits, arena) {}

  ROTORSWEEP_HD AdaptiveIntegrator(const System& system, const Method& method, Tolerances tol,
                                   StepLimits limits, LaneArena<V>& arena)
      : AdaptiveIntegrator(system, method, tol, limits, Steps::first_step_scale(tol, method), arena) {}

  ROTORSWEEP_HD AdaptiveIntegrator(const System& system, const Method& method, Tolerances tol,
                                   StepLimits limits, double first_step_scale, LaneArena<V>& arena)
      : Steps(system.dimension(), method, tol, limits, first_step_scale, arena, system) {}
};

}  // namespace rotorsweep::kernels
