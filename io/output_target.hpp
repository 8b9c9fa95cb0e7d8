// An output file written safely (docs/cli.md "Running a sweep"): checked before any work, written to a
// temporary file beside it, and put in place by rename only when complete, so nothing is lost.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rotorsweep::io {

/// A path that cannot be written: empty, a directory, one of the inputs, or an existing file
/// of another kind. The message names the path and the reason (exit code 2).
class OutputPathError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What an existing file at the target may be, to be replaced without --force: an HDF5 file (what the
/// HDF5 writers write), or a text file that starts with `text_signature` (what a CSV writer writes itself).
struct Replaceable {
  std::string text_signature;  ///< empty: an HDF5 file
  static const Replaceable hdf5;
  static Replaceable text_starting_with(std::string signature) { return {std::move(signature)}; }
};
inline const Replaceable Replaceable::hdf5{};

/// The output whose writer also writes the file named `name` beside it, and so holds the lock that
/// covers it: X for X.partial, X.partial.rank-R, .X.PID.part and .X.lock; empty for any other name.
std::string covering_output(const std::string& name);

/// Where a file that must appear whole is created before it is renamed to `path` (a partial file: a
/// process killed while creating it leaves this hidden name, which the output's next writer removes,
/// never an unreadable `path`): ".NAME.PID.part" beside it.
std::string creating_path(const std::string& path);

/// The file at `path` is written as a temporary file in the same directory, which commit()
/// renames over `path` (atomically: a reader sees the old file or the new one). Until then an
/// existing file at `path` is untouched; without commit() (an error, an exception) the temporary
/// file and the directories created for it are removed. For its whole life it holds a lock on the
/// path (flock on ".NAME.lock" beside it, which holds its PID), so that a second process writing
/// there is refused before it touches anything; the system drops the lock of a process that dies. A
/// path that another output's writer writes too (its partial or temporary file) also takes that
/// output's lock (covering_output), so neither can destroy the other's file; a lock file's name is
/// refused as an output. Once locked, temporary files of the output that a killed writer left behind
/// (".NAME.PID.part", ".NAME.partial.PID.part") are removed.
class OutputTarget {
 public:
  /// Checks the path and creates missing parent directories. Throws OutputPathError when the path
  /// is empty or names a directory, is the same file as one of `inputs` (also through a link),
  /// is an existing file that is not `replaceable` (unless `force`), or another process holds its
  /// lock or the lock of the output it belongs to (the message names its PID).
  /// With `resumable` the temporary file is path + ".partial", which keep() leaves in place.
  OutputTarget(const std::string& path, const std::vector<std::string>& inputs,
               const Replaceable& replaceable, bool force, bool resumable = false);
  OutputTarget(const OutputTarget&) = delete;
  OutputTarget& operator=(const OutputTarget&) = delete;
  ~OutputTarget();

  /// Where to write until commit().
  std::string temporary() const { return temporary_.string(); }
  /// The lock files this target holds: the target's own, then those of the outputs it belongs to
  /// (each removed with its lock).
  std::vector<std::string> lock_files() const;
  /// The final path as the user gave it.
  const std::string& path() const { return path_; }
  /// Whether commit() replaced an existing file.
  bool replaced() const { return replaced_; }
  /// The directories the constructor created for the path, innermost last.
  const std::vector<std::filesystem::path>& created_directories() const { return created_directories_; }

  /// Records which file the temporary is (device and inode), once the writer has created or reopened
  /// it: commit() and temporary_is_ours() compare with it.
  void claim_temporary();
  /// Whether the file at temporary() is still the one claim_temporary() recorded (nobody replaced or
  /// removed it).
  bool temporary_is_ours() const;
  /// Renames the temporary file over the target, after checking that it is still the file this
  /// writer claimed. Throws std::runtime_error saying why not, or with the OS reason.
  void commit();
  /// Leaves the temporary file where it is (an unfinished run to resume).
  void keep() { committed_ = true; }

 private:
  std::string path_;
  std::filesystem::path target_;                            ///< path_, through a symbolic link to its target
  std::filesystem::path temporary_;                         ///< beside target_
  std::vector<std::filesystem::path> created_directories_;  ///< innermost last
  bool replaced_ = false;
  bool committed_ = false;
  struct HeldLock {
    std::filesystem::path path;  ///< ".NAME.lock" beside the output it covers
    int fd = -1;                 ///< holds the flock
  };
  std::vector<HeldLock> locks_;                     ///< the target's own, then its covering outputs'
  std::optional<std::pair<dev_t, ino_t>> claimed_;  ///< the temporary file's identity

  /// Takes the lock of the output `output` (a path; `name`: the target as given, in quotes); false when
  /// this target holds it already. Throws OutputPathError beginning with `refusal` when another process
  /// holds it.
  bool lock(const std::filesystem::path& output, const std::string& name, const std::string& refusal);
  void unlock();
};

/// Whether the file at `path` starts with the HDF5 signature (at 0, 512, 1024, ... bytes).
bool is_hdf5_file(const std::filesystem::path& path);

}  // namespace rotorsweep::io
