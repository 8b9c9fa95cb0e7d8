// A shadow run as an error estimate (ensemble/rows/shadow_attractor.hpp, rows/shadow_run.hpp) on
// hand-made results: one that reaches its primary's attractor gives the Richardson bound, at least the
// local estimate times shadow_local_floor; one that does not (another regime, slip count or domain
// walls) is flagged and gives no estimate; symmetry-limited members and departed shadows are never
// resolved.
#include <catch2/catch.hpp>
#include <cmath>

#include "ensemble/rows/shadow_attractor.hpp"

using namespace rotorsweep::ensemble;

namespace {

MemberResult result(Regime regime, double D, double slips, int walls = 0) {
  MemberResult r;
  r.regime = regime;
  r.summary(Summary::mean, Channel::dissipation) = D;
  r.summary(Summary::mean, Channel::dissipation_error) = 1e-9;  // the local estimate
  r.summary(Summary::mean, Channel::slips) = slips;
  r.final_state.domain_walls = walls;
  return r;
}

}  // namespace

TEST_CASE("a shadow that reaches the primary's attractor bounds D's error", "[ensemble][global_error]") {
  MemberResult primary = result(Regime::cp, 10.0, 4);
  complete_with_shadow(primary, result(Regime::cp, 10.09, 4), false);
  CHECK_FALSE(primary.shadow_departed);
  CHECK(primary.dissipation_shadow == 10.09);
  CHECK(primary.dissipation_error() == Approx(2 * 0.09 / 0.9));
  CHECK(primary.dissipation_resolved());  // 0.2 < 0.1 · 10
  // a shadow that agrees by chance leaves the local estimate amplified as the slips amplify it
  MemberResult agreeing = result(Regime::cp, 10.0, 4);
  complete_with_shadow(agreeing, result(Regime::cp, 10.0, 4), false);
  CHECK(agreeing.dissipation_error() == shadow_local_floor * 1e-9);
  // SA is CP by its slips (the slower rerun that tells them apart does not run for shadows)
  MemberResult smooth = result(Regime::sa, 1.0, 4);
  complete_with_shadow(smooth, result(Regime::cp, 1.0001, 4), false);
  CHECK_FALSE(smooth.shadow_departed);
}

TEST_CASE("a shadow that reaches another attractor is flagged and estimates nothing",
          "[ensemble][global_error]") {
  // the collapse into the strict-FM set: the shadow stops slipping
  MemberResult collapsed = result(Regime::cp, 0.97, 4);
  complete_with_shadow(collapsed, result(Regime::fm, 12.29, 0), false);
  CHECK(collapsed.shadow_departed);
  CHECK(collapsed.dissipation_shadow == 12.29);
  CHECK(std::isinf(collapsed.dissipation_error()));
  CHECK_FALSE(collapsed.dissipation_resolved());
  // another slip count, and other domain walls, with D by chance alike
  for (const MemberResult& shadow : {result(Regime::cp, 1.0, 2), result(Regime::dw, 1.0, 4, 2)}) {
    MemberResult primary = result(Regime::cp, 1.0, 4);
    complete_with_shadow(primary, shadow, false);
    CHECK(primary.shadow_departed);
    CHECK_FALSE(primary.dissipation_resolved());
  }
  // a failed shadow departs nowhere: no estimate either
  MemberResult primary = result(Regime::cp, 1.0, 4);
  MemberResult failed = result(Regime::unsettled, NAN, NAN);
  failed.status = rotorsweep::kernels::LaneStatus::non_finite;
  complete_with_shadow(primary, failed, false);
  CHECK_FALSE(primary.shadow_departed);
  CHECK(std::isnan(primary.dissipation_shadow));
  CHECK(std::isinf(primary.dissipation_error()));
}

TEST_CASE("a symmetry-limited member is not resolved, however small its shadow difference",
          "[ensemble][global_error]") {
  MemberResult primary = result(Regime::cp, 10.0, 4);
  complete_with_shadow(primary, result(Regime::cp, 10.0 + 1e-9, 4), true);
  CHECK(primary.symmetry_limited);
  CHECK(primary.dissipation_error() < 1e-3 * primary.dissipation());
  CHECK_FALSE(primary.dissipation_resolved());
}
