// Adaptive lockstep integration of a block of lanes (AdaptiveSteps over LaneMemberForm): each lane has its
// own t, h, stopping time and status; accept/reject is a mask, and a failing lane freezes alone.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/adaptive_steps.hpp"
#include "kernels/steppers/lane_state.hpp"
#include "kernels/steppers/model_concept.hpp"

namespace rotorsweep::kernels {

/// The form of AdaptiveSteps and LangevinSteps for a block of lanes, a member per lane: sums over the
/// components in order, the model's own evaluate (for a first step's rate and the Langevin step).
template <LaneModel System>
class LaneMemberForm {
 public:
  using value_type = typename System::lane_type;
  using State = LaneState<value_type>;
  using Context = const System&;
  static constexpr std::size_t max_quadratures = System::max_quadratures;
  static constexpr double period = System::period;

  ROTORSWEEP_HD LaneMemberForm(std::size_t n, LaneArena<value_type>& arena, const System&)
      : n_(n), work_(n, arena) {}

  ROTORSWEEP_HD static const System& model(Context system) { return system; }
  template <class Part>
  ROTORSWEEP_HD void rows(Context, Part&& part) const {
    part(std::size_t(0), n_);
  }
  template <class Part>
  ROTORSWEEP_HD value_type sum(Context, Part&& part) const {
    return part(std::size_t(0), n_);
  }
  template <class Stepper, class... Arguments>
  ROTORSWEEP_HD auto step(Stepper& stepper, Context system, Arguments... arguments) const {
    return stepper.attempt(system, arguments...);
  }
  ROTORSWEEP_HD void evaluate(Context system, const value_type* y, value_type t, value_type* f, value_type* q) {
    system.evaluate(work_, y, t, f, q);
  }
  template <class Stepper>
  ROTORSWEEP_HD value_type first_rate(Context system, Stepper&, const State& s, value_type* f, value_type* q) {
    evaluate(system, s.y, s.t, f, q);
    value_type rate(1e-300);
    for (std::size_t k = 0; k < n_; ++k) rate = lane_max(rate, lane_abs(f[k]));
    return rate;
  }
  ROTORSWEEP_HD static LaneStatus& status(State& s, std::size_t lane) { return s.status[lane]; }

 private:
  std::size_t n_;
  typename System::Workspace work_;
};

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

  ROTORSWEEP_HD AdaptiveIntegrator(const System& system, const Method& method, Tolerances tol, StepLimits limits,
                                   LaneArena<V>& arena)
      : AdaptiveIntegrator(system, method, tol, limits, Steps::first_step_scale(tol, method), arena) {}

  ROTORSWEEP_HD AdaptiveIntegrator(const System& system, const Method& method, Tolerances tol, StepLimits limits,
                                   double first_step_scale, LaneArena<V>& arena)
      : Steps(system.dimension(), method, tol, limits, first_step_scale, arena, system) {}
};

}  // namespace rotorsweep::kernels
