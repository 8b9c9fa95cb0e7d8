// Adaptive integration of one member on a team of threads (docs/architecture.md "Teams"): AdaptiveSteps
// with sums over the ranks' rows.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/adaptive_steps.hpp"
#include "kernels/steppers/step_control.hpp"
#include "kernels/steppers/team_member_form.hpp"

namespace rotorsweep::kernels {

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
