// The slider scan's HDF5 result file (docs/output.md "The slider's result file"): per member its
// separation, mean friction, per-period friction and energy balance, order parameters and time series,
// all in SI units.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ensemble/slider/slider_scene.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "io/member_table_file.hpp"
#include "io/table_columns.hpp"

namespace rotorsweep::io {

/// One column of a slider file, below its root ("members/friction", "series/angles").
using SliderColumn = TableColumn<ensemble::SliderMember>;

/// Every column of /members and /series the scene asks for, in the order they are created.
std::vector<SliderColumn> slider_columns(const ensemble::SliderScene& scene,
                                         const ensemble::SliderTimeline& timeline);

/// A slider file being written, like a row sweep's (MemberTableFile): from construction on it holds
/// the scene, the provenance and every column sized for its members; members are written as they
/// finish; /curve and complete = TRUE come last.
class SliderResultFile : public MemberTableFile {
 public:
  /// Creates (truncates) path for the whole plan of `scene`, or for a shard's part of it.
  SliderResultFile(const std::string& path, const ensemble::SliderScene& scene, const Provenance& provenance,
                   const std::optional<ShardLabel>& shard = std::nullopt);
  /// A file this class created (and did not finish), to write more members into.
  static SliderResultFile reopen(const std::string& path, const ensemble::SliderScene& scene);

  /// Throws std::runtime_error naming what differs where `file` (a partial or shard file) is not what this
  /// class writes for `scene`: its attributes kind, plan_members and shard label, and every /members and
  /// /series dataset's shape and type.
  static void check_file(const Hdf5Location& file, const ensemble::SliderScene& scene);
  /// Disk bytes the finishing writes of a file of `scene` need (its /curve, none in a shard).
  static double finishing_bytes(const ensemble::SliderScene& scene, bool shard);

  /// Writes the members (of any rows of the file) and marks their rows done.
  void write_members(const std::vector<ensemble::SliderMember>& members) const;
  /// Copies the rows marked done in `source`, a file of the same scene (a shard, or a whole plan's
  /// file written in part), into their rows here and marks them done; returns how many.
  std::size_t copy_done_rows(const Hdf5Location& source) const;
  /// wall_seconds and threads of a run that stopped early with `members_done` rows; complete stays FALSE.
  void keep_partial(std::size_t members_done, double wall_seconds, int threads) const;
  /// wall_seconds and threads, /curve from the file's rows (not for shards), then complete = TRUE.
  void finish(double wall_seconds, int threads) const;

 private:
  SliderResultFile(Hdf5Location file, const ensemble::SliderScene& scene, std::optional<ShardLabel> shard);
  void create(const Provenance& provenance) const;

  ensemble::SliderScene scene_;
  ensemble::SliderTimeline timeline_;
  std::vector<SliderColumn> columns_;
};

}  // namespace rotorsweep::io
