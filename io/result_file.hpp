// The output file of a sweep (README "Output file"): /members (one row per member, allocated
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

namespace rotorsweep::io {

/// Where a result came from.
struct Provenance {
  std::string scene_path;
  std::string version;
  std::string revision;  ///< source revision, "unknown" when the build could not tell
  std::string device;    ///< where members ran: "cpu" or "gpu (<name>)"
  std::string isa;       ///< instruction set of the sweeps' binary (ensemble::instruction_set), or a list
};

/// Writes the scene text and the provenance as attributes of a result file (scene, scene_path, version,
/// revision, device, isa).
void write_provenance(const Hdf5Location& file, const std::string& scene_text, const Provenance& provenance);

/// Which part of a plan a shard file holds (ensemble::shard_members).
struct ShardLabel {
  std::size_t index = 1, count = 1;  ///< part index of count, 1-based
  std::size_t plan_members = 0;      ///< members in the whole plan
};

/// A result file being written. From construction on it holds the scene, the provenance and every
/// /members column sized for its members; rows are written as members finish, each batch marked in
/// /members/done only after it is on disk, so the file is readable and resumable whenever the
/// process stops. complete = TRUE comes last, after /curves.
class ResultFile {
 public:
  /// Creates (truncates) path for the whole plan of `scene`, or for a shard's part of it (rows in
  /// the shard's plan order, /members/plan_index, attributes shard_index and shard_count).
  ResultFile(const std::string& path, const ensemble::Scene& scene, const Provenance& provenance,
             const std::optional<ShardLabel>& shard = std::nullopt);
  /// The same file in memory only (see image()).
  static ResultFile in_memory(const ensemble::Scene& scene, const Provenance& provenance);
  /// A file this class created (and did not finish), to write more rows into; `scene` is its scene.
  static ResultFile reopen(const std::string& path, const ensemble::Scene& scene);

  /// The row of plan member `plan_index` (which must belong to the file).
  hsize_t row_of(std::size_t plan_index) const;
  /// Members the file has rows for.
  std::size_t rows() const { return rows_; }

  /// Writes each result (in any order) into the row of its member (`plan` gives the members),
  /// flushes, then marks the rows done and flushes again.
  void write_results(const ensemble::MemberPlan& plan, std::vector<ensemble::MemberResult> results) const;
  /// /members/done: 1 for the rows written.
  std::vector<char> done() const;
  /// Run statistics, /curves computed from the file (not for shards), then complete = TRUE.
  void finish(const ensemble::SweepStatistics& statistics) const;
  /// Run statistics and members_done of a run that stopped early; complete stays FALSE. Like every
  /// write before finish(), it changes bytes in place and allocates nothing.
  void keep_partial(std::size_t members_done, const ensemble::SweepStatistics& statistics) const;
  /// Every member of the file at once (results held in memory), then finish().
  void write_sweep(const std::vector<ensemble::Member>& members, const ensemble::SweepOutcome& outcome) const;

  /// Closes the file; throws when its last buffers cannot be written.
  void close() { file_.close(); }
  /// The file's bytes (for a file in memory).
  std::vector<unsigned char> image() const { return file_.file_image(); }

 private:
  ResultFile(Hdf5Location file, const ensemble::Scene& scene, std::optional<ShardLabel> shard);
  void create(const Provenance& provenance) const;
  void write_rows(std::vector<hsize_t> rows, const std::vector<ensemble::Member>& members,
                  const std::vector<ensemble::MemberResult>& results) const;
  void write_statistics(const ensemble::SweepStatistics& statistics) const;
  /// Reserves disk blocks beyond the file's end for `bytes` of data still to come, so that a full
  /// disk stops finish() before it touches the file; throws when the disk cannot hold them.
  void reserve(double bytes) const;

  Hdf5Location file_;
  bool on_disk_ = false;
  ensemble::Scene scene_;
  std::vector<MemberColumn> columns_;
  std::optional<ShardLabel> shard_;
  std::size_t rows_ = 0;
};

}  // namespace rotorsweep::io
