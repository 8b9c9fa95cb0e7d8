// Step reducers (ensemble/step_reducers): slip events counted once per run of fast steps, each
// slip's energy, and alignment extremes, on scalar and SIMD lanes with masked (rejected) steps.
#include <catch2/catch.hpp>
#include <cmath>

#include "ensemble/rows/step_reducers.hpp"

using namespace rotorsweep::ensemble;
using Catch::Detail::Approx;
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

TEMPLATE_TEST_CASE("with energies, each slip's g Σ Δθ²/Δt goes to its own channel, in order",
                   "[ensemble][reducers]", double, simd_lane) {
  using V = TestType;
  SlipCounter<V> slips(10.0, true);
  for (std::size_t l = 0; l < rotorsweep::kernels::lane_width<V>; ++l) {
    slips.start_lane(l);
    slips.set_damping(l, 0.5);
  }
  V before[2] = {V(0.0), V(0.0)}, after[2] = {V(0.0), V(0.0)};
  const auto accepted = V(0.0) == V(0.0);
  const auto rejected = V(0.0) != V(0.0);
  const auto step = [&](double d0, double d1, double dt, auto mask) {
    after[0] = before[0] + V(d0);
    after[1] = before[1] + V(d1);
    slips.accumulate(mask, 2, before, after, V(dt));
    before[0] = after[0];
    before[1] = after[1];
  };
  step(0.01, 0.0, 0.01, accepted);  // smooth: no energy
  step(1.0, 0.5, 0.01, accepted);   // slip 1: 0.5 (1 + 0.25)/0.01 = 62.5
  step(0.3, 0.4, 0.01, accepted);   // still slip 1: + 0.5 · 0.25/0.01 = 12.5
  step(5.0, 0.0, 0.01, rejected);   // rejected: nothing
  step(0.0, 0.001, 0.01, accepted);
  step(-2.0, 0.0, 0.1, accepted);  // slip 2: 0.5 · 4/0.1 = 20
  PeriodRecord record;
  slips.end_period(0, record);
  CHECK(record.slips() == 2);
  CHECK(record.slip_energy(0) == Approx(75.0));
  CHECK(record.slip_energy(1) == Approx(20.0));
  for (std::size_t k = 2; k < max_slip_energies; ++k) CHECK(std::isnan(record.slip_energy(k)));
  step(0.0, 0.001, 0.01, accepted);
  step(0.0, 3.0, 0.01, accepted);  // the next period's first slip starts from 0
  slips.end_period(0, record);
  CHECK(record.slips() == 1);
  CHECK(record.slip_energy(0) == Approx(450.0));
  CHECK(std::isnan(record.slip_energy(1)));
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
