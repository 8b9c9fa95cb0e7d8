// Overdamped Langevin dynamics of one member on a team of threads (docs/model.md §7, docs/architecture.md
// "Teams"): the Leimkuhler–Matthews scheme (LangevinSteps) over each rank's rows, the same noise per row.
#pragma once

#include <cstddef>
#include <cstdint>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/langevin_steps.hpp"
#include "kernels/steppers/team_member_form.hpp"
#include "kernels/steppers/team_model_concept.hpp"

namespace rotorsweep::kernels {

/// TeamMemberForm with the model's f from team_evaluate (LangevinSteps evaluates it itself).
template <class Team, class Model>
class TeamLangevinForm : public TeamMemberForm<Team, Model> {
 public:
  static_assert(TeamModel<Model, Team>, "a model's team header gives its team forms");
  using Context = typename TeamMemberForm<Team, Model>::Context;
  static constexpr double period = Model::period;
  static constexpr std::size_t partial_stride = 5;  ///< team_evaluate's values per rank

  ROTORSWEEP_HD TeamLangevinForm(std::size_t n, LaneArena<double>& arena, const Model& model,
                                 std::size_t ranks)
      : TeamMemberForm<Team, Model>(n, arena, model, ranks),
        work_(n, arena),
        partial_(arena.take(partial_stride * ranks)) {}

  ROTORSWEEP_HD void evaluate(Context c, const double* y, double t, double* f, double* qdot) {
    team_evaluate(c.team, c.model, work_, y, t, f, partial_, partial_stride, qdot);
  }

 private:
  typename Model::Workspace work_;
  double* partial_;  ///< per rank: its parts of the integrands' sums
};

/// LangevinSteps for one member of a row model on the double lane (NearestNeighbourRows or CoupledRows) on a
/// team: the lanes' steps and the same ξ of row j at step k, so the rows' path has the lanes' bits; only the
/// quadratures, left-point sums of the integrands, come from team sums in another order.
template <class Team, class RowModel>
class TeamLeimkuhlerMatthews : public LangevinSteps<TeamLangevinForm<Team, RowModel>> {
  using Steps = LangevinSteps<TeamLangevinForm<Team, RowModel>>;

 public:
  using Model = RowModel;
  using TeamType = Team;

  ROTORSWEEP_HD TeamLeimkuhlerMatthews(const Model& model, std::size_t ranks, LangevinSettings settings,
                                       LaneArena<double>& arena)
      : Steps(model.dimension(), settings, arena, model, ranks) {}

  /// A member starts: its noise stream key, its g and its curvature bound κ (LangevinSteps::start_lane).
  ROTORSWEEP_HD void start(std::uint64_t key, double g, double curvature) {
    Steps::start_lane(0, key, g, curvature);
  }
  /// The member's step (period / steps per period).
  ROTORSWEEP_HD double step_size() const { return Steps::step_size(0); }
  /// One step where the member steps; returns whether it took one (a non-finite step flags it).
  ROTORSWEEP_HD bool attempt(Team& team, const Model& model, TeamMemberState& s) {
    return Steps::attempt({team, model}, s);
  }
};

}  // namespace rotorsweep::kernels
