// A Rosenbrock step (Hairer & Wanner Eq. IV.7.25, as RosenbrockStepper) of one member of a row model
// on a team of threads (docs/architecture.md "Teams"): vectors over each rank's rows.
#pragma once

#include <cstddef>
#include <utility>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"
#include "kernels/steppers/team_evaluation.hpp"
#include "kernels/steppers/team_linearization.hpp"

namespace rotorsweep::kernels {

/// The stages of RosenbrockStepper for a model on the double lane (NearestNeighbourRows, CoupledRows
/// or the slider) on a team of `ranks`: each rank forms its rows' arguments and right-hand sides and
/// evaluates the model over them (team_evaluate), the team solves with the model's TeamStageMatrix
/// (TeamCyclicTridiagonal, TeamDenseSymmetric, TeamSecondOrderJacobian), and the quadratures' stage
/// values come from team sums (identical on every rank, so each may keep its own copy); every
/// quadrature the model carries (R, W, S, ρ̄, H, the moments; the slider's impulse and dissipation).
/// With the sums over the team in butterfly order (and for nearest neighbours without
/// evaluate_displaced), its bits differ from the lanes' at rounding level (docs/numerics.md "The stage
/// solve on a team").
template <class Team, const RosenbrockTableau& Table, class TeamModel = NearestNeighbourRows<double>>
class TeamRosenbrock {
 public:
  using Model = TeamModel;
  static constexpr int stages = Table.stages;
  static constexpr std::size_t quadratures = Integrals::max_count;  ///< at most

  ROTORSWEEP_HD TeamRosenbrock(const Model& model, std::size_t ranks, LaneArena<double>& arena)
      : n_(model.dimension()),
        ranks_(ranks),
        carried_(model.quadrature_count()),
        work_(n_, arena),
        jacobian_(n_, ranks, arena),
        f_(arena.take(n_)),
        df_dt_(arena.take(n_)),
        argument_(arena.take(n_)),
        stages_(arena.take(std::size_t(stages) * n_)),
        dq_dy_(arena.take(carried_ * n_)),
        scratch_(arena.take(n_)),
        partial_(arena.take(quadratures * ranks)) {}

  ROTORSWEEP_HD static constexpr int order() { return Table.order; }
  ROTORSWEEP_HD static constexpr int embedded_order() { return Table.embedded_order; }
  ROTORSWEEP_HD std::size_t quadrature_count() const { return carried_; }

  /// One step of size h from (t, y, q) into y_new, q_new and the error estimates; returns whether it
  /// resolves every unstable direction (RosenbrockStepper::attempt). y and y_new are the team's.
  ROTORSWEEP_HD bool attempt(Team& team, const Model& model, double t, double h, const double* y,
                             const double* q, double* y_new, double* q_new, double* y_error,
                             double* q_error) {
    linearize(team, model, y, t);
    const Step step{t, h, h * Table.gamma, 1.0 / h};
    if constexpr (requires { model.strict_fm(0); }) jacobian_.keep_constant_solutions(model.strict_fm(0));
    jacobian_.factor(team, 1.0 / step.h_gamma);
    double quad_stages[stages][quadratures] = {};
    run_stages(team, model, step, y, quad_stages, std::make_integer_sequence<int, stages>{});
    combine(team, y, q, quad_stages, y_new, q_new, y_error, q_error,
            std::make_integer_sequence<int, stages>{});
    return jacobian_.positive_definite();
  }

  /// The quadratures' integrands at the start of the last attempt.
  ROTORSWEEP_HD const double* start_integrands() const { return start_qdot_; }

  /// f at (y, t) into `f` over the team, with the quadratures' integrands (the first step's rate).
  ROTORSWEEP_HD void evaluate(Team& team, const Model& model, const double* y, double t, double* qdot) {
    team_evaluate(team, model, work_, y, t, f_, partial_, quadratures, qdot);
  }
  /// f of the last evaluate (the team's).
  ROTORSWEEP_HD const double* rate() const { return f_; }

 private:
  // The stages unrolled at compile time, as RosenbrockStepper's: every coefficient is a literal (a
  // device reads no table), zero ones cost nothing, and the additions come in the same order.
  struct Step {
    double t, h, h_gamma, inv_h;
  };

  template <int... I>
  ROTORSWEEP_HD void run_stages(Team& team, const Model& model, const Step& s, const double* y,
                                double (&quad_stages)[stages][quadratures],
                                std::integer_sequence<int, I...>) {
    (run_stage<I>(team, model, s, y, quad_stages, std::make_integer_sequence<int, I>{}), ...);
  }

  /// Stage I: f at y + Σ a_IJ U_J, its right-hand side over each rank's rows, the team solve, and
  /// the quadratures' stage values from team sums.
  template <int I, int... J>
  ROTORSWEEP_HD void run_stage(Team& team, const Model& model, const Step& s, const double* y,
                               double (&quad_stages)[stages][quadratures], std::integer_sequence<int, J...>) {
    if constexpr (I > 0) {
      team.each([&](std::size_t r) {
        const TeamRows rows = team_rows(n_, ranks_, r);
        for (std::size_t k = rows.begin; k < rows.end; ++k) {
          double sum = y[k];
          ((sum = add_term<Table.a[I][J]>(sum, stages_[std::size_t(J) * n_ + k])), ...);
          argument_[k] = sum;
        }
      });
      constexpr double alpha = Table.alpha[I];
      evaluate(team, model, argument_, s.t + alpha * s.h, qdot_);
    }
    constexpr double gamma_sum = Table.gamma_sum[I];
    const double time_weight = gamma_sum * s.h;
    [[maybe_unused]] const double weight[sizeof...(J) + 1] = {Table.c[I][J] * s.inv_h..., 0.0};
    double* u = stages_ + std::size_t(I) * n_;
    team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      for (std::size_t k = rows.begin; k < rows.end; ++k) {
        double sum = f_[k] + time_weight * df_dt_[k];
        ((sum += weight[J] * stages_[std::size_t(J) * n_ + k]), ...);
        u[k] = sum;
      }
    });
    jacobian_.solve(team, u);
    const double* integrands = I == 0 ? start_qdot_ : qdot_;
    for (std::size_t p = 0; p < quadrature_count(); ++p) {
      const double* gradient = dq_dy_ + p * n_;
      const double dot = team.sum([&](std::size_t r) {
        const TeamRows rows = team_rows(n_, ranks_, r);
        double partial = 0.0;
        for (std::size_t k = rows.begin; k < rows.end; ++k) partial += gradient[k] * u[k];
        return partial;
      });
      double sum = integrands[p] + time_weight * dq_dt_[p] + dot;
      ((sum += weight[J] * quad_stages[J][p]), ...);
      quad_stages[I][p] = s.h_gamma * sum;
    }
  }

  /// sum + c·u, or sum where c = 0.
  template <double c>
  ROTORSWEEP_HD static double add_term(double sum, double u) {
    if constexpr (c == 0.0)
      return sum;
    else
      return sum + c * u;
  }

  /// y_new = y + Σ m_I U_I and y_error = Σ e_I U_I over each rank's rows; the quadratures' alike.
  template <int... I>
  ROTORSWEEP_HD void combine(Team& team, const double* y, const double* q,
                             const double (&quad_stages)[stages][quadratures], double* y_new, double* q_new,
                             double* y_error, double* q_error, std::integer_sequence<int, I...>) {
    team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      for (std::size_t k = rows.begin; k < rows.end; ++k) {
        double sum = y[k], error = 0.0;
        ((sum = add_term<Table.m[I]>(sum, stages_[std::size_t(I) * n_ + k]),
          error = add_term<Table.e[I]>(error, stages_[std::size_t(I) * n_ + k])),
         ...);
        y_new[k] = sum;
        y_error[k] = error;
      }
    });
    for (std::size_t p = 0; p < quadrature_count(); ++p) {
      double sum = q[p], error = 0.0;
      ((sum = add_term<Table.m[I]>(sum, quad_stages[I][p]),
        error = add_term<Table.e[I]>(error, quad_stages[I][p])),
       ...);
      q_new[p] = sum;
      q_error[p] = error;
    }
  }

  /// f, the integrands, J, ∂f/∂t and the integrands' gradients at (y, t).
  ROTORSWEEP_HD void linearize(Team& team, const Model& model, const double* y, double t) {
    evaluate(team, model, y, t, start_qdot_);
    team_linearize(team, model, work_, y, f_, jacobian_, df_dt_, scratch_, dq_dy_, partial_, quadratures, t);
    double time_sums[quadratures] = {};
    for (std::size_t p = 0; p < carried_; ++p)
      time_sums[p] = team.sum([&](std::size_t r) { return partial_[quadratures * r + p]; });
    model.team_time_derivatives(time_sums, t, start_qdot_, dq_dt_);
  }

  std::size_t n_, ranks_;
  std::size_t carried_;  ///< the model's quadratures
  typename Model::Workspace work_;
  TeamStageMatrix<Model, Team> jacobian_;
  double *f_, *df_dt_, *argument_, *stages_;
  double* dq_dy_;    ///< ∂q̇_p/∂θ_k at [p·N + k]
  double* scratch_;  ///< J x for the gradients
  double* partial_;  ///< per rank: its parts of sums (quadratures values each)
  // the quadratures' integrands and ∂/∂t: team sums, the same on every rank (each keeps its own)
  double start_qdot_[quadratures] = {}, qdot_[quadratures] = {}, dq_dt_[quadratures] = {};
};

}  // namespace rotorsweep::kernels
