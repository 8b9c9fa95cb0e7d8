// MemberProgress, the period schedule every backend follows (README "schedule.*"): a fixed
// schedule, the steady-state test of steady_tol, and the max_periods cap.
#include <catch2/catch.hpp>
#include <vector>

#include "ensemble/engine/member_progress.hpp"

using namespace rotorsweep::ensemble;

namespace {

/// Closes periods with the given dissipations until the member retires; returns how many it took
/// (0 if it never retired).
int periods_until_retired(const PeriodSchedule& s, const std::vector<double>& dissipations,
                          MemberProgress& progress) {
  for (double d : dissipations)
    if (progress.close_period(s, d)) return progress.periods();
  return 0;
}

}  // namespace

TEST_CASE("successive periods agree to a relative tolerance", "[ensemble][steady]") {
  CHECK(dissipations_agree(1.0, 1.05, 0.1));
  CHECK_FALSE(dissipations_agree(1.0, 1.2, 0.1));
  CHECK(dissipations_agree(0.0, 0.0, 1e-9));
  CHECK(dissipations_agree(-1.0, -1.05, 0.1));
  CHECK_FALSE(dissipations_agree(1.0, -1.0, 0.5));
}

TEST_CASE("a fixed schedule retires after relax + average periods, settled", "[ensemble][steady]") {
  const PeriodSchedule s{2, 3, 50, 0.0};
  MemberProgress progress;
  CHECK(periods_until_retired(s, {9, 1, 5, 2, 7, 7, 7}, progress) == 5);
  CHECK(progress.settled());
  CHECK(s.limit() == 5);
}

TEST_CASE("steady_tol retires once two successive periods agree, not before the schedule",
          "[ensemble][steady]") {
  const PeriodSchedule s{1, 2, 10, 0.01};
  MemberProgress early;
  // periods 1 and 2 agree, but the schedule asks for 3 periods first
  CHECK(periods_until_retired(s, {1.0, 1.0, 2.0, 1.5, 1.501}, early) == 5);
  CHECK(early.settled());
  // the first period is never compared with anything (here it would agree with the initial 0)
  MemberProgress first;
  CHECK(periods_until_retired({0, 1, 10, 0.01}, {0.0, 5.0, 5.0}, first) == 3);
  CHECK(s.limit() == 10);
}

TEST_CASE("steady_tol stops at max_periods, unsettled", "[ensemble][steady]") {
  const PeriodSchedule s{1, 1, 4, 1e-6};
  MemberProgress progress;
  CHECK(periods_until_retired(s, {1, 2, 3, 4, 5, 6}, progress) == 4);
  CHECK_FALSE(progress.settled());
}
