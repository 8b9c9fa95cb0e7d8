// MemberProgress, the stop schedule every backend follows (a row member's periods, docs/scenes.md
// "Row scenes", keys schedule.*; a slider member's samples): a fixed count, a problem's steady test after
// it but never at the first stop, and the cap.
#include <catch2/catch.hpp>
#include <vector>

#include "ensemble/engine/member_progress.hpp"

using namespace rotorsweep::ensemble;

namespace {

/// Closes stops at which the steady test holds or not until the member retires; returns how many it
/// took (0 if it never retired).
int stops_until_retired(const StopSchedule& s, const std::vector<bool>& steady, MemberProgress& progress) {
  for (const bool holds : steady)
    if (progress.close_stop(s, holds)) return progress.stops();
  return 0;
}

}  // namespace

TEST_CASE("a fixed schedule retires after its stops, settled, whatever the test says", "[ensemble][steady]") {
  const StopSchedule s{5, 50, false};
  MemberProgress progress;
  CHECK(stops_until_retired(s, {false, true, false, false, false, false}, progress) == 5);
  CHECK(progress.settled());
  CHECK(s.limit() == 5);
}

TEST_CASE("a steady test retires once it holds, not before the schedule nor at the first stop",
          "[ensemble][steady]") {
  const StopSchedule s{3, 10, true};
  MemberProgress early;
  // the test holds at stop 2, but the schedule asks for 3 stops first
  CHECK(stops_until_retired(s, {false, true, false, false, true}, early) == 5);
  CHECK(early.settled());
  // the first stop is never taken as settled
  MemberProgress first;
  CHECK(stops_until_retired({1, 10, true}, {true, false, true}, first) == 3);
  CHECK(s.limit() == 10);
}

TEST_CASE("a steady test stops at max_stops, unsettled", "[ensemble][steady]") {
  const StopSchedule s{2, 4, true};
  MemberProgress progress;
  CHECK(stops_until_retired(s, {false, false, false, false, false, false}, progress) == 4);
  CHECK_FALSE(progress.settled());
}
