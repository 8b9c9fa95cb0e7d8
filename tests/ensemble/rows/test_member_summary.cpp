// Member summaries (ensemble/member_summary): the regime rule on hand-made period records,
// the steady-state test, means and spread over the averaged periods, and the DW label.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "ensemble/rows/member_summary.hpp"

using namespace rotorsweep::ensemble;

namespace {

PeriodRecord period(double D, double rho_min, double rho_max, double slips) {
  PeriodRecord p;
  p[Channel::dissipation] = D;
  p[Channel::alignment_min] = rho_min;
  p[Channel::alignment_max] = rho_max;
  p[Channel::alignment_mean] = (rho_min + rho_max) / 2;
  p[Channel::slips] = slips;
  return p;
}

}  // namespace

TEST_CASE("the regime rule", "[ensemble][regime]") {
  CHECK(classify_regime({period(1, 0.9, 1.0, 0), period(1, 0.7, 1.0, 0)}) == Regime::fm);
  CHECK(classify_regime({period(1, 0.0, 0.1, 0), period(1, 0.0, 0.3, 0)}) == Regime::afm);
  CHECK(classify_regime({period(1, 0.3, 1.0, 4), period(1, 0.3, 1.0, 4)}) == Regime::cp);
  CHECK(classify_regime({period(1, 0.7, 1.0, 2), period(1, 0.7, 1.0, 2)}) == Regime::cp);
  // slips in one period only: a transient
  CHECK(classify_regime({period(1, 0.3, 1.0, 1), period(1, 0.3, 1.0, 0)}) == Regime::unsettled);
  // ρ̄ crossing 1/2 without a slip
  CHECK(classify_regime({period(1, 0.4, 0.6, 0)}) == Regime::unsettled);
  // exactly 1/2 is neither strictly FM-like nor AFM-like
  CHECK(classify_regime({period(1, 0.5, 0.9, 0)}) == Regime::unsettled);
  CHECK(classify_regime({}) == Regime::unsettled);
}

TEST_CASE("summaries average the last periods only", "[ensemble][summary]") {
  MemberResult r;
  summarize({period(100, 0.0, 1.0, 9), period(2, 0.0, 0.2, 0), period(4, 0.1, 0.3, 0)}, 2, true, r);
  CHECK(r.dissipation() == 3);
  CHECK(r.dissipation_std() == 1);  // population spread of {2, 4}
  CHECK(r.alignment_min() == 0.0);
  CHECK(r.alignment_max() == 0.3);
  CHECK(r.alignment_mean() == Approx((0.1 + 0.2) / 2));
  CHECK(r.slips_per_period() == 0);
  CHECK(r.regime == Regime::afm);

  MemberResult unclassified;
  summarize({period(2, 0.0, 0.2, 0)}, 2, false, unclassified);
  CHECK(unclassified.regime == Regime::unsettled);

  MemberResult unsettled;
  unsettled.settled = false;
  summarize({period(2, 0.0, 0.2, 0)}, 1, true, unsettled);
  CHECK(unsettled.regime == Regime::unsettled);

  MemberResult failed;
  summarize({}, 2, true, failed);
  CHECK(std::isnan(failed.dissipation()));
  CHECK(std::isnan(failed.alignment_mean()));
}

TEST_CASE("a member that slips every period across domain walls is DW, with walls it is not CP",
          "[ensemble][regime]") {
  const double pi = std::acos(-1.0);
  const auto retired = [&](const std::vector<double>& theta) {
    RetiredLane lane;
    lane.status = rotorsweep::kernels::LaneStatus::ok;
    lane.settled = true;
    lane.periods = 4;
    lane.theta = theta;
    lane.history = {period(1, 0.3, 1.0, 4), period(1, 0.3, 1.0, 4)};
    lane.end_states.assign(4, theta);
    SummaryRules rules;
    rules.average_periods = 2;
    rules.classify = true;
    return retired_member_result(std::move(lane), rules);
  };
  // two antiferromagnetic domains: the bonds 3–4 and 7–0 are aligned, four sign changes, two walls
  const auto walls = retired({0, pi, 0, pi, pi, 0, pi, 0});
  CHECK(walls.regime == Regime::dw);
  CHECK(walls.final_state.domain_walls == 2);
  CHECK(walls.final_state.attractor == "DW:walls2:p1");
  const auto two_sublattices = retired({0, pi, 0, pi, 0, pi, 0, pi});
  CHECK(two_sublattices.regime == Regime::cp);
  CHECK(two_sublattices.final_state.attractor == "CP:2SL:p1");
}
