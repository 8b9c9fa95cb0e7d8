// The run API of every problem (docs/architecture.md "The run API"): how a caller runs members (threads,
// progress, stop, a claim shared with other processes) and what it gets back, for rows and slider alike.
#pragma once

#include <omp.h>

#include <atomic>
#include <cstddef>
#include <functional>

namespace rotorsweep::ensemble {

/// Positions [begin, end) of a run's members that run together (a row variant, a slider size; on a
/// device a slider's size and speed): what RunControl::claim hands out.
struct PositionRange {
  std::size_t begin = 0, end = 0;
};

/// How members run and stop. Every part may be left empty.
struct RunControl {
  int threads = 0;  ///< OpenMP threads (on a GPU: the host's, for fills and summaries); 0: OpenMP's default
  /// Members finished so far (handed to the sink); never called from two threads at once.
  std::function<void(std::size_t done)> progress = {};
  /// Asked from any thread: once true, no member starts and the running ones are abandoned within one
  /// step (the run's outcome is then interrupted where members were left out).
  std::function<bool()> stop = {};
  /// Counts the stops members close on the CPU's lanes (a row member's periods, a slider member's
  /// samples), and progress is also called after them: the progress of runs whose members are long.
  std::atomic<std::size_t>* stops = nullptr;
  /// The next position in [begin, end) — a group the problem runs together — for this process to run
  /// (≥ end: none left), from a counter shared with other processes (the ranks of mpirun); called from
  /// any thread. Without it the threads share one counter per group.
  std::function<std::size_t(std::size_t begin, std::size_t end)> claim = {};

  bool stopped() const { return stop && stop(); }
  int thread_count() const { return threads > 0 ? threads : omp_get_max_threads(); }
  /// The next position of [begin, end) through claim, else from `counter` (shared by this process's
  /// threads, starting at begin).
  std::size_t next(std::size_t begin, std::size_t end, std::atomic<std::size_t>& counter) const {
    return claim ? claim(begin, end) : counter.fetch_add(1, std::memory_order_relaxed);
  }
};

/// Where a run's time went.
struct SweepStatistics {
  double wall_seconds = 0;
  double kernel_seconds = 0;  ///< on a GPU: the time its kernels ran (CUDA events); 0 on the CPU
  /// On a GPU, the host's side of the wall time: allocating a run's chunks (device and pinned host
  /// buffers, stream, events), filling chunks, waiting for the GPU, and delivering the returned chunks'
  /// results (summaries and the sink); 0 on the CPU.
  double setup_seconds = 0, fill_seconds = 0, wait_seconds = 0, deliver_seconds = 0;
  double lane_steps_busy = 0;   ///< Σ over step attempts of lanes that held a member
  double lane_steps_total = 0;  ///< Σ over step attempts of all lanes
  int threads = 1;
  std::size_t lane_width = 1;
  double occupancy() const { return lane_steps_total > 0 ? lane_steps_busy / lane_steps_total : 0.0; }
  /// Adds another part of the same run (its threads and lane width are the last part's).
  void add(const SweepStatistics& part) {
    wall_seconds += part.wall_seconds;
    kernel_seconds += part.kernel_seconds;
    setup_seconds += part.setup_seconds;
    fill_seconds += part.fill_seconds;
    wait_seconds += part.wait_seconds;
    deliver_seconds += part.deliver_seconds;
    lane_steps_busy += part.lane_steps_busy;
    lane_steps_total += part.lane_steps_total;
    threads = part.threads;
    lane_width = part.lane_width;
  }
};

/// What a run gives back besides the members its sink took.
struct RunOutcome {
  SweepStatistics statistics;
  /// The stop was raised and members were left out: those still running were abandoned and those not
  /// started were skipped.
  bool interrupted = false;
};

}  // namespace rotorsweep::ensemble
