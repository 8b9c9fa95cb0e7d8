// The three forms of the adaptive Rosenbrock steps on one member (kernels/steppers/adaptive_steps.hpp):
// the lanes' RosenbrockStages, a host team's, and the warp's registers (warp_rosenbrock.hpp, whose stages
// are written out for the registers), the fourth-order tableaus (ros2 takes millions of steps at these
// tolerances; the forms share its code path), in AFM and FM: the same integration
// to rounding (quadratures and angles within 1e-9, step attempts within 1 %).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "support/kernel_scratch.hpp"
#include "support/lanes_reference.hpp"
#include "support/member_forms.hpp"

TEST_CASE("lanes, a team and a warp's registers take the same steps with each fourth-order tableau",
          "[kernels][warp][team][steppers]") {
  using namespace rotorsweep::kernels;
  using rotorsweep::testing::RowsOnLanes;
  using rotorsweep::testing::TwoPeriods;
  constexpr std::size_t n = 21;  // 8 lanes × 3 slots, one padding slot; 4 ranks of 5 or 6 rows
  std::vector<double> disorder(n);
  for (std::size_t j = 0; j < n; ++j) disorder[j] = 1e-6 * std::sin(2.3 * double(j) + 0.4);
  for (const RosenbrockTableau* table : {&rodas4_tableau, &rodas4p2_tableau, &rodas5p_tableau})
    for (double A : {2.0, 12.0}) {  // AFM and FM at g = 0.0011
      RowsOnLanes::Parameters p{A, 0.0011};
      p.A_rows = p.anisotropy_rows = p.coupling_rows = disorder.data();
      const RowsOnLanes model = rotorsweep::testing::model<RowsOnLanes>(n, all_integrals, p);
      bool ok = false;
      const TwoPeriods lanes = rotorsweep::testing::on_lanes(model, n, *table, ok);
      REQUIRE(ok);
      INFO(table->name << ", A = " << A << ": R " << lanes.quad[0] << ", steps " << lanes.steps);
      {
        INFO("on a team of 4 ranks");
        rotorsweep::testing::check_follows_lanes(rotorsweep::testing::on_team(model, n, 4, *table), lanes,
                                                 1e-9);
      }
      {
        INFO("in the registers of 8 lanes × 3 slots");
        rotorsweep::testing::check_follows_lanes(rotorsweep::testing::in_registers<8, 3, true>(n, p, *table),
                                                 lanes, 1e-9);
      }
    }
}
