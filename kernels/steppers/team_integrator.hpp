// Adaptive integration of one member on a team of threads (docs/architecture.md "Teams"): AdaptiveSteps
// with sums over the ranks' rows; the same decisions for a member in registers (control_member_step).
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/adaptive_steps.hpp"
#include "kernels/steppers/lane_status.hpp"
#include "kernels/steppers/step_control.hpp"
#include "kernels/steppers/team_member_form.hpp"

namespace rotorsweep::kernels {

/// AdaptiveIntegrator::attempt's decision for one member whose step of size h (clipped: to land on
/// s.t_stop) has the error norm `err`: whether it is accepted (finite err and `checksum`, the sum of the
/// new state and quadratures; every unstable direction resolved; err ≤ 1), then s's time, next step
/// size, counts and failure status, and `error_previous` for the PI controller. The caller takes the
/// new state where it returns true: AdaptiveSteps' decisions for one member, written out for a member in
/// registers (WarpIntegrator), whose vectors are no arrays to hand a form.
template <class State>
ROTORSWEEP_HD bool control_member_step(const StepLimits& limits, int embedded_order, double err,
                                       double checksum, bool resolved, double h, bool clipped,
                                       double& error_previous, State& s) {
  const bool finite = std::isfinite(err) && std::isfinite(checksum);
  const bool accept = finite && resolved && err <= 1.0;
  if (accept) s.t = clipped ? s.t_stop : s.t + h;
  double h_next =
      h * step_factor(limits, embedded_order, finite ? err : err + INFINITY, error_previous, accept);
  if (accept) error_previous = err > pi_error_floor ? err : pi_error_floor;
  if (accept && clipped && s.h > h_next) h_next = s.h;
  if (!resolved) h_next = h * limits.shrink_min;
  s.h = h_next < limits.h_max ? h_next : limits.h_max;
  (accept ? s.steps_accepted : s.steps_rejected) += 1.0;

  const double h_floor = 16.0 * 0x1p-52 * (std::fabs(s.t) > 1.0 ? std::fabs(s.t) : 1.0);
  if (s.steps_accepted + s.steps_rejected >= limits.max_steps)
    s.status = LaneStatus::step_budget;
  else if (s.h < h_floor)
    s.status = finite ? LaneStatus::step_underflow : LaneStatus::non_finite;
  return accept;
}

/// One member's adaptive steps on a team with a team stepper (TeamRosenbrock): AdaptiveIntegrator's
/// proposal of the first step, error norm, acceptance, step-size control and failure flags
/// (AdaptiveSteps), decided alike on every rank from team sums.
template <class Team, class Stepper>
class TeamIntegrator : public AdaptiveSteps<TeamMemberForm<Team, typename Stepper::Model>, Stepper> {
  using Steps = AdaptiveSteps<TeamMemberForm<Team, typename Stepper::Model>, Stepper>;

 public:
  using Model = typename Stepper::Model;
  using TeamType = Team;

  ROTORSWEEP_HD TeamIntegrator(const Model& model, std::size_t ranks, const typename Steps::Method& method,
                               Tolerances tol, StepLimits limits, double first_step_scale,
                               LaneArena<double>& arena)
      : Steps(model.dimension(), method, tol, limits, first_step_scale, arena, model, ranks) {}

  /// One step attempt, clipped to land on t_stop, where the member steps; returns whether it
  /// accepted one.
  ROTORSWEEP_HD bool attempt(Team& team, const Model& model, TeamMemberState& s) {
    return Steps::attempt({team, model}, s);
  }
  /// Attempts steps until the member reaches its t_stop or fails.
  ROTORSWEEP_HD void advance(Team& team, const Model& model, TeamMemberState& s) {
    Steps::advance({team, model}, s);
  }
};

}  // namespace rotorsweep::kernels
