// The form of the adaptive and Langevin steps for one member on a team of threads (docs/architecture.md
// "Teams"): the member's state, each rank its rows, sums over the team in butterfly order.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/arena_storage.hpp"
#include "kernels/steppers/lane_status.hpp"

namespace rotorsweep::kernels {

/// One member's state on a team: θ, the team's array, and what every rank keeps alike (each its own
/// copy): the quadratures, time, step size, stopping time, counts and status.
struct TeamMemberState {
  /// The most quadratures a member on a team or a warp carries (the TeamModel concept checks a model's).
  static constexpr std::size_t max_quadratures = 8;
  double* y = nullptr;
  double quad[max_quadratures] = {};
  double t = 0.0, h = 0.0, t_stop = 0.0;  ///< h = 0 asks for an automatic first step
  double steps_accepted = 0.0, steps_rejected = 0.0;
  double tolerance_scale = 1.0;  ///< tolerances rtol·scale, atol·scale (a shadow run's below 1)
  LaneStatus status = LaneStatus::ok;
  ROTORSWEEP_HD bool stepping() const { return status == LaneStatus::ok && t < t_stop; }
};

/// AdaptiveSteps' form for one member on a team (TeamIntegrator): each rank its rows, the error norm's state
/// part, the checksum and a first step's rate from team sums (every rank decides alike), the rate through
/// the stepper's evaluate. TeamStageForm and TeamLangevinForm add what the Rosenbrock and Langevin steps
/// need.
template <class Team, class Model>
class TeamMemberForm : public ArenaStorage<double> {
 public:
  using value_type = double;
  using scalar_type = double;
  using State = TeamMemberState;
  struct Context {
    Team& team;
    const Model& model;
  };
  static constexpr std::size_t max_quadratures = Model::max_quadratures;
  static_assert(max_quadratures <= TeamMemberState::max_quadratures);

  ROTORSWEEP_HD TeamMemberForm(std::size_t n, LaneArena<double>&, std::size_t ranks) : n_(n), ranks_(ranks) {}
  ROTORSWEEP_HD TeamMemberForm(std::size_t n, LaneArena<double>& arena, const Model&, std::size_t ranks)
      : TeamMemberForm(n, arena, ranks) {}

  ROTORSWEEP_HD static const Model& model(Context c) { return c.model; }
  template <class Part>
  ROTORSWEEP_HD void rows(Context c, Part&& part) const {
    c.team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      part(rows.begin, rows.end);
    });
  }
  template <class Part>
  ROTORSWEEP_HD double sum(Context c, Part&& part) const {
    return c.team.sum([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      return part(rows.begin, rows.end);
    });
  }
  template <class Stepper, class... Arguments>
  ROTORSWEEP_HD bool step(Stepper& stepper, Context c, Arguments... arguments) const {
    return stepper.attempt(c.team, c.model, arguments...);
  }
  template <class Stepper>
  ROTORSWEEP_HD double first_rate(Context c, Stepper& stepper, const State& s, double*, double*) const {
    double qdot[max_quadratures] = {};
    stepper.evaluate(c.team, c.model, s.y, s.t, qdot);
    const double* f = stepper.rate();
    return c.team.max([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, ranks_, r);
      double m = 1e-300;
      for (std::size_t k = rows.begin; k < rows.end; ++k) m = std::fabs(f[k]) > m ? std::fabs(f[k]) : m;
      return m;
    });
  }
  ROTORSWEEP_HD static LaneStatus& status(State& s, std::size_t) { return s.status; }

 private:
  std::size_t n_, ranks_;
};

}  // namespace rotorsweep::kernels
