// A shadow run as an error estimate (ensemble/rows/shadow_attractor.hpp, rows/shadow_run.hpp) on
// hand-made results: one that reaches its primary's attractor gives the Richardson bound, at least the
// local estimate times shadow_local_floor; one that does not (another regime, slip count or domain
// walls) is flagged and gives no estimate; symmetry-limited members and departed shadows are never
// resolved; the symmetry probe's verdict and the symmetric sets an end state lies on.
#include <catch2/catch.hpp>
#include <cmath>

#include "ensemble/rows/shadow_attractor.hpp"
#include "ensemble/rows/symmetry_probe.hpp"

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
  complete_with_shadow(primary, result(Regime::cp, 10.09, 4));
  CHECK_FALSE(primary.shadow_departed);
  CHECK(primary.dissipation_shadow == 10.09);
  CHECK(primary.dissipation_error() == Approx(2 * 0.09 / 0.9));
  CHECK(primary.dissipation_resolved());  // 0.2 < 0.1 · 10
  // a shadow that agrees by chance leaves the local estimate amplified as the slips amplify it
  MemberResult agreeing = result(Regime::cp, 10.0, 4);
  complete_with_shadow(agreeing, result(Regime::cp, 10.0, 4));
  CHECK(agreeing.dissipation_error() == shadow_local_floor * 1e-9);
  // SA is CP by its slips (the slower rerun that tells them apart does not run for shadows)
  MemberResult smooth = result(Regime::sa, 1.0, 4);
  complete_with_shadow(smooth, result(Regime::cp, 1.0001, 4));
  CHECK_FALSE(smooth.shadow_departed);
}

TEST_CASE("a shadow that reaches another attractor is flagged and estimates nothing",
          "[ensemble][global_error]") {
  // the collapse into the strict-FM set: the shadow stops slipping
  MemberResult collapsed = result(Regime::cp, 0.97, 4);
  complete_with_shadow(collapsed, result(Regime::fm, 12.29, 0));
  CHECK(collapsed.shadow_departed);
  CHECK(collapsed.dissipation_shadow == 12.29);
  CHECK(std::isinf(collapsed.dissipation_error()));
  CHECK_FALSE(collapsed.dissipation_resolved());
  // another slip count, and other domain walls, with D by chance alike
  for (const MemberResult& shadow : {result(Regime::cp, 1.0, 2), result(Regime::dw, 1.0, 4, 2)}) {
    MemberResult primary = result(Regime::cp, 1.0, 4);
    complete_with_shadow(primary, shadow);
    CHECK(primary.shadow_departed);
    CHECK_FALSE(primary.dissipation_resolved());
  }
  // a failed shadow departs nowhere: no estimate either
  MemberResult primary = result(Regime::cp, 1.0, 4);
  MemberResult failed = result(Regime::unsettled, NAN, NAN);
  failed.status = rotorsweep::kernels::LaneStatus::non_finite;
  complete_with_shadow(primary, failed);
  CHECK_FALSE(primary.shadow_departed);
  CHECK(std::isnan(primary.dissipation_shadow));
  CHECK(std::isinf(primary.dissipation_error()));
}

TEST_CASE("a symmetry-limited member is not resolved, however small its shadow difference",
          "[ensemble][global_error]") {
  MemberResult primary = result(Regime::cp, 10.0, 4);
  complete_with_shadow(primary, result(Regime::cp, 10.0 + 1e-9, 4));
  take_probe(primary, result(Regime::cp, 10.5, 4));  // an asymmetry at rtol moves D by 5 %
  settle_symmetry(primary);
  CHECK(primary.symmetry_limited);
  CHECK_FALSE(primary.symmetry_held);
  CHECK(primary.dissipation_probe == 10.5);
  CHECK(primary.dissipation_error() < 1e-3 * primary.dissipation());
  CHECK_FALSE(primary.dissipation_resolved());
}

TEST_CASE("the symmetry probe's verdict: another attractor, or a slipping member's D moved beyond its error",
          "[ensemble][global_error]") {
  // a converging member: the probe moves D by less than its error
  MemberResult converging = result(Regime::cp, 10.0, 4);
  complete_with_shadow(converging, result(Regime::cp, 10.0 + 1e-6, 4));
  take_probe(converging, result(Regime::cp, 10.0 + 1e-7, 4));
  settle_symmetry(converging);
  CHECK(converging.probe_followed);
  CHECK_FALSE(converging.symmetry_limited);
  CHECK(converging.dissipation_resolved());
  // held in the strict-FM set: the probe slips, so the set is unstable
  MemberResult held = result(Regime::fm, 0.272, 0);
  take_probe(held, result(Regime::cp, 1.02, 2));
  settle_symmetry(held);
  CHECK_FALSE(held.probe_followed);
  CHECK(held.symmetry_limited);
  CHECK(held.symmetry_held);
  CHECK_FALSE(held.dissipation_resolved());
  // a stable FM member: its probe stays, and D moving by more than the local estimate alone is no verdict
  MemberResult stable = result(Regime::fm, 0.272, 0);
  take_probe(stable, result(Regime::fm, 0.272 + 1e-8, 0));
  settle_symmetry(stable);
  CHECK_FALSE(stable.symmetry_limited);
  // a probe that failed shows nothing: the member counts as limited, its verdict unknown
  MemberResult unknown = result(Regime::cp, 10.0, 4);
  MemberResult failed = result(Regime::unsettled, NAN, NAN);
  failed.status = rotorsweep::kernels::LaneStatus::non_finite;
  take_probe(unknown, failed);
  settle_symmetry(unknown);
  CHECK(std::isnan(unknown.dissipation_probe));
  CHECK(unknown.symmetry_limited);
}

TEST_CASE("end states on symmetric sets: commensurate patterns on periodic rows, mirror images on open rows",
          "[ensemble][global_error]") {
  const double pi = 3.141592653589793;
  CHECK(on_symmetric_set({0.3, 0.3 + 2 * pi, 0.3 - 1e-5, 0.3}, false));  // strict FM, angles mod 2π
  CHECK(on_symmetric_set({0.1, 2.0, 0.1, 2.0, 0.1, 2.0}, false));        // two sublattices
  CHECK(on_symmetric_set({0.1, 2.0, 3.0, 0.1, 2.0, 3.0}, false));        // period 3 of 6
  CHECK_FALSE(on_symmetric_set({0.1, 2.0, 3.0, 0.1, 2.0, 3.0, 0.1}, false));
  CHECK_FALSE(on_symmetric_set({0.3, 0.3, 0.3, 0.302}, false));
  CHECK(on_symmetric_set({0.1, 2.0, 2.0, 0.1}, true));
  CHECK(on_symmetric_set({0.1, 2.0, 5.0, 2.0, 0.1}, true));
  CHECK_FALSE(on_symmetric_set({0.1, 2.0, 2.1, 0.1}, true));
}
