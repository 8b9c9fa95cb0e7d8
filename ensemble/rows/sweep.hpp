// Runs a whole member plan (docs/architecture.md "Layers"): lane blocks on OpenMP threads take
// members from one shared counter; results land at their member index, whatever the order.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/scene.hpp"

namespace rotorsweep::ensemble {

struct SweepStatistics {
  double wall_seconds = 0;
  double kernel_seconds = 0;    ///< on a GPU: the time its sweep kernels ran (CUDA events); 0 on the CPU
  /// On a GPU, the host's side of the wall time: allocating a sweep's chunks (device and pinned host
  /// buffers, stream, events), filling chunks, waiting for the GPU, and delivering the returned chunks'
  /// results (summaries and the sink); 0 on the CPU.
  double setup_seconds = 0, fill_seconds = 0, wait_seconds = 0, deliver_seconds = 0;
  double lane_steps_busy = 0;   ///< Σ over step attempts of lanes that held a member
  double lane_steps_total = 0;  ///< Σ over step attempts of all lanes
  int threads = 1;
  std::size_t lane_width = 1;
  double occupancy() const { return lane_steps_total > 0 ? lane_steps_busy / lane_steps_total : 0.0; }
};

struct SweepOutcome {
  std::vector<MemberResult> results;  ///< results[i] belongs to members[i]
  /// Adds another part of the same sweep (its results go after these).
  void append(SweepOutcome&& part);
  SweepStatistics statistics;
  /// The stop flag was raised: members still in lanes were abandoned and members not yet
  /// started were skipped; their entries of results are default values, not results.
  bool interrupted = false;
  std::vector<char> finished;  ///< finished[i]: results[i] holds a result (all 1 unless interrupted)
};

/// Called now and then with the number of members finished (never from two threads at once).
using ProgressCallback = std::function<void(std::size_t done)>;

/// What a caller sees of a running sweep and how it stops one: progress (may be empty) and a
/// flag (may be null) that, once raised from any thread, ends the sweep within one step.
struct SweepControl {
  ProgressCallback progress;
  const std::atomic<bool>* stop = nullptr;
  /// Counts the periods members close (CPU lanes), and progress is also called after them: the
  /// progress of runs whose members are long (a few members of large N).
  std::atomic<std::size_t>* periods = nullptr;
  bool stopped() const { return stop != nullptr && stop->load(std::memory_order_relaxed); }
};

struct VariantRange;

/// The members a run takes, in plan order (ascending Member::index): how many, and the k-th.
struct MemberSource {
  std::size_t count = 0;
  std::function<Member(std::size_t k)> at;
  /// Optional: the next k of a range for this process to run (≥ range.end: none left), from a
  /// counter shared with other processes; called from any thread. Without it the threads share
  /// one counter per range.
  std::function<std::size_t(const VariantRange&)> claim;
};

/// Members [begin, end) of a source, all of one variant.
struct VariantRange {
  const MemberSource* source = nullptr;
  std::size_t begin = 0, end = 0;
};

/// Takes each finished member's result (MemberResult::index is its plan index); called from the
/// worker threads, possibly at the same time.
using ResultSink = std::function<void(MemberResult&&)>;

/// Runs the members of `source` (any part of the scene's plan, in plan order), handing each result
/// to `sink` as it finishes and keeping none: outcome.results stays empty. Members of different
/// variants run one variant after the other. Raising control.stop returns early with
/// outcome.interrupted set; members still in lanes are abandoned and reach no sink.
SweepOutcome run_members(const Scene& scene, const MemberSource& source, int threads,
                         const SweepControl& control, const ResultSink& sink);

/// Runs `members` (any subset of the scene's plan, in plan order) and returns their results in
/// the same order; members of different variants run one variant after the other. Raising
/// *stop returns early with outcome.interrupted set; *periods (where given) counts the periods
/// members close, as SweepControl::periods.
SweepOutcome run_sweep(const Scene& scene, const std::vector<Member>& members, int threads,
                       const ProgressCallback& progress, const std::atomic<bool>* stop = nullptr,
                       std::atomic<std::size_t>* periods = nullptr);

}  // namespace rotorsweep::ensemble
