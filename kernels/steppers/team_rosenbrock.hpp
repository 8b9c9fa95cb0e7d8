// A Rosenbrock step (Hairer & Wanner Eq. IV.7.25, as RosenbrockStepper) of one member of a row model
// on a team of threads (docs/architecture.md "Teams"): vectors over each rank's rows.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"
#include "kernels/steppers/stage_combination.hpp"
#include "kernels/steppers/team_model_concept.hpp"

namespace rotorsweep::kernels {

/// The stages of RosenbrockStepper for a LinearizableTeamModel on the double lane (NearestNeighbourRows,
/// CoupledRows or the slider, with their team headers) on a team of `ranks`: each rank forms its rows'
/// arguments and right-hand sides and evaluates the model over them (team_evaluate), the team solves with the
/// model's TeamStageMatrix (TeamCyclicTridiagonal, TeamDenseSymmetric, TeamSecondOrderJacobian), and the
/// quadratures' stage values come from team sums (identical on every rank, so each may keep its own copy);
/// every quadrature the model carries (R, W, S, ρ̄, H, the moments; the slider's impulse and dissipation). The
/// tableau is data, as RosenbrockStepper's (combine_stages over each rank's rows). With the sums over the
/// team in butterfly order (and for nearest neighbours without evaluate_displaced), its bits differ from the
/// lanes' at rounding level (docs/numerics.md "The stage solve on a team").
template <class Team, class TeamModelType>
class TeamRosenbrock {
 public:
  using Model = TeamModelType;
  static_assert(LinearizableTeamModel<Model, Team>, "a model's team header gives its team forms");
  using Method = RosenbrockTableau;
  static constexpr int max_stages = RosenbrockTableau::max_stages;
  /// The most quadratures the model carries (the row models' 8, the slider's 2): the stage arrays' size,
  /// and the values per rank of the partial sums, which hold what its team_evaluate and team_linearize
  /// leave per rank (the rows 5 and 8, the slider 2 and 2).
  static constexpr std::size_t quadratures = Model::max_quadratures;

  /// `table` outlives the stepper (on a device: the kernel's parameters, read where they are).
  ROTORSWEEP_HD TeamRosenbrock(const Model& model, std::size_t ranks, const RosenbrockTableau& table,
                               LaneArena<double>& arena)
      : table_(&table),
        n_(model.dimension()),
        ranks_(ranks),
        carried_(model.quadrature_count()),
        work_(n_, arena),
        jacobian_(n_, ranks, arena),
        f_(arena.take(n_)),
        df_dt_(arena.take(n_)),
        argument_(arena.take(n_)),
        stages_(arena.take(std::size_t(table.stages) * n_)),
        dq_dy_(arena.take(carried_ * n_)),
        scratch_(arena.take(n_)),
        partial_(arena.take(quadratures * ranks)) {}

  ROTORSWEEP_HD int order() const { return table_->order; }
  ROTORSWEEP_HD int embedded_order() const { return table_->embedded_order; }
  ROTORSWEEP_HD std::size_t quadrature_count() const { return carried_; }

  /// One step of size h from (t, y, q) into y_new, q_new and the error estimates; returns whether it
  /// resolves every unstable direction (RosenbrockStepper::attempt). y and y_new are the team's.
  ROTORSWEEP_HD bool attempt(Team& team, const Model& model, double t, double h, const double* y,
                             const double* q, double* y_new, double* q_new, double* y_error,
                             double* q_error) {
    linearize(team, model, y, t);
    const Step step{t, h, h * table_->gamma, 1.0 / h};
    if constexpr (requires { model.strict_fm(0); }) jacobian_.keep_constant_solutions(model.strict_fm(0));
    jacobian_.factor(team, 1.0 / step.h_gamma);
    double quad_stages[max_stages][quadratures] = {};
    for (int i = 0; i < table_->stages; ++i) run_stage(team, model, step, y, quad_stages, i);
    combine(team, y, q, quad_stages, y_new, q_new, y_error, q_error);
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
  using Terms = StageTerms<double, max_stages>;
  struct Step {
    double t, h, h_gamma, inv_h;
  };

  /// combine_stages over each rank's rows.
  template <class Base>
  ROTORSWEEP_HD void each_combination(Team& team, const Terms& terms, Base&& base, double* out) const {
    team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      combine_stages(terms, base, out, rows.begin, rows.end);
    });
  }

  /// Stage i: f at y + Σ a_ij U_j, its right-hand side over each rank's rows, the team solve, and
  /// the quadratures' stage values from team sums.
  ROTORSWEEP_HD void run_stage(Team& team, const Model& model, const Step& s, const double* y,
                               double (&quad_stages)[max_stages][quadratures], int i) {
    if (i > 0) {
      Terms arguments;
      for (int j = 0; j < i; ++j)
        if (table_->a[i][j] != 0.0) arguments.add(table_->a[i][j], stage(j));
      each_combination(team, arguments, [&](std::size_t k) { return y[k]; }, argument_);
      evaluate(team, model, argument_, s.t + table_->alpha[i] * s.h, qdot_);
    }
    const double time_weight = table_->gamma_sum[i] * s.h;
    Terms earlier;  // c_ij / h U_j for every j < i
    for (int j = 0; j < i; ++j) earlier.add(table_->c[i][j] * s.inv_h, stage(j));
    double* u = stage(i);
    each_combination(team, earlier, [&](std::size_t k) { return f_[k] + time_weight * df_dt_[k]; }, u);
    jacobian_.solve(team, u);
    const double* integrands = i == 0 ? start_qdot_ : qdot_;
    for (std::size_t p = 0; p < quadrature_count(); ++p) {
      const double* gradient = dq_dy_ + p * n_;
      const double dot = team.sum([&](std::size_t r) {
        const TeamRows rows = team_rows(n_, ranks_, r);
        double partial = 0.0;
        for (std::size_t k = rows.begin; k < rows.end; ++k) partial += gradient[k] * u[k];
        return partial;
      });
      double sum = integrands[p] + time_weight * dq_dt_[p] + dot;
      for (int j = 0; j < i; ++j) sum += earlier.weight[j] * quad_stages[j][p];
      quad_stages[i][p] = s.h_gamma * sum;
    }
  }

  ROTORSWEEP_HD double* stage(int i) const { return stages_ + std::size_t(i) * n_; }

  /// y_new = y + Σ m_i U_i and y_error = Σ e_i U_i over each rank's rows (nonzero weights, in stage
  /// order); the quadratures' alike.
  ROTORSWEEP_HD void combine(Team& team, const double* y, const double* q,
                             const double (&quad_stages)[max_stages][quadratures], double* y_new, double* q_new,
                             double* y_error, double* q_error) const {
    Terms solution, estimate;
    for (int i = 0; i < table_->stages; ++i) {
      if (table_->m[i] != 0.0) solution.add(table_->m[i], stage(i));
      if (table_->e[i] != 0.0) estimate.add(table_->e[i], stage(i));
    }
    each_combination(team, solution, [&](std::size_t k) { return y[k]; }, y_new);
    each_combination(team, estimate, [](std::size_t) { return 0.0; }, y_error);
    for (std::size_t p = 0; p < quadrature_count(); ++p) {
      double sum = q[p], error = 0.0;
      for (int i = 0; i < table_->stages; ++i) {
        if (table_->m[i] != 0.0) sum = sum + table_->m[i] * quad_stages[i][p];
        if (table_->e[i] != 0.0) error = error + table_->e[i] * quad_stages[i][p];
      }
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

  const RosenbrockTableau* table_;  ///< outlives the stepper (a device reads it from its parameters)
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
