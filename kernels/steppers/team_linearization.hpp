// A model's linearization at one point on a team (docs/architecture.md "Teams"): J into the team's
// stage matrix, ∂f/∂t and the quadratures' gradients (docs/model.md §3, §9), each rank its rows or rotors.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/linear/team_cyclic_tridiagonal.hpp"
#include "kernels/linear/team_dense_symmetric.hpp"
#include "kernels/linear/team_second_order_jacobian.hpp"
#include "kernels/models/rows/coupled_rows.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/steppers/team_evaluation.hpp"

namespace rotorsweep::kernels {

template <class Team>
TeamCyclicTridiagonal<Team> team_stage_matrix_of(const NearestNeighbourRows<double>&);
template <class Team>
TeamDenseSymmetric<Team> team_stage_matrix_of(const CoupledRows<double>&);
template <class Team, bool Inertial>
TeamSecondOrderJacobian<Team, Inertial> team_stage_matrix_of(const SliderModel<double, Inertial>&);

/// The stage matrix of Model on a team: the cyclic tridiagonal one of nearest-neighbour rows, the
/// dense symmetric one of a coupling table, the slider's reduced one.
template <class Model, class Team>
using TeamStageMatrix = decltype(team_stage_matrix_of<Team>(std::declval<const Model&>()));

/// J, ∂f/∂t and the carried integrands' gradients dq_dy at time t, after team_evaluate there (f and the
/// workspace's trigonometry in place); each rank leaves its parts of the time sums at partial + stride ·
/// rank. Nearest neighbours take J's rows first and the gradients in a phase of their own (they read
/// the previous rank's link); with a coupling table, and for the slider (K's rows, its gradients from
/// its own row of K), a rank's gradients read only its own rows of J.
template <class Team, class Model>
ROTORSWEEP_HD void team_linearize(Team& team, const Model& model, const typename Model::Workspace& work,
                                  const double* y, const double* f, TeamStageMatrix<Model, Team>& J,
                                  double* df_dt, double* scratch, double* dq_dy, double* partial,
                                  std::size_t stride, double t) {
  const auto each_rank = [&](auto&& part) {
    team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(team_units(model), team.size(), r);
      part(rows.begin, rows.end, partial + stride * r);
    });
  };
  if constexpr (team_slider_model<Model>) {
    each_rank([&](std::size_t begin, std::size_t end, double* sums) {
      model.jacobian_range(work, y, t, J, df_dt, dq_dy, sums, begin, end);
    });
  } else if constexpr (std::is_same_v<Model, NearestNeighbourRows<double>>) {
    each_rank([&](std::size_t begin, std::size_t end, double*) {
      model.jacobian_range(work, J.diagonal(), J.links(), df_dt, begin, end);
    });
    each_rank([&](std::size_t begin, std::size_t end, double* sums) {
      model.integrand_gradient_range(work, f, J.diagonal(), J.links(), df_dt, scratch, dq_dy, sums, t, begin,
                                     end);
    });
  } else {
    each_rank([&](std::size_t begin, std::size_t end, double* sums) {
      model.jacobian_range(work, J, df_dt, begin, end);
      model.integrand_gradient_range(work, f, J, df_dt, scratch, dq_dy, sums, t, begin, end);
    });
  }
}

}  // namespace rotorsweep::kernels
