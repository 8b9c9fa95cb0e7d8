// Overdamped Langevin dynamics of one member on a team of threads (docs/model.md §7, docs/architecture.md
// "Teams"): LeimkuhlerMatthews's step over each rank's rows, with the same noise per row and step.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "kernels/lanes/counter_random.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/lane_status.hpp"
#include "kernels/steppers/leimkuhler_matthews.hpp"
#include "kernels/steppers/team_integrator.hpp"
#include "kernels/steppers/team_model_concept.hpp"

namespace rotorsweep::kernels {

/// LeimkuhlerMatthews::attempt for one member of a row model on the double lane (NearestNeighbourRows
/// or CoupledRows) on a team: the same steps (evened out to land on t_stop), the same ξ of row j at
/// step k (normal number k N + j of the member's stream), so the rows' path has the lanes' bits; only
/// the quadratures, left-point sums of the integrands, come from team sums in another order.
template <class Team, class RowModel>
class TeamLeimkuhlerMatthews {
 public:
  using Model = RowModel;
  static_assert(TeamModel<Model, Team>, "a model's team header gives its team forms");
  using TeamType = Team;
  using Settings = typename LeimkuhlerMatthews<Model>::Settings;
  static constexpr bool stochastic = true;
  static constexpr std::size_t partial_stride = 5;  ///< team_evaluate's values per rank

  ROTORSWEEP_HD TeamLeimkuhlerMatthews(const Model& model, std::size_t ranks, Settings settings,
                                       LaneArena<double>& arena)
      : settings_(settings),
        n_(model.dimension()),
        ranks_(ranks),
        work_(n_, arena),
        f_(arena.take(n_)),
        xi_next_(arena.take(n_)),
        partial_(arena.take(partial_stride * ranks)) {}

  /// A member starts: its noise stream key, its g (the noise amplitude is √(2T/g)) and its
  /// curvature bound κ (the step), as LeimkuhlerMatthews::start_lane.
  ROTORSWEEP_HD void start(std::uint64_t key, double g, double curvature) {
    key_ = key;
    drawn_ = false;
    amplitude_ = std::sqrt(2.0 * settings_.temperature / g);
    h_nominal_ = Model::period / LeimkuhlerMatthews<Model>::steps_for(settings_, g, curvature);
  }

  /// The member's step (period / steps per period).
  ROTORSWEEP_HD double step_size() const { return h_nominal_; }

  /// One step where the member steps; returns whether it took one (a non-finite step flags it).
  ROTORSWEEP_HD bool attempt(Team& team, const Model& model, TeamMemberState& s) {
    if (!s.stepping()) return false;
    const double remaining = s.t_stop - s.t;
    const double rounded = lane_round(remaining / h_nominal_ + 0.25);
    const double steps_left = rounded > 1.0 ? rounded : 1.0;
    const double h = remaining / steps_left;
    s.h = h;
    team_evaluate(team, model, work_, s.y, s.t, f_, partial_, partial_stride, qdot_);
    // Δ = h f + amplitude √h (ξ_n + ξ_{n+1}) / 2
    const double noise_factor = 0.5 * amplitude_ * std::sqrt(h);
    const RandomStream stream = RandomStream::from_key(key_);
    const std::uint64_t step = std::uint64_t(s.steps_accepted);
    const double checksum = team.sum([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      double sum = 0.0;
      for (std::size_t j = rows.begin; j < rows.end; ++j) {
        const double xi_now = drawn_ ? xi_next_[j] : stream.normal(step * n_ + j);
        xi_next_[j] = stream.normal((step + 1) * n_ + j);
        f_[j] = h * f_[j] + noise_factor * (xi_now + xi_next_[j]);
        sum += f_[j];
      }
      return sum;
    });
    if (!std::isfinite(checksum)) {
      s.status = LaneStatus::non_finite;
      return false;
    }
    team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      for (std::size_t j = rows.begin; j < rows.end; ++j) s.y[j] = s.y[j] + f_[j];
    });
    for (std::size_t p = 0; p < model.quadrature_count(); ++p) s.quad[p] = s.quad[p] + h * qdot_[p];
    s.t = steps_left <= 1.0 ? s.t_stop : s.t + h;
    s.steps_accepted += 1.0;
    drawn_ = true;
    return true;
  }

  /// The quadratures' integrands at the start of the last step.
  ROTORSWEEP_HD const double* start_integrands() const { return qdot_; }

 private:
  Settings settings_;
  std::size_t n_, ranks_;
  typename Model::Workspace work_;
  double *f_, *xi_next_;
  double* partial_;  ///< per rank: its parts of the integrands' sums
  double qdot_[TeamMemberState::max_quadratures] = {};
  std::uint64_t key_ = 0;
  bool drawn_ = false;  ///< xi_next_ holds the member's ξ of its next step
  double amplitude_ = 0.0, h_nominal_ = 1.0;
};

}  // namespace rotorsweep::kernels
