// A member with its rows in registers (kernels/steppers/warp_member_form.hpp and warp_rosenbrock.hpp, on
// the host's emulation of a warp) follows the lanes' integration (AdaptiveIntegrator over
// NearestNeighbourRows) over two periods: every lane count and fill of the slots, uniform and disordered
// rows, every quadrature; and with fewer stage vectors (a shape's stage count) the same bits.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/lanes/warp.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "support/kernel_scratch.hpp"
#include "support/lanes_reference.hpp"
#include "support/member_forms.hpp"

using namespace rotorsweep::kernels;

namespace {

using Lanes = NearestNeighbourRows<double>;
using rotorsweep::testing::in_registers;
using rotorsweep::testing::TwoPeriods;

/// The member in registers against the lanes at g = 0.0011: AFM and FM within 1e-9, and with disorder
/// (which breaks the rows' symmetry that rounding otherwise breaks at each slip) CP's four slips per
/// period within 1e-7: the sums' other order moves the slips' times at rounding level, which the
/// slips amplify (the lanes against themselves in another order do the same).
template <std::size_t L, std::size_t R, bool PerRow>
void check_follows(std::size_t n, const RosenbrockTableau& table = rodas4p2_tableau) {
  for (double A : {2.0, 6.0, 12.0}) {
    if (A == 6.0 && (!PerRow || n > 32)) continue;  // at N = 100, CP's slips amplify rounding beyond 1e-7
    std::vector<double> disorder(n);
    for (std::size_t j = 0; j < n; ++j) disorder[j] = 1e-6 * std::sin(2.3 * double(j) + 0.4);
    Lanes::Parameters p{A, 0.0011};
    if (PerRow) p.A_rows = p.anisotropy_rows = p.coupling_rows = disorder.data();
    bool ok = false;
    const TwoPeriods lanes =
        rotorsweep::testing::on_lanes(rotorsweep::testing::model<Lanes>(n, all_integrals, p), n, table, ok);
    REQUIRE(ok);
    const TwoPeriods warp = in_registers<L, R, PerRow>(n, p, table);
    INFO(table.name << ", L = " << L << ", R = " << R << ", N = " << n << ", A = " << A << ": R "
                    << lanes.quad[0] << ", steps " << lanes.steps << " and " << warp.steps);
    rotorsweep::testing::check_follows_lanes(warp, lanes, A == 6.0 ? 1e-7 : 1e-9);
  }
}

}  // namespace

TEST_CASE("a member in registers follows the lanes' integration for each border solve and fill",
          "[kernels][warp][steppers]") {
  check_follows<1, 4, false>(4);
  check_follows<1, 4, false>(3);
  check_follows<4, 5, false>(20);
  check_follows<8, 3, false>(20);
  check_follows<8, 3, true>(21);
  check_follows<32, 4, true>(100);
}

TEST_CASE("a member in registers runs every linearly implicit tableau", "[kernels][warp][steppers]") {
  check_follows<8, 3, true>(20, rodas4_tableau);
  check_follows<8, 3, true>(20, rodas5p_tableau);
}

TEST_CASE("a member in registers with six stage vectors gives eight's bits with a six-stage tableau",
          "[kernels][warp][steppers]") {
  for (const RosenbrockTableau* table : {&rodas4_tableau, &rodas4p2_tableau}) {
    const Lanes::Parameters p{6.0, 0.0011};
    const TwoPeriods six = in_registers<1, 4, false, 6>(4, p, *table);
    const TwoPeriods eight = in_registers<1, 4, false, 8>(4, p, *table);
    INFO(table->name);
    CHECK(six.theta == eight.theta);
    CHECK(six.quad == eight.quad);
    CHECK(six.steps == eight.steps);
  }
}
