// The output file of a sweep (docs/output.md "Output file"): /members (one row per member, allocated
// up front and filled as members finish, /members/done marking them), /curves and root attributes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/hdf5_file.hpp"
#include "io/member_columns.hpp"
#include "io/member_table_file.hpp"

namespace rotorsweep::io {

/// A result file being written. From construction on it holds the scene, the provenance and every
/// /members column sized for its members; rows are written as members finish, each batch marked in
/// /members/done only after it is on disk, so the file is readable and resumable whenever the
/// process stops. complete = TRUE comes last, after /curves.
class ResultFile : public MemberTableFile {
 public:
  /// Creates (truncates) path for the whole plan of `scene`, or for a shard's part of it (rows in
  /// the shard's plan order, /members/plan_index, attributes shard_index and shard_count).
  ResultFile(const std::string& path, const ensemble::Scene& scene, const Provenance& provenance,
             const std::optional<ShardLabel>& shard = std::nullopt);
  /// The same file in memory only (see image()).
  static ResultFile in_memory(const ensemble::Scene& scene, const Provenance& provenance);
  /// A file this class created (and did not finish), to write more rows into; `scene` is its scene.
  static ResultFile reopen(const std::string& path, const ensemble::Scene& scene);

  /// Throws std::runtime_error naming what differs where `file` (a partial or shard file) is not what this
  /// class writes for `scene`: its attributes kind, plan_members and shard label, and every /members
  /// dataset's shape and type (MemberTableFile::check_table, check_table_columns).
  static void check_file(const Hdf5Location& file, const ensemble::Scene& scene);
  /// Disk bytes the finishing writes of a file of `scene` need (its /curves, none in a shard), counted
  /// before a run starts or resumes (the attractor labels estimated).
  static double finishing_bytes(const ensemble::Scene& scene, bool shard);

  /// Writes each result (in any order) into the row of its member (`plan` gives the members),
  /// flushes, then marks the rows done and flushes again.
  void write_results(const ensemble::MemberPlan& plan,
                     const std::vector<ensemble::MemberResult>& results) const;
  /// Member `member`'s row of every /members column, for write_packed (on any thread).
  PackedRow pack(const ensemble::Member& member, const ensemble::MemberResult& result) const;
  /// write_results for rows already packed.
  void write_packed(std::vector<PackedRow> rows) const;
  /// The run statistics an earlier part of the run recorded (keep_partial): its wall time, threads, lane
  /// width and occupancy; where none were recorded (that part was killed), `threads` and `lane_width`.
  ensemble::SweepStatistics recorded_statistics(int threads, std::size_t lane_width) const;
  /// Run statistics, /curves computed from the file (not for shards), then complete = TRUE.
  void finish(const ensemble::SweepStatistics& statistics) const;
  /// Run statistics and members_done of a run that stopped early; complete stays FALSE. Like every
  /// write before finish(), it changes bytes in place and allocates nothing.
  void keep_partial(std::size_t members_done, const ensemble::SweepStatistics& statistics) const;

 private:
  ResultFile(Hdf5Location file, const ensemble::Scene& scene, std::optional<ShardLabel> shard);
  void create(const Provenance& provenance) const;
  void write_statistics(const ensemble::SweepStatistics& statistics) const;

  ensemble::Scene scene_;
  std::vector<MemberColumn> columns_;
};

}  // namespace rotorsweep::io
