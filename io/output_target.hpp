// An output file written safely (README "Output file"): checked before any work, written to a
// temporary file beside it, and put in place by rename only when complete, so nothing is lost.
#pragma once

#include <filesystem>
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

/// What an existing file at the target may be, to be replaced without --force.
enum class Replaceable { hdf5, any };

/// The file at `path` is written as a temporary file in the same directory, which commit()
/// renames over `path` (atomically: a reader sees the old file or the new one). Until then an
/// existing file at `path` is untouched; without commit() (an error, an exception) the temporary
/// file and the directories created for it are removed. For its whole life it holds a lock on the
/// path (flock on ".NAME.lock" beside it, which holds its PID), so that a second process writing
/// there is refused before it touches anything; the system drops the lock of a process that dies.
class OutputTarget {
 public:
  /// Checks the path and creates missing parent directories. Throws OutputPathError when the path
  /// is empty or names a directory, is the same file as one of `inputs` (also through a link),
  /// is an existing file that is not `replaceable` (unless `force`), or another process holds its
  /// lock (the message names its PID).
  /// With `resumable` the temporary file is path + ".partial", which keep() leaves in place.
  OutputTarget(const std::string& path, const std::vector<std::string>& inputs, Replaceable replaceable,
               bool force, bool resumable = false);
  OutputTarget(const OutputTarget&) = delete;
  OutputTarget& operator=(const OutputTarget&) = delete;
  ~OutputTarget();

  /// Where to write until commit().
  std::string temporary() const { return temporary_.string(); }
  /// The lock file beside the target (removed with the target's lock).
  std::string lock_file() const { return lock_path_.string(); }
  /// The final path as the user gave it.
  const std::string& path() const { return path_; }
  /// Whether commit() replaced an existing file.
  bool replaced() const { return replaced_; }
  /// The directories the constructor created for the path, innermost last.
  const std::vector<std::filesystem::path>& created_directories() const { return created_directories_; }

  /// Renames the temporary file over the target. Throws std::runtime_error with the OS reason.
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
  std::filesystem::path lock_path_;  ///< ".NAME.lock" beside target_
  int lock_fd_ = -1;                 ///< holds the flock

  void lock(const std::filesystem::path& parent, const std::string& name);
  void unlock();
};

/// Whether the file at `path` starts with the HDF5 signature (at 0, 512, 1024, ... bytes).
bool is_hdf5_file(const std::filesystem::path& path);

}  // namespace rotorsweep::io
