// The form of the adaptive and Langevin steps for a block of lanes, a member per lane (AdaptiveSteps,
// LangevinSteps): the components in one part, sums in component order, the model's own evaluate.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/arena_storage.hpp"
#include "kernels/steppers/lane_state.hpp"
#include "kernels/steppers/lane_status.hpp"
#include "kernels/steppers/model_concept.hpp"

namespace rotorsweep::kernels {

/// The form of AdaptiveSteps and LangevinSteps for a block of lanes, a member per lane: sums over the
/// components in order, the model's own evaluate (for a first step's rate and the Langevin step);
/// LaneStageForm adds the Rosenbrock stages' needs.
template <LaneModel System>
class LaneMemberForm : public ArenaStorage<typename System::lane_type> {
 public:
  using value_type = typename System::lane_type;
  using scalar_type = value_type;
  using State = LaneState<value_type>;
  using Context = const System&;
  static constexpr std::size_t max_quadratures = System::max_quadratures;
  static constexpr double period = System::period;

  ROTORSWEEP_HD LaneMemberForm(std::size_t n, LaneArena<value_type>& arena) : n_(n), work_(n, arena) {}
  ROTORSWEEP_HD LaneMemberForm(std::size_t n, LaneArena<value_type>& arena, const System&)
      : LaneMemberForm(n, arena) {}

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
  ROTORSWEEP_HD void evaluate(Context system, const value_type* y, value_type t, value_type* f,
                              value_type* q) {
    system.evaluate(work_, y, t, f, q);
  }
  template <class Stepper>
  ROTORSWEEP_HD value_type first_rate(Context system, Stepper&, const State& s, value_type* f,
                                      value_type* q) {
    evaluate(system, s.y, s.t, f, q);
    value_type rate(1e-300);
    for (std::size_t k = 0; k < n_; ++k) rate = lane_max(rate, lane_abs(f[k]));
    return rate;
  }
  ROTORSWEEP_HD static LaneStatus& status(State& s, std::size_t lane) { return s.status[lane]; }

 protected:
  std::size_t n_;
  typename System::Workspace work_;
};

}  // namespace rotorsweep::kernels
