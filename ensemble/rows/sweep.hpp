// Runs a whole member plan (docs/architecture.md "Layers"): lane blocks on OpenMP threads take
// members from one shared counter; results land at their member index, whatever the order.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "ensemble/engine/run_control.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/scene.hpp"

namespace rotorsweep::ensemble {

struct SweepOutcome : RunOutcome {
  std::vector<MemberResult> results;  ///< run_sweep's: results[i] belongs to members[i]
  std::vector<char> finished;         ///< finished[i]: results[i] holds a result (all 1 unless interrupted)
  /// Adds another part of the same sweep (its results go after these).
  void append(SweepOutcome&& part);
};

/// The members a run takes, in plan order (ascending Member::index): how many, and the k-th.
struct MemberSource {
  std::size_t count = 0;
  std::function<Member(std::size_t k)> at;
};

/// Members [begin, end) of a source, all of one variant.
struct VariantRange {
  const MemberSource* source = nullptr;
  std::size_t begin = 0, end = 0;
};

/// Takes each finished member's result (MemberResult::index is its plan index); called from the
/// worker threads, possibly at the same time.
using ResultSink = std::function<void(MemberResult&&)>;

/// An executor that runs a variant's members off the CPU's lanes (the GPU's: ensemble/gpu/gpu_executor.hpp),
/// handed to run_members by its caller: the sweep names no backend.
class RowDevice {
 public:
  virtual ~RowDevice() = default;
  /// Runs the members of `range` (one variant) as run_members does.
  virtual SweepOutcome run_variant(const Scene& scene, const VariantRange& range, const RunControl& control,
                                   const ResultSink& sink) const = 0;
};

/// Runs the members of `source` (any part of the scene's plan, in plan order), handing each result
/// to `sink` as it finishes and keeping none: outcome.results stays empty. Members of different
/// variants run one variant after the other; control.claim, where set, is asked for positions k of
/// the source within one variant's members; control.stops counts the periods members close. A stop
/// returns early with outcome.interrupted set; members still in lanes are abandoned and reach no sink.
/// A scene with numerics.device = "gpu" runs on `device` (an error where there is none).
SweepOutcome run_members(const Scene& scene, const MemberSource& source, const RunControl& control,
                         const ResultSink& sink, const RowDevice* device = nullptr);

/// Runs `members` (any subset of the scene's plan, in plan order) as run_members does and returns
/// their results in the same order.
SweepOutcome run_sweep(const Scene& scene, const std::vector<Member>& members, const RunControl& control = {},
                       const RowDevice* device = nullptr);

}  // namespace rotorsweep::ensemble
