// A member with its rows in registers (kernels/steppers/warp_integrator.hpp, on the host's emulation of
// a warp) follows the lanes' integration (AdaptiveIntegrator over NearestNeighbourRows) over two
// periods: every lane count and fill of the slots, uniform and disordered rows, every quadrature; and
// with fewer stage vectors (a shape's stage count) the same bits.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/lanes/warp.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/models/rows/warp_rows.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "kernels/steppers/warp_integrator.hpp"
#include "kernels/steppers/warp_rosenbrock.hpp"
#include "support/kernel_scratch.hpp"
#include "support/lanes_reference.hpp"

using namespace rotorsweep::kernels;

namespace {

using Lanes = NearestNeighbourRows<double>;
using rotorsweep::testing::afm_start;
using rotorsweep::testing::TwoPeriods;
constexpr Tolerances tight = rotorsweep::testing::tight_tolerances;

template <std::size_t L, std::size_t R, bool PerRow, std::size_t S = 8>
TwoPeriods in_registers(std::size_t n, const Lanes::Parameters& p, const RosenbrockTableau& table) {
  using W = HostWarp<L>;
  using Model = WarpRows<W, R, PerRow, all_integrals>;
  using Integrator = WarpIntegrator<Model, WarpRosenbrock<Model, S>>;
  const WarpRowSlots<W, R> slots(n);
  Model model(slots, all_integrals, {p.A, p.g, p.strict_fm, p.A_rows, p.anisotropy_rows, p.coupling_rows});
  const double scale = AdaptiveIntegrator<Lanes, RosenbrockStepper<Lanes>>::first_step_scale(tight, table);
  Integrator integrator(table, tight, StepLimits{}, scale);
  typename Integrator::State state;
  const auto theta = afm_start(n);
  for (std::size_t r = 0; r < R; ++r)
    for (std::size_t l = 0; l < L; ++l)
      lane_set(state.y[r], l,
               mask_get(slots.real(r), l) ? theta[std::size_t(lane_get(slots.row(r), l))] : 0.0);
  state.t_stop = 2 * two_pi;
  while (state.stepping()) integrator.attempt(model, state);
  REQUIRE(state.status == LaneStatus::ok);
  TwoPeriods run{std::vector<double>(n), std::vector<double>(state.quad, state.quad + 8),
                 state.steps_accepted + state.steps_rejected};
  for (std::size_t r = 0; r < R; ++r)
    for (std::size_t l = 0; l < L; ++l)
      if (mask_get(slots.real(r), l))
        run.theta[std::size_t(lane_get(slots.row(r), l))] = lane_get(state.y[r], l);
  return run;
}

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
    const double tolerance = A == 6.0 ? 1e-7 : 1e-9;
    for (std::size_t q = 0; q < 8; ++q) {
      INFO("quadrature " << q);
      CHECK(warp.quad[q] == Approx(lanes.quad[q]).epsilon(tolerance).margin(1e-12));
    }
    double largest = 0;
    for (std::size_t j = 0; j < n; ++j)
      largest = std::max(largest, std::fabs(warp.theta[j] - lanes.theta[j]));
    CHECK(largest < tolerance);
    CHECK(warp.steps == Approx(lanes.steps).epsilon(0.01));
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
