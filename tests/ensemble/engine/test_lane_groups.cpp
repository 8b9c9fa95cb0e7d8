// run_lane_groups, the CPU's one driver of lane schedulers (ensemble/engine/lane_groups.hpp): every
// position of every group runs once, through the control's claim where it has one; progress and stops
// are counted; a stop leaves members out and says so, one after the last member does not.
#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cstddef>
#include <mutex>
#include <vector>

#include "ensemble/engine/lane_groups.hpp"

using namespace rotorsweep::ensemble;

namespace {

const std::vector<PositionRange> groups{{0, 5}, {5, 12}, {12, 13}};

/// Positions given outside their group, progress counts that went backwards, claims of unknown groups:
/// counted on the worker threads (Catch2's assertions are for the main thread).
std::atomic<int> misplaced{0}, backwards{0}, unknown{0};

/// Runs the groups with a run_group that takes positions until none is left, "closes" two stops per
/// member and counts each position it ran in `ran`.
RunOutcome run(const RunControl& control, std::vector<std::atomic<int>>& ran) {
  return run_lane_groups(groups, control, 4,
                         [&](std::size_t g, const auto& next, const auto& retired, const auto& stopped,
                             const auto& stop_closed) {
                           LaneSteps steps;
                           while (const auto k = next()) {
                             if (*k < groups[g].begin || *k >= groups[g].end) ++misplaced;
                             if (stopped()) break;
                             stop_closed();
                             stop_closed();
                             ++ran[*k];
                             retired();
                             steps.busy += 1;
                             steps.total += 4;
                           }
                           return steps;
                         });
}

}  // namespace

TEST_CASE("run_lane_groups runs every position once and reports progress and stops", "[engine]") {
  std::vector<std::atomic<int>> ran(13);
  std::atomic<std::size_t> stops{0};
  std::size_t last = 0, calls = 0;
  const RunOutcome outcome = run({.threads = 3,
                                  .progress =
                                      [&](std::size_t done) {
                                        if (done < last) ++backwards;  // never backwards, never two at once
                                        last = done;
                                        ++calls;
                                      },
                                  .stops = &stops},
                                 ran);
  for (const auto& r : ran) CHECK(r == 1);
  CHECK(misplaced == 0);
  CHECK(backwards == 0);
  CHECK(last == 13);
  CHECK(calls >= 13);
  CHECK(stops == 26);
  CHECK_FALSE(outcome.interrupted);
  CHECK(outcome.statistics.threads == 3);
  CHECK(outcome.statistics.lane_width == 4);
  CHECK(outcome.statistics.lane_steps_busy == 13);
  CHECK(outcome.statistics.occupancy() == Catch::Detail::Approx(0.25));
}

TEST_CASE("run_lane_groups takes positions through the control's claim, shared by two runs", "[engine]") {
  // two processes of mpirun, as two runs on one counter per group: each position runs in one of them
  std::vector<std::atomic<std::size_t>> counters(groups.size());
  std::mutex claims;
  std::vector<std::size_t> claimed;
  const RunControl control{
      .threads = 2, .claim = [&](std::size_t begin, std::size_t end) {
        const auto g = std::size_t(std::find_if(groups.begin(), groups.end(),
                                                [&](const PositionRange& r) { return r.begin == begin; }) -
                                   groups.begin());
        if (g == groups.size() || groups[g].end != end) ++unknown;
        const std::size_t k = begin + counters[g]++;
        const std::lock_guard guard(claims);
        claimed.push_back(k);
        return k;
      }};
  std::vector<std::atomic<int>> ran(13);
  run(control, ran);
  run(control, ran);
  for (const auto& r : ran) CHECK(r == 1);
  CHECK(unknown == 0);
  CHECK(claimed.size() >= 13);
}

TEST_CASE("run_lane_groups: a stop leaves members out and says so; one after the last member does not",
          "[engine]") {
  std::vector<std::atomic<int>> ran(13);
  std::atomic<bool> stop{false};
  const auto raised = [&] { return stop.load(); };
  const RunOutcome stopped = run(
      {.threads = 1, .progress = [&](std::size_t done) { stop = stop || done == 3; }, .stop = raised}, ran);
  CHECK(stopped.interrupted);
  int total = 0;
  for (const auto& r : ran) total += r;
  CHECK(total == 3);

  std::vector<std::atomic<int>> again(13);
  stop = false;
  const RunOutcome whole =
      run({.threads = 2, .progress = [&](std::size_t done) { stop = stop || done == 13; }, .stop = raised},
          again);
  CHECK_FALSE(whole.interrupted);
  for (const auto& r : again) CHECK(r == 1);
}
