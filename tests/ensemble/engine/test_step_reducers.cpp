// Step reducers (ensemble/step_reducers): slip events counted once per run of fast steps,
// and alignment extremes, on scalar and SIMD lanes with masked (rejected) steps.
#include <catch2/catch.hpp>

#include "ensemble/engine/step_reducers.hpp"

using namespace rotorsweep::ensemble;
using rotorsweep::kernels::simd_lane;

TEMPLATE_TEST_CASE("a slip is a run of fast steps, counted once", "[ensemble][reducers]", double, simd_lane) {
  using V = TestType;
  SlipCounter<V> slips(10.0);
  for (std::size_t l = 0; l < rotorsweep::kernels::lane_width<V>; ++l) slips.start_lane(l);
  V before[2] = {V(0.0), V(0.0)}, after[2] = {V(0.0), V(0.0)};
  const auto accepted = V(0.0) == V(0.0);
  const auto rejected = V(0.0) != V(0.0);
  const auto step = [&](double dtheta, double dt, auto mask) {
    after[1] = before[1] + V(dtheta);
    slips.accumulate(mask, 2, before, after, V(dt));
    before[1] = after[1];
  };
  step(0.01, 0.01, accepted);  // rate 1: smooth
  step(1.0, 0.01, accepted);   // rate 100: slip begins
  step(1.0, 0.01, accepted);   // still inside
  step(5.0, 0.01, rejected);   // rejected steps do not count
  step(0.01, 0.01, accepted);  // smooth again
  step(-2.0, 0.01, accepted);  // a second slip (either direction)
  PeriodRecord record;
  slips.end_period(0, record);
  CHECK(record.slips() == 2);
  step(-2.0, 0.01, accepted);  // the slip goes on across the period boundary: not a new one
  slips.end_period(0, record);
  CHECK(record.slips() == 0);
}

TEMPLATE_TEST_CASE("alignment extremes follow the attempts' start points", "[ensemble][reducers]", double,
                   simd_lane) {
  using V = TestType;
  AlignmentExtrema<V> extrema;
  extrema.start_lane(0);
  const auto stepped = V(0.0) == V(0.0);
  const auto idle = V(0.0) != V(0.0);
  extrema.accumulate(stepped, V(0.5));  // the period's first point
  extrema.accumulate(stepped, V(0.7));
  extrema.accumulate(idle, V(0.9));  // lanes that did not step do not count
  extrema.accumulate(stepped, V(0.2));
  extrema.accumulate(stepped, V(0.3));
  PeriodRecord record;
  extrema.end_period(0, record);
  CHECK(record.alignment_min() == 0.2);
  CHECK(record.alignment_max() == 0.7);
  extrema.accumulate(stepped, V(0.4));  // the next period starts afresh at its own first point
  extrema.end_period(0, record);
  CHECK(record.alignment_min() == 0.4);
  CHECK(record.alignment_max() == 0.4);
}
