// A row model's linearization at one point on a team (docs/architecture.md "Teams"): J into the team's
// stage matrix, ∂f/∂t and the quadratures' integrand gradients (docs/model.md §3), each rank its rows.
#pragma once

#include <cstddef>
#include <utility>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/linear/team_cyclic_tridiagonal.hpp"
#include "kernels/linear/team_dense_symmetric.hpp"
#include "kernels/models/rows/coupled_rows.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"

namespace rotorsweep::kernels {

template <class Team>
TeamCyclicTridiagonal<Team> team_stage_matrix_of(const NearestNeighbourRows<double>&);
template <class Team>
TeamDenseSymmetric<Team> team_stage_matrix_of(const CoupledRows<double>&);

/// The stage matrix of Model on a team: the cyclic tridiagonal one of nearest-neighbour rows, the
/// dense symmetric one of a coupling table.
template <class Model, class Team>
using TeamStageMatrix = decltype(team_stage_matrix_of<Team>(std::declval<const Model&>()));

/// J, ∂f/∂t and the carried integrands' gradients dq_dy at time t, after team_evaluate there (f and the
/// workspace's trigonometry in place); each rank leaves its parts of the time sums at partial + stride ·
/// rank. Nearest neighbours: J's rows first, then the gradients (which read the next rank's link).
template <class Team>
ROTORSWEEP_HD void team_linearize(Team& team, const NearestNeighbourRows<double>& model,
                                  const NearestNeighbourRows<double>::Workspace& work, const double* f,
                                  TeamCyclicTridiagonal<Team>& J, double* df_dt, double* scratch, double* dq_dy,
                                  double* partial, std::size_t stride, double t) {
  const std::size_t n = model.dimension(), ranks = team.size();
  team.each([&](std::size_t r) {
    const TeamRows rows = team_rows(n, ranks, r);
    model.jacobian_range(work, J.diagonal(), J.links(), df_dt, rows.begin, rows.end);
  });
  team.each([&](std::size_t r) {
    const TeamRows rows = team_rows(n, ranks, r);
    model.integrand_gradient_range(work, f, J.diagonal(), J.links(), df_dt, scratch, dq_dy, partial + stride * r,
                                   t, rows.begin, rows.end);
  });
}

/// The same for a coupling table: a rank's gradients read only its own rows of J, so one phase.
template <class Team>
ROTORSWEEP_HD void team_linearize(Team& team, const CoupledRows<double>& model,
                                  const CoupledRows<double>::Workspace& work, const double* f,
                                  TeamDenseSymmetric<Team>& J, double* df_dt, double* scratch, double* dq_dy,
                                  double* partial, std::size_t stride, double t) {
  const std::size_t n = model.dimension(), ranks = team.size();
  team.each([&](std::size_t r) {
    const TeamRows rows = team_rows(n, ranks, r);
    model.jacobian_range(work, J, df_dt, rows.begin, rows.end);
    model.integrand_gradient_range(work, f, J, df_dt, scratch, dq_dy, partial + stride * r, t, rows.begin,
                                   rows.end);
  });
}

}  // namespace rotorsweep::kernels
