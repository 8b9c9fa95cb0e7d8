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

namespace rotorsweep::kernels {

/// One member's state on a team: θ, the team's array, and what every rank keeps alike (each its own
/// copy): the quadratures, time, step size, stopping time, counts and status.
struct TeamMemberState {
  static constexpr std::size_t max_quadratures = 8;  ///< the row models' Integrals::max_count
  double* y = nullptr;
  double quad[max_quadratures] = {};
  double t = 0.0, h = 0.0, t_stop = 0.0;  ///< h = 0 asks for an automatic first step
  double steps_accepted = 0.0, steps_rejected = 0.0;
  double tolerance_scale = 1.0;  ///< tolerances rtol·scale, atol·scale (a shadow run's below 1)
  LaneStatus status = LaneStatus::ok;
  ROTORSWEEP_HD bool stepping() const { return status == LaneStatus::ok && t < t_stop; }
};

/// AdaptiveIntegrator::attempt's decision for one member whose step of size h (clipped: to land on
/// s.t_stop) has the error norm `err`: whether it is accepted (finite err and `checksum`, the sum of the
/// new state and quadratures; every unstable direction resolved; err ≤ 1), then s's time, next step
/// size, counts and failure status, and `error_previous` for the PI controller. The caller takes the
/// new state where it returns true: AdaptiveSteps' decisions for one member, written out for a member in
/// registers (WarpIntegrator), whose vectors are no arrays to hand a form.
template <class State>
ROTORSWEEP_HD bool control_member_step(const StepLimits& limits, int embedded_order, double err, double checksum,
                                       bool resolved, double h, bool clipped, double& error_previous, State& s) {
  const bool finite = std::isfinite(err) && std::isfinite(checksum);
  const bool accept = finite && resolved && err <= 1.0;
  if (accept) s.t = clipped ? s.t_stop : s.t + h;
  double h_next = h * step_factor(limits, embedded_order, finite ? err : err + INFINITY, error_previous, accept);
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

/// AdaptiveSteps' form for one member on a team (TeamIntegrator): each rank its rows, the error norm's state
/// part, the checksum and a first step's rate from team sums (every rank decides alike), the rate through
/// the stepper's evaluate.
template <class Team, class Model>
class TeamMemberForm {
 public:
  using value_type = double;
  using State = TeamMemberState;
  struct Context {
    Team& team;
    const Model& model;
  };
  static constexpr std::size_t max_quadratures = Model::max_quadratures;
  static_assert(max_quadratures <= TeamMemberState::max_quadratures);

  ROTORSWEEP_HD TeamMemberForm(std::size_t n, LaneArena<double>&, const Model&, std::size_t ranks)
      : n_(n), ranks_(ranks) {}

  ROTORSWEEP_HD static const Model& model(Context c) { return c.model; }
  template <class Part>
  ROTORSWEEP_HD void rows(Context c, Part&& part) const {
    c.team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      part(rows.begin, rows.end);
    });
  }
  template <class Part>
  ROTORSWEEP_HD double sum(Context c, Part&& part) const {
    return c.team.sum([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      return part(rows.begin, rows.end);
    });
  }
  template <class Stepper, class... Arguments>
  ROTORSWEEP_HD bool step(Stepper& stepper, Context c, Arguments... arguments) const {
    return stepper.attempt(c.team, c.model, arguments...);
  }
  template <class Stepper>
  ROTORSWEEP_HD double first_rate(Context c, Stepper& stepper, const State& s, double*, double*) const {
    double qdot[max_quadratures] = {};
    stepper.evaluate(c.team, c.model, s.y, s.t, qdot);
    const double* f = stepper.rate();
    return c.team.max([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      double m = 1e-300;
      for (std::size_t k = rows.begin; k < rows.end; ++k) m = std::fabs(f[k]) > m ? std::fabs(f[k]) : m;
      return m;
    });
  }
  ROTORSWEEP_HD static LaneStatus& status(State& s, std::size_t) { return s.status; }

 private:
  std::size_t n_, ranks_;
};

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
                               Tolerances tol, StepLimits limits, double first_step_scale, LaneArena<double>& arena)
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
