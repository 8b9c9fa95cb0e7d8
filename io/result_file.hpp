// The output file of a sweep (README "Output file"): /members (one row per member),
// /members/periods (per-period series), /curves (per-point statistics) and root attributes.
#pragma once

#include <string>
#include <vector>

#include "ensemble/curves.hpp"
#include "ensemble/member_plan.hpp"
#include "ensemble/scene.hpp"
#include "ensemble/sweep.hpp"
#include "io/hdf5_file.hpp"

namespace rotorsweep::io {

/// Where a result came from.
struct Provenance {
  std::string scene_path;
  std::string version;
  std::string revision;  ///< source revision, "unknown" when the build could not tell
};

/// Which part of a plan a shard file holds (ensemble::shard_members).
struct ShardLabel {
  std::size_t index = 1, count = 1;  ///< part index of count, 1-based
  std::size_t plan_members = 0;      ///< members in the whole plan
};

/// A result file being written: it exists with complete = FALSE from construction on, and
/// says complete = TRUE only after every dataset has been written and flushed.
class ResultFile {
 public:
  /// Creates (truncates) path and writes the scene and provenance (see io/output_target.hpp for
  /// writing beside the final path).
  ResultFile(const std::string& path, const ensemble::Scene& scene, const Provenance& provenance);
  /// The same file in memory only (see image()).
  static ResultFile in_memory(const ensemble::Scene& scene, const Provenance& provenance);

  /// Members, curves (aggregated from them) and statistics: everything after the constructor.
  void write_sweep(const ensemble::Scene& scene, const std::vector<ensemble::Member>& members,
                   const ensemble::SweepOutcome& outcome) const;
  /// A shard's members, their plan indices (/members/plan_index) and the shard's label as
  /// attributes shard_index, shard_count, plan_members; no curves (`rotorsweep merge` makes them).
  void write_shard(const ensemble::Scene& scene, const std::vector<ensemble::Member>& members,
                   const ensemble::SweepOutcome& outcome, const ShardLabel& shard) const;
  /// The finished members of an interrupted run, laid out like a shard's, with the attributes
  /// members_done and plan_members; complete stays FALSE (`run --resume` continues from it).
  void write_partial(const ensemble::Scene& scene, const std::vector<ensemble::Member>& members,
                     const std::vector<ensemble::MemberResult>& results, std::size_t plan_members,
                     const ensemble::SweepStatistics& statistics) const;

  void write_members(const ensemble::Scene& scene, const std::vector<ensemble::Member>& members,
                     const std::vector<ensemble::MemberResult>& results) const;
  void write_curves(const ensemble::Scene& scene, const std::vector<ensemble::CurvePoint>& curves) const;
  /// Run statistics, then complete = TRUE.
  void finish(const ensemble::SweepStatistics& statistics) const;
  /// Closes the file; throws when its last buffers cannot be written.
  void close() { file_.close(); }
  /// The file's bytes (for a file in memory).
  std::vector<unsigned char> image() const { return file_.file_image(); }

 private:
  ResultFile(Hdf5Location file, const ensemble::Scene& scene, const Provenance& provenance);
  /// /members of a part of the plan, with /members/plan_index.
  void write_part(const ensemble::Scene& scene, const std::vector<ensemble::Member>& members,
                  const std::vector<ensemble::MemberResult>& results) const;
  void write_statistics(const ensemble::SweepStatistics& statistics) const;
  Hdf5Location file_;
};

}  // namespace rotorsweep::io
