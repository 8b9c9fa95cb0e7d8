// Failure isolation in a SIMD block: a lane whose state turns non-finite is frozen and flagged
// while the other lanes finish bit-identically; an exhausted step budget is flagged per lane.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "kernels/lanes/angles.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "support/kernel_scratch.hpp"

using namespace rotorsweep::kernels;

namespace {

using Model = NearestNeighbourRows<simd_lane>;
constexpr std::size_t W = lane_width<simd_lane>;
constexpr std::size_t rows = 8;

LaneState<simd_lane> make_state(bool poison_lane_zero) {
  auto s = rotorsweep::testing::lane_state<simd_lane>(rows, Model::max_quadratures);
  for (std::size_t j = 0; j < rows; ++j)
    s.y[j] = lane_from<simd_lane>([&](std::size_t l) { return 0.1 * double(j) + 0.01 * double(l); });
  if (poison_lane_zero) lane_set(s.y[3], 0, std::numeric_limits<double>::quiet_NaN());
  s.t_stop = simd_lane(two_pi);
  return s;
}

}  // namespace

TEST_CASE("a non-finite lane is frozen and flagged; the others are untouched", "[kernels][status]") {
  const auto model = rotorsweep::testing::model<Model>(
      rows, dissipation_only, lane_from<simd_lane>([](std::size_t l) { return 1.0 + double(l); }),
      simd_lane(0.01));
  auto clean_run =
      rotorsweep::testing::integrator<AdaptiveIntegrator<Model, RosenbrockStepper<Model>>>(model, rodas4_tableau, {1e-7, 1e-10});
  auto poisoned_run =
      rotorsweep::testing::integrator<AdaptiveIntegrator<Model, RosenbrockStepper<Model>>>(model, rodas4_tableau, {1e-7, 1e-10});
  auto clean = make_state(false), poisoned = make_state(true);
  clean_run.advance(model, clean);
  poisoned_run.advance(model, poisoned);

  CHECK(poisoned.status[0] == LaneStatus::non_finite);
  for (std::size_t l = 1; l < W; ++l) {
    INFO("lane " << l);
    CHECK(poisoned.status[l] == LaneStatus::ok);
    CHECK(clean.status[l] == LaneStatus::ok);
    CHECK(lane_get(poisoned.t, l) == two_pi);
    CHECK(lane_get(poisoned.steps_accepted, l) == lane_get(clean.steps_accepted, l));
    for (std::size_t j = 0; j < rows; ++j) CHECK(lane_get(poisoned.y[j], l) == lane_get(clean.y[j], l));
    CHECK(lane_get(poisoned.quad[0], l) == lane_get(clean.quad[0], l));
  }
}

TEST_CASE("an exhausted step budget is flagged and stops the lane", "[kernels][status]") {
  const auto model =
      rotorsweep::testing::model<Model>(rows, dissipation_only, simd_lane(6.0), simd_lane(0.001));
  StepLimits limits;
  limits.max_steps = 40;
  auto integrator =
      rotorsweep::testing::integrator<AdaptiveIntegrator<Model, RosenbrockStepper<Model>>>(model, rodas4_tableau, {1e-8, 1e-11}, limits);
  auto s = make_state(false);
  integrator.advance(model, s);
  for (std::size_t l = 0; l < W; ++l) {
    CHECK(s.status[l] == LaneStatus::step_budget);
    CHECK(lane_get(s.t, l) < two_pi);
    CHECK(lane_get(s.steps_accepted, l) + lane_get(s.steps_rejected, l) == 40);
  }
}
