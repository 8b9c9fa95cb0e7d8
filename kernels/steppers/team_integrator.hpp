// Adaptive integration of one member on a team of threads (docs/architecture.md "Teams"): the step
// control of AdaptiveIntegrator for one lane, its error norm summed over the ranks' rows.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
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
/// new state where it returns true. Every member driver that decides alike on all its threads (a team,
/// a member in registers) takes its decisions here.
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

/// AdaptiveIntegrator::attempt for one member on a team with a team stepper (TeamRosenbrock): the
/// same proposal of the first step, error norm (its state part a team sum), acceptance, step-size
/// control and failure flags, decided alike on every rank from team sums.
template <class Team, class Stepper>
class TeamIntegrator {
 public:
  using Model = typename Stepper::Model;
  using TeamType = Team;
  static constexpr bool stochastic = false;

  using Method = typename Stepper::Method;  ///< the stepper's tableau
  static_assert(Stepper::quadratures <= TeamMemberState::max_quadratures);

  ROTORSWEEP_HD TeamIntegrator(const Model& model, std::size_t ranks, const Method& method, Tolerances tol,
                               StepLimits limits, double first_step_scale, LaneArena<double>& arena)
      : n_(model.dimension()),
        ranks_(ranks),
        tol_(tol),
        limits_(limits),
        first_step_scale_(first_step_scale),
        stepper_(model, ranks, method, arena),
        y_new_(arena.take(n_)),
        y_error_(arena.take(n_)) {}

  /// One step attempt, clipped to land on t_stop, where the member steps; returns whether it
  /// accepted one.
  ROTORSWEEP_HD bool attempt(Team& team, const Model& model, TeamMemberState& s) {
    if (!s.stepping()) return false;
    if (s.h <= 0.0) propose_first_step(team, model, s);
    const double remaining = s.t_stop - s.t;
    const bool clipped = s.h >= remaining;
    const double h = s.h < remaining ? s.h : remaining;
    double q_new[Stepper::quadratures] = {}, q_error[Stepper::quadratures] = {};
    const bool resolved =
        stepper_.attempt(team, model, s.t, h, s.y, s.quad, y_new_, q_new, y_error_, q_error);
    const double squares = team.sum([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      return state_error_squares(model, tol_, s.y, y_new_, y_error_, rows.begin, rows.end);
    });
    const double err =
        quadrature_error_norm(model, tol_, squares, s.quad, q_new, q_error) / s.tolerance_scale;
    const std::size_t carried = stepper_.quadrature_count();
    double checksum = team.sum([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      double sum = 0.0;
      for (std::size_t k = rows.begin; k < rows.end; ++k) sum += y_new_[k];
      return sum;
    });
    for (std::size_t p = 0; p < carried; ++p) checksum += q_new[p];
    const bool accept = control_member_step(limits_, stepper_.embedded_order(), err, checksum, resolved, h,
                                            clipped, error_previous_, s);
    if (accept) {
      team.each([&](std::size_t r) {
        const TeamRows rows = team_rows(n_, ranks_, r);
        for (std::size_t k = rows.begin; k < rows.end; ++k) s.y[k] = y_new_[k];
      });
      for (std::size_t p = 0; p < carried; ++p) s.quad[p] = q_new[p];
    }
    return accept;
  }

  /// Attempts steps until the member reaches its t_stop or fails.
  ROTORSWEEP_HD void advance(Team& team, const Model& model, TeamMemberState& s) {
    while (s.stepping()) attempt(team, model, s);
  }

  /// The quadratures' integrands at the start of the last attempt.
  ROTORSWEEP_HD const double* start_integrands() const { return stepper_.start_integrands(); }

 private:
  /// h = min(h_max, first_step_scale / max_j |f_j|), and no previous error (AdaptiveIntegrator's).
  ROTORSWEEP_HD void propose_first_step(Team& team, const Model& model, TeamMemberState& s) {
    error_previous_ = 1.0;
    double qdot[Stepper::quadratures] = {};
    stepper_.evaluate(team, model, s.y, s.t, qdot);
    const double* f = stepper_.rate();
    double rate = team.max([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      double m = 1e-300;
      for (std::size_t k = rows.begin; k < rows.end; ++k) m = std::fabs(f[k]) > m ? std::fabs(f[k]) : m;
      return m;
    });
    const double h0 = first_step_scale_ / rate < limits_.h_max ? first_step_scale_ / rate : limits_.h_max;
    s.h = std::isfinite(h0) ? h0 : limits_.h_max;
  }

  std::size_t n_, ranks_;
  Tolerances tol_;
  StepLimits limits_;
  double first_step_scale_;
  double error_previous_ = 1.0;  ///< the last accepted step's error (PI controller); alike on every rank
  Stepper stepper_;
  double *y_new_, *y_error_;
};

}  // namespace rotorsweep::kernels
