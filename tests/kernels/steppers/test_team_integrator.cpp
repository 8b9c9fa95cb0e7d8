// One member integrated on a host team (kernels/steppers/team_integrator.hpp, team_rosenbrock.hpp)
// against the lanes' AdaptiveIntegrator: every quadrature (R, W, S, ρ̄, H, the moments) over two periods
// and the final angles of members in the AFM, CP and FM regimes agree within the integration error, for
// teams of 1 … 8 ranks. The rows' substrate
// strengths differ by 1e-6 (quenched disorder), so that in CP no rounding decides the slips
// (docs/regimes.md "Errors in CP, and symmetry-limited members").
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "support/kernel_scratch.hpp"
#include "support/lanes_reference.hpp"
#include "support/member_forms.hpp"

TEST_CASE("a member on a team of 1 … 8 ranks follows the lanes' integration", "[kernels][team][steppers]") {
  using namespace rotorsweep::kernels;
  using Model = NearestNeighbourRows<double>;
  using rotorsweep::testing::TwoPeriods;
  // blocks of 1 to 36 rows, split evenly and not (the team's stage solve alone: rings of 2 … 1024 rows)
  for (std::size_t n : {4u, 20u, 36u})
    for (double A : {2.0, 6.0, 12.0}) {  // AFM, CP (four slips per period), FM at g = 0.0011
      std::vector<double> disorder(n);
      for (std::size_t j = 0; j < n; ++j) disorder[j] = 1e-6 * std::sin(2.3 * double(j) + 0.4);
      Model::Parameters p{A, 0.0011};
      p.A_rows = disorder.data();
      const Model model = rotorsweep::testing::model<Model>(n, all_integrals, p);
      bool ok = false;
      const TwoPeriods lanes = rotorsweep::testing::on_lanes(model, n, rodas4p2_tableau, ok);
      REQUIRE(ok);
      for (std::size_t ranks : {1u, 2u, 4u, 8u}) {
        if (ranks > n) continue;
        INFO("N = " << n << ", A = " << A << ", ranks = " << ranks << ": R " << lanes.quad[0] << ", steps "
                    << lanes.steps);
        rotorsweep::testing::check_follows_lanes(
            rotorsweep::testing::on_team(model, n, ranks, rodas4p2_tableau), lanes, 1e-9);
      }
    }
}
