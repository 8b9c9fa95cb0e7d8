// A Rosenbrock step (Hairer & Wanner Eq. IV.7.25; its stages: RosenbrockStages) of one member of a model on
// a team of threads (docs/architecture.md "Teams"): vectors over each rank's rows, sums over the team.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/rosenbrock_stages.hpp"
#include "kernels/steppers/team_member_form.hpp"
#include "kernels/steppers/team_model_concept.hpp"

namespace rotorsweep::kernels {

/// RosenbrockStages' form for one member of a LinearizableTeamModel on the double lane (NearestNeighbourRows,
/// CoupledRows or the slider, with their team headers) on a team of `ranks`: each rank forms its rows'
/// vectors and evaluates the model over them (team_evaluate), the team solves with the model's
/// TeamStageMatrix (TeamCyclicTridiagonal, TeamDenseSymmetric, TeamSecondOrderJacobian), and the
/// quadratures' stage values come from team sums (identical on every rank, so each keeps its own copy). The
/// tableau is read where the caller keeps it (on a device: the kernel's parameters). With the sums over the
/// team in butterfly order (and for nearest neighbours without evaluate_displaced), its bits differ from the
/// lanes' at rounding level (docs/numerics.md "The stage solve on a team").
template <class Team, class Model>
class TeamStageForm : public TeamMemberForm<Team, Model> {
  using Base = TeamMemberForm<Team, Model>;

 public:
  static_assert(LinearizableTeamModel<Model, Team>, "a model's team header gives its team forms");
  using typename Base::Context;
  using resolved_type = bool;
  /// The partial sums per rank hold max_quadratures values (what team_evaluate and team_linearize leave).
  using Base::max_quadratures;
  static constexpr bool displaced = false;
  static constexpr bool copies_table = false;

  ROTORSWEEP_HD TeamStageForm(std::size_t n, LaneArena<double>& arena, std::size_t ranks)
      : Base(n, arena, ranks),
        work_(n, arena),
        jacobian_(n, ranks, arena),
        scratch_(arena.take(n)),
        partial_(arena.take(max_quadratures * ranks)) {}

  ROTORSWEEP_HD double add_dot(Context c, double running, const double* a, const double* b) const {
    return running + this->sum(c, [&](std::size_t begin, std::size_t end) {
      double partial = 0.0;
      for (std::size_t k = begin; k < end; ++k) partial += a[k] * b[k];
      return partial;
    });
  }
  ROTORSWEEP_HD void evaluate(Context c, const double* y, double t, double* f, double* qdot) {
    team_evaluate(c.team, c.model, work_, y, t, f, partial_, max_quadratures, qdot);
  }
  ROTORSWEEP_HD void evaluate_stage(Context c, const double*, const double* argument, double t, double tau,
                                    double* f, double* qdot) {
    evaluate(c, argument, t + tau, f, qdot);
  }
  ROTORSWEEP_HD void linearize(Context c, const double* y, double t, double* f, double* qdot, double* df_dt,
                               double* dq_dy, double* dq_dt) {
    evaluate(c, y, t, f, qdot);
    team_linearize(c.team, c.model, work_, y, f, jacobian_, df_dt, scratch_, dq_dy, partial_, max_quadratures,
                   t);
    double time_sums[max_quadratures] = {};
    for (std::size_t p = 0; p < c.model.quadrature_count(); ++p)
      time_sums[p] = c.team.sum([&](std::size_t r) { return partial_[max_quadratures * r + p]; });
    c.model.team_time_derivatives(time_sums, t, qdot, dq_dt);
  }
  ROTORSWEEP_HD void factor(Context c, double shift) {
    if constexpr (requires { c.model.strict_fm(0); }) jacobian_.keep_constant_solutions(c.model.strict_fm(0));
    jacobian_.factor(c.team, shift);
  }
  ROTORSWEEP_HD void solve(Context c, double* u) { jacobian_.solve(c.team, u); }
  ROTORSWEEP_HD bool resolved(double) const { return jacobian_.positive_definite(); }

 private:
  typename Model::Workspace work_;
  TeamStageMatrix<Model, Team> jacobian_;
  double* scratch_;  ///< J x for the gradients
  double* partial_;  ///< per rank: its parts of sums (max_quadratures values each)
};

/// One member's Rosenbrock step on a team (RosenbrockStages::attempt with the team and the model).
template <class Team, class TeamModelType>
class TeamRosenbrock : public RosenbrockStages<TeamStageForm<Team, TeamModelType>> {
  using Stages = RosenbrockStages<TeamStageForm<Team, TeamModelType>>;

 public:
  using Model = TeamModelType;

  /// `table` outlives the stepper (on a device: the kernel's parameters, read where they are).
  ROTORSWEEP_HD TeamRosenbrock(const Model& model, std::size_t ranks, const RosenbrockTableau& table,
                               LaneArena<double>& arena)
      : Stages(model.dimension(), model.quadrature_count(), table, arena, ranks) {}

  /// One step of size h from (t, y, q); y and y_new are the team's (RosenbrockStages::attempt).
  ROTORSWEEP_HD bool attempt(Team& team, const Model& model, double t, double h, const double* y,
                             const double* q, double* y_new, double* q_new, double* y_error,
                             double* q_error) {
    return Stages::attempt({team, model}, t, h, y, q, y_new, q_new, y_error, q_error);
  }
  /// f at (y, t) over the team (rate()), with the quadratures' integrands (the first step's rate).
  ROTORSWEEP_HD void evaluate(Team& team, const Model& model, const double* y, double t, double* qdot) {
    Stages::evaluate({team, model}, y, t, qdot);
  }
};

}  // namespace rotorsweep::kernels
