// MemberProgress, the period schedule every backend follows (README "schedule.*"): a fixed
// schedule, a problem's steady test after the schedule but never at the first period, and the cap.
#include <catch2/catch.hpp>
#include <vector>

#include "ensemble/engine/member_progress.hpp"

using namespace rotorsweep::ensemble;

namespace {

/// Closes periods at which the steady test holds or not until the member retires; returns how many it
/// took (0 if it never retired).
int periods_until_retired(const PeriodSchedule& s, const std::vector<bool>& steady, MemberProgress& progress) {
  for (const bool holds : steady)
    if (progress.close_period(s, holds)) return progress.periods();
  return 0;
}

}  // namespace

TEST_CASE("a fixed schedule retires after relax + average periods, settled, whatever the test says",
          "[ensemble][steady]") {
  const PeriodSchedule s{2, 3, 50, false};
  MemberProgress progress;
  CHECK(periods_until_retired(s, {false, true, false, false, false, false}, progress) == 5);
  CHECK(progress.settled());
  CHECK(s.limit() == 5);
}

TEST_CASE("a steady test retires once it holds, not before the schedule nor at the first period",
          "[ensemble][steady]") {
  const PeriodSchedule s{1, 2, 10, true};
  MemberProgress early;
  // the test holds at period 2, but the schedule asks for 3 periods first
  CHECK(periods_until_retired(s, {false, true, false, false, true}, early) == 5);
  CHECK(early.settled());
  // the first period is never taken as settled
  MemberProgress first;
  CHECK(periods_until_retired({0, 1, 10, true}, {true, false, true}, first) == 3);
  CHECK(s.limit() == 10);
}

TEST_CASE("a steady test stops at max_periods, unsettled", "[ensemble][steady]") {
  const PeriodSchedule s{1, 1, 4, true};
  MemberProgress progress;
  CHECK(periods_until_retired(s, {false, false, false, false, false, false}, progress) == 4);
  CHECK_FALSE(progress.settled());
}
