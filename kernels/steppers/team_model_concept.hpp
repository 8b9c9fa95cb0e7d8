// What the team steppers need of a model (docs/architecture.md "Teams"): the TeamModel concept, met by
// each model's team header (kernels/models/rows/row_models_on_teams.hpp, slider/slider_on_teams.hpp).
#pragma once

#include <concepts>
#include <cstddef>
#include <utility>

#include "kernels/steppers/team_member_form.hpp"

namespace rotorsweep::kernels {

/// The stage matrix of Model on a team of kind Team, given by the model's team header (a
/// specialization with `type`: TeamCyclicTridiagonal, TeamDenseSymmetric, TeamSecondOrderJacobian).
template <class Model, class Team>
struct TeamStageMatrixOf;
template <class Model, class Team>
using TeamStageMatrix = typename TeamStageMatrixOf<Model, Team>::type;

/// A model on the double lane that runs on a team, through functions of its team header that
/// argument-dependent lookup finds:
///   team_units(model)  the units its ranks split among them (team_rows): rows, or the slider's rotors
///   team_evaluate(team, model, work, y, t, f, partial, stride, qdot)  f(y, t), each rank its units,
///                      and the integrands from team sums of the ranks' parts (at partial + stride · rank)
/// Its quadratures fit the team's state (TeamMemberState::max_quadratures: every rank's copy).
template <class Model, class Team>
concept TeamModel = requires(Team& team, const Model& model, typename Model::Workspace& work, const double* y,
                             double* out, std::size_t stride, double t) {
  { team_units(model) } -> std::convertible_to<std::size_t>;
  team_evaluate(team, model, work, y, t, out, out, stride, out);
} && (Model::max_quadratures <= TeamMemberState::max_quadratures);

/// A TeamModel that a linearly implicit stepper can run: its TeamStageMatrix and
///   team_linearize(team, model, work, y, f, J, df_dt, scratch, dq_dy, partial, stride, t)  J into the
///                      stage matrix, ∂f/∂t and the carried integrands' gradients, after team_evaluate
template <class Model, class Team>
concept LinearizableTeamModel = TeamModel<Model, Team> &&
    requires(Team& team, const Model& model, const typename Model::Workspace& work, const double* y,
             double* out, TeamStageMatrix<Model, Team>& J, std::size_t stride, double t) {
  team_linearize(team, model, work, y, out, J, out, out, out, out, stride, t);
};

}  // namespace rotorsweep::kernels
