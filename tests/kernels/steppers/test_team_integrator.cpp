// One member integrated on a host team (kernels/steppers/team_integrator.hpp, team_rosenbrock.hpp)
// against the lanes' AdaptiveIntegrator: every quadrature (R, W, S, ρ̄, H, the moments) over two periods
// and the final angles of members in the AFM, CP and FM regimes agree within the integration error, for
// teams of 1 … 8 ranks. The rows' substrate
// strengths differ by 1e-6 (quenched disorder), so that in CP no rounding decides the slips
// (docs/regimes.md "Errors in CP, and symmetry-limited members").
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/lanes/team.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/models/rows/row_models_on_teams.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "kernels/steppers/team_integrator.hpp"
#include "kernels/steppers/team_rosenbrock.hpp"
#include "support/kernel_scratch.hpp"
#include "support/lanes_reference.hpp"

using namespace rotorsweep::kernels;
using Model = NearestNeighbourRows<double>;
using TeamStepper = TeamRosenbrock<HostTeam, NearestNeighbourRows<double>>;
using Lanes = AdaptiveIntegrator<Model, RosenbrockStepper<Model>>;
using Team = TeamIntegrator<HostTeam, TeamStepper>;

namespace {

constexpr Integrals every_integral = all_integrals;
using rotorsweep::testing::afm_start;
using rotorsweep::testing::TwoPeriods;
constexpr Tolerances tight = rotorsweep::testing::tight_tolerances;

TwoPeriods on_team(const Model& model, std::size_t n, std::size_t ranks) {
  const double scale = Lanes::first_step_scale(tight, rodas4p2_tableau);
  std::vector<double> storage(counted_storage<double>([&](LaneArena<double>& arena) {
    const Team counted(model, ranks, rodas4p2_tableau, tight, StepLimits{}, scale, arena);
  }));
  LaneArena<double> arena(storage.data(), storage.size());
  Team integrator(model, ranks, rodas4p2_tableau, tight, StepLimits{}, scale, arena);
  std::vector<double> theta = afm_start(n);
  TeamMemberState state;
  state.y = theta.data();
  state.t_stop = 2 * two_pi;
  HostTeam team(ranks);
  integrator.advance(team, model, state);
  REQUIRE(state.status == LaneStatus::ok);
  return {theta, std::vector<double>(state.quad, state.quad + 8),
          state.steps_accepted + state.steps_rejected};
}

}  // namespace

TEST_CASE("a member on a team of 1 … 8 ranks follows the lanes' integration", "[kernels][team][steppers]") {
  // blocks of 1 to 36 rows, split evenly and not (the team's stage solve alone: rings of 2 … 1024 rows)
  for (std::size_t n : {4u, 20u, 36u})
    for (double A : {2.0, 6.0, 12.0}) {  // AFM, CP (four slips per period), FM at g = 0.0011
      std::vector<double> disorder(n);
      for (std::size_t j = 0; j < n; ++j) disorder[j] = 1e-6 * std::sin(2.3 * double(j) + 0.4);
      Model::Parameters p{A, 0.0011};
      p.A_rows = disorder.data();
      const Model model = rotorsweep::testing::model<Model>(n, every_integral, p);
      bool ok = false;
      const TwoPeriods lanes = rotorsweep::testing::on_lanes(model, n, rodas4p2_tableau, ok);
      REQUIRE(ok);
      for (std::size_t ranks : {1u, 2u, 4u, 8u}) {
        if (ranks > n) continue;
        INFO("N = " << n << ", A = " << A << ", ranks = " << ranks << ": R " << lanes.quad[0] << ", steps "
                    << lanes.steps);
        const TwoPeriods team = on_team(model, n, ranks);
        for (std::size_t p = 0; p < 8; ++p) {
          INFO("quadrature " << p);
          CHECK(team.quad[p] == Approx(lanes.quad[p]).epsilon(1e-9).margin(1e-12));
        }
        double largest = 0;
        for (std::size_t j = 0; j < n; ++j)
          largest = std::max(largest, std::fabs(team.theta[j] - lanes.theta[j]));
        CHECK(largest < 1e-9);
        CHECK(team.steps == Approx(lanes.steps).epsilon(0.01));
      }
    }
}
