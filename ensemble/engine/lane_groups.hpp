// The CPU's members on lane schedulers over OpenMP threads (docs/architecture.md "The run API"): groups of
// positions claimed through the run's control, progress after members and stops; one driver for every
// problem.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <optional>
#include <vector>

#include "ensemble/engine/run_control.hpp"
#include "ensemble/engine/stopping_threads.hpp"

namespace rotorsweep::ensemble {

/// A lane scheduler's steps: attempts × lanes that held a member, and of all lanes.
struct LaneSteps {
  double busy = 0, total = 0;
};

/// Runs the positions of `groups` on control's threads (run_on_threads: the first exception stops the
/// others and is rethrown). Each thread goes through the groups in order, calling
/// run_group(g, next, retired, stopped, stop_closed) → LaneSteps for each while nothing stopped it:
/// next() gives the group's next position (RunControl::next; empty once none is left or stopped() holds),
/// retired() is called after each member handed to the sink, stop_closed() after each stop a member
/// closes, and stopped() holds once control.stop did (for good) or a thread threw. A thread whose group
/// has no position left goes on to the next group while the others finish theirs.
template <class RunGroup>
RunOutcome run_lane_groups(const std::vector<PositionRange>& groups, const RunControl& control,
                           std::size_t lane_width, RunGroup&& run_group) {
  RunOutcome outcome;
  SweepStatistics& stats = outcome.statistics;
  stats.threads = control.thread_count();
  stats.lane_width = lane_width;
  std::vector<std::atomic<std::size_t>> next(groups.size());
  std::size_t members = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    next[g] = groups[g].begin;
    members += groups[g].end - groups[g].begin;
  }
  std::atomic<std::size_t> done{0};
  std::atomic<bool> stop_seen{false};
  std::mutex progress_lock, statistics_lock;
  const auto start = std::chrono::steady_clock::now();
  const auto asked = [&] {  // once asked, for good
    if (!stop_seen.load(std::memory_order_relaxed) && control.stopped()) stop_seen = true;
    return stop_seen.load(std::memory_order_relaxed);
  };

  run_on_threads(stats.threads, asked, [&](const auto& stopped) {
    for (std::size_t g = 0; g < groups.size() && !stopped(); ++g) {
      const auto take = [&, g]() -> std::optional<std::size_t> {
        if (stopped()) return std::nullopt;
        const std::size_t k = control.next(groups[g].begin, groups[g].end, next[g]);
        if (k >= groups[g].end) return std::nullopt;
        return k;
      };
      const auto retired = [&] {
        done.fetch_add(1, std::memory_order_relaxed);
        if (!control.progress) return;
        const std::lock_guard guard(progress_lock);
        control.progress(done.load(std::memory_order_relaxed));
      };
      const auto stop_closed = [&] {  // progress within long members
        if (!control.stops) return;
        control.stops->fetch_add(1, std::memory_order_relaxed);
        if (control.progress && progress_lock.try_lock()) {
          control.progress(done.load(std::memory_order_relaxed));
          progress_lock.unlock();
        }
      };
      const LaneSteps steps = run_group(g, take, retired, stopped, stop_closed);
      const std::lock_guard guard(statistics_lock);
      stats.lane_steps_busy += steps.busy;
      stats.lane_steps_total += steps.total;
    }
  });
  stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.interrupted = stop_seen && done < members;
  return outcome;
}

}  // namespace rotorsweep::ensemble
