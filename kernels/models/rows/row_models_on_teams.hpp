// The row models on a team (docs/architecture.md "Teams"): NearestNeighbourRows and CoupledRows on the
// double lane as TeamModels — f, the integrands and J (docs/model.md §3) over each rank's rows.
#pragma once

#include <cstddef>
#include <type_traits>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/linear/team_cyclic_tridiagonal.hpp"
#include "kernels/linear/team_dense_symmetric.hpp"
#include "kernels/models/rows/coupled_rows.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/team_model_concept.hpp"

namespace rotorsweep::kernels {

/// A row model that runs on a team.
template <class Model>
concept RowModelOnTeams =
    std::is_same_v<Model, NearestNeighbourRows<double>> || std::is_same_v<Model, CoupledRows<double>>;

template <class Team>
struct TeamStageMatrixOf<NearestNeighbourRows<double>, Team> {
  using type = TeamCyclicTridiagonal<Team>;
};
template <class Team>
struct TeamStageMatrixOf<CoupledRows<double>, Team> {
  using type = TeamDenseSymmetric<Team>;
};

/// A team splits a row model's rows.
template <RowModelOnTeams Model>
ROTORSWEEP_HD std::size_t team_units(const Model& model) {
  return model.dimension();
}

/// Whether Model's range forms read the trigonometry of other ranks' rows, which a phase of its own
/// puts in place first (CoupledRows: a row's pairs reach across the row), rather than taking their
/// neighbours' themselves (NearestNeighbourRows).
template <class Model>
concept TrigonometryFirst = requires(const Model& model, typename Model::Workspace& work, const double* y) {
  model.trigonometry_range(work, y, 0.0, std::size_t(0), std::size_t(0));
};

/// Each rank's rows' trigonometry at (y, t) where Model's range forms read it across ranks; nothing
/// (and no barrier) otherwise.
template <class Team, RowModelOnTeams Model>
ROTORSWEEP_HD void team_trigonometry(Team& team, const Model& model, typename Model::Workspace& work,
                                     const double* y, double t) {
  if constexpr (TrigonometryFirst<Model>)
    team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(model.dimension(), team.size(), r);
      model.trigonometry_range(work, y, t, rows.begin, rows.end);
    });
}

/// f(y, t) into f, each rank its rows (evaluate_range), and the integrands into qdot from the team's
/// sums of the ranks' parts, which each rank leaves at partial + stride · rank (5 values).
template <class Team, RowModelOnTeams Model>
ROTORSWEEP_HD void team_evaluate(Team& team, const Model& model, typename Model::Workspace& work,
                                 const double* y, double t, double* f, double* partial, std::size_t stride,
                                 double* qdot) {
  const std::size_t n = model.dimension(), ranks = team.size();
  team_trigonometry(team, model, work, y, t);
  team.each([&](std::size_t r) {
    const TeamRows rows = team_rows(n, ranks, r);
    const typename Model::RowSums sums = model.evaluate_range(work, y, t, f, rows.begin, rows.end);
    const typename Model::IntegrandSums more = model.integrand_sums_range(work, f, rows.begin, rows.end);
    double* mine = partial + stride * r;
    mine[0] = sums.lag;
    mine[1] = sums.cos_link;
    mine[2] = more.lag_force;
    mine[3] = more.force_squares;
    mine[4] = more.energy;
  });
  const auto total = [&](std::size_t i) {
    return team.sum([&](std::size_t r) { return partial[stride * r + i]; });
  };
  typename Model::RowSums sums;
  sums.lag = total(0);
  sums.cos_link = total(1);
  typename Model::IntegrandSums more;
  more.lag_force = total(2);
  more.force_squares = total(3);
  more.energy = total(4);
  model.team_integrands(sums, more, t, qdot);
}

/// J, ∂f/∂t and the carried integrands' gradients dq_dy at time t, after team_evaluate there (f and the
/// workspace's trigonometry in place); each rank leaves its parts of the time sums at partial + stride ·
/// rank. Nearest neighbours take J's rows first and the gradients in a phase of their own (they read
/// the previous rank's link).
template <class Team>
ROTORSWEEP_HD void team_linearize(Team& team, const NearestNeighbourRows<double>& model,
                                  const NearestNeighbourRows<double>::Workspace& work, const double*,
                                  const double* f, TeamCyclicTridiagonal<Team>& J, double* df_dt,
                                  double* scratch, double* dq_dy, double* partial, std::size_t stride,
                                  double t) {
  team.each([&](std::size_t r) {
    const TeamRows rows = team_rows(model.dimension(), team.size(), r);
    model.jacobian_range(work, J.diagonal(), J.links(), df_dt, rows.begin, rows.end);
  });
  team.each([&](std::size_t r) {
    const TeamRows rows = team_rows(model.dimension(), team.size(), r);
    model.integrand_gradient_range(work, f, J.diagonal(), J.links(), df_dt, scratch, dq_dy,
                                   partial + stride * r, t, rows.begin, rows.end);
  });
}

/// The same with a coupling table: a rank's gradients read only its own rows of J.
template <class Team>
ROTORSWEEP_HD void team_linearize(Team& team, const CoupledRows<double>& model,
                                  const CoupledRows<double>::Workspace& work, const double*, const double* f,
                                  TeamDenseSymmetric<Team>& J, double* df_dt, double* scratch, double* dq_dy,
                                  double* partial, std::size_t stride, double t) {
  team.each([&](std::size_t r) {
    const TeamRows rows = team_rows(model.dimension(), team.size(), r);
    model.jacobian_range(work, J, df_dt, rows.begin, rows.end);
    model.integrand_gradient_range(work, f, J, df_dt, scratch, dq_dy, partial + stride * r, t, rows.begin,
                                   rows.end);
  });
}

}  // namespace rotorsweep::kernels
