// What every streamed result file shares, whatever its kind (docs/output.md "Output file"): rows
// allocated up front for the plan or a shard's part of it, /members/done marking rows on disk, the complete
// flag last.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "io/hdf5_file.hpp"

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

/// Disk bytes that finishing writes of `data_bytes` (the curves) take: the data twice over and room for
/// their groups' metadata. reserve() asks for them before those writes; the checks before a run count them.
double reserved_bytes(double data_bytes);

/// Which part of a plan a shard file holds: plan members index - 1, index - 1 + count, ...
/// (ensemble::shard_members).
struct ShardLabel {
  std::size_t index = 1, count = 1;  ///< part index of count, 1-based
  std::size_t plan_members = 0;      ///< members in the whole plan
};

/// The rows of a result file and their states. A kind of result (row sweeps, the slider) derives from
/// it, adds its columns, and writes rows through mark_done(); the file is readable and resumable
/// whenever the process stops, and says complete = TRUE only at the end.
class MemberTableFile {
 public:
  /// The row of plan member `plan_index` (which must belong to the file).
  hsize_t row_of(std::size_t plan_index) const;
  /// The plan member in row `row`.
  std::size_t plan_index_of(std::size_t row) const;
  /// Members the file has rows for.
  std::size_t rows() const { return rows_; }
  /// /members/done: 1 for the rows written.
  std::vector<char> done() const;
  /// Adds `isa` to the file's list of instruction sets that wrote its rows (attribute isa, ", "
  /// between names) when it is not there: a run resumed by another binary.
  void add_writer_isa(const std::string& isa) const;

  /// The shard label a file states (none for a whole plan); throws std::runtime_error where its
  /// shard_index and shard_count do not name a part I/N with 1 <= I <= N <= 10⁹.
  static std::optional<ShardLabel> shard_label(const Hdf5Location& file);

  /// Closes the file; throws when its last buffers cannot be written.
  void close() { file_.close(); }
  /// The file's bytes (for a file in memory).
  std::vector<unsigned char> image() const { return file_.file_image(); }

 protected:
  MemberTableFile(Hdf5Location file, std::size_t plan_members, std::optional<ShardLabel> shard);
  /// Checks what every kind of file states of its table against its scene: the attribute kind (none
  /// for row files), plan_members, a shard label within its plan, and /members/done and, in a shard,
  /// /members/plan_index of its rows; returns those rows. Throws std::runtime_error naming what differs.
  static hsize_t check_table(const Hdf5Location& file, const std::string& kind, std::size_t plan_members);

  /// Writes complete = FALSE, the scene and provenance, plan_members, members_done = 0,
  /// /members/done (all FALSE) and, in a shard, /members/plan_index; returns /members.
  Hdf5Location create_table(const std::string& scene_text, const Provenance& provenance) const;
  /// Runs `write_new` on the file just created at creating_path(path), closes it, renames it to `path`
  /// (so a process killed while creating it leaves no unreadable file at `path`) and opens it for writing:
  /// its length is then all it allocated, and nothing is allocated until the kind's finishing writes.
  /// Where `write_new` or the close fails (a full disk), the new file is removed and the error rethrown.
  void settle_on_disk(const std::string& path, const std::function<void()>& write_new);
  /// A reopened file: on disk, with the rows its /members/done marks.
  void adopt_reopened();
  /// After the rows' values: flushes, marks `rows` (not yet done) done and counts them in members_done,
  /// flushes again.
  void mark_done(const std::vector<hsize_t>& rows) const;
  /// members_done (a stopped run's count, or every row).
  void set_members_done(std::size_t count) const;
  /// complete = TRUE, after everything else is on disk.
  void set_complete() const;
  /// Reserves disk blocks beyond the file's end for `bytes` of data still to come, so that a full
  /// disk stops the finishing writes before they touch the file; throws when the disk cannot hold them.
  void reserve(double bytes, const std::string& what) const;

  Hdf5Location file_;
  std::optional<ShardLabel> shard_;
  std::size_t rows_ = 0;
  mutable std::size_t rows_done_ = 0;  ///< rows marked done (writing rows changes the file, not the object)
  bool on_disk_ = false;
};

}  // namespace rotorsweep::io
