// OutputTarget: the checks on an output path, the temporary file beside it, and the rename that
// puts a complete file in place (or the clean-up that leaves no trace of a failed one).
#include "io/output_target.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cstring>
#include <fstream>

namespace rotorsweep::io {

namespace fs = std::filesystem;

namespace {

std::string in_quotes(const std::string& path) { return "'" + path + "'"; }

bool ends_with(const std::string& text, const std::string& end) {
  return text.size() > end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

/// `path` through its symbolic links (also dangling ones) to the file they finally name; `name` is
/// the path as given, for messages. A link's relative target is relative to the directory that holds the
/// link physically, so that directory and the target's own directories are resolved through their links
/// first (a link sub/out.h5 → ../x.h5, sub a link to real/sub, names real/x.h5, not x.h5).
fs::path through_links(fs::path path, const std::string& name) {
  std::error_code error;
  for (int hops = 0; fs::is_symlink(fs::symlink_status(path, error)); ++hops) {
    if (hops == 40) throw OutputPathError("output path " + name + ": too many levels of symbolic links");
    const fs::path next = fs::read_symlink(path, error);
    if (error) throw OutputPathError("output path " + name + ": " + error.message());
    const fs::path holder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    const fs::path directory =
        fs::weakly_canonical((next.is_absolute() ? fs::path() : holder) / next.parent_path(), error);
    if (error) throw OutputPathError("output path " + name + ": " + error.message());
    path = directory / next.filename();
  }
  return path;
}

/// Whether `name` is the lock file of an output (".X.lock"), which its writer creates and removes.
bool lock_file_name(const std::string& name) {
  return name.size() > 6 && name.front() == '.' && ends_with(name, ".lock");
}

/// Whether `name` is a writer's temporary file of the output named `output`: ".output.PID.part", or while
/// its partial or rank file is created ".output.partial.PID.part", ".output.partial.rank-R.PID.part".
bool temporary_of(const std::string& name, const std::string& output) {
  const std::string stem = "." + output + ".";
  if (name.size() <= stem.size() + 5 || name.compare(0, stem.size(), stem) != 0 || !ends_with(name, ".part"))
    return false;
  std::string middle = name.substr(stem.size(), name.size() - stem.size() - 5);  // [partial[.rank-R].]PID
  const auto digits = [](const std::string& text) {
    return !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
  };
  const auto dot = middle.rfind('.');
  if (dot == std::string::npos) return digits(middle);
  const std::string kind = middle.substr(0, dot);
  return digits(middle.substr(dot + 1)) &&
         (kind == "partial" || (kind.rfind("partial.rank-", 0) == 0 && digits(kind.substr(13))));
}

/// Whether the file at `path` starts with `text`.
bool starts_with_text(const fs::path& path, const std::string& text) {
  std::ifstream in(path, std::ios::binary);
  std::string start(text.size(), '\0');
  return in.read(start.data(), std::streamsize(start.size())) && start == text;
}

}  // namespace

std::string covering_output(const std::string& name) {
  if (ends_with(name, ".partial")) return name.substr(0, name.size() - 8);
  if (const auto rank = name.rfind(".partial.rank-");
      rank != std::string::npos && rank > 0 && rank + 14 < name.size() &&
      name.find_first_not_of("0123456789", rank + 14) == std::string::npos)
    return name.substr(0, rank);
  if (name.size() < 2 || name.front() != '.') return "";
  if (ends_with(name, ".lock")) return name.substr(1, name.size() - 6);
  if (!ends_with(name, ".part")) return "";
  const std::string stem = name.substr(1, name.size() - 6);  // "X.PID"
  const auto dot = stem.rfind('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == stem.size() ||
      stem.find_first_not_of("0123456789", dot + 1) != std::string::npos)
    return "";
  return stem.substr(0, dot);
}

std::string creating_path(const std::string& path) {
  const fs::path at(path);
  return (at.parent_path() / ("." + at.filename().string() + "." + std::to_string(::getpid()) + ".part"))
      .string();
}

bool is_hdf5_file(const fs::path& path) {
  static constexpr std::array<char, 8> signature{'\x89', 'H', 'D', 'F', '\r', '\n', '\x1a', '\n'};
  std::ifstream in(path, std::ios::binary);
  std::error_code error;
  const auto size = fs::file_size(path, error);
  if (!in || error) return false;
  for (std::uintmax_t offset = 0; offset + signature.size() <= size; offset = offset ? 2 * offset : 512) {
    std::array<char, 8> bytes{};
    in.seekg(std::streamoff(offset));
    if (!in.read(bytes.data(), bytes.size())) return false;
    if (bytes == signature) return true;
  }
  return false;
}

OutputTarget::OutputTarget(const std::string& path, const std::vector<std::string>& inputs,
                           const Replaceable& replaceable, bool force, bool resumable)
    : path_(path) {
  if (path.empty()) throw OutputPathError("the output path is empty");
  if (path.find('\0') != std::string::npos)
    throw OutputPathError("output path " + in_quotes(path.substr(0, path.find('\0'))) +
                          "<NUL>… contains a NUL byte, where the system would cut the name short");
  const std::string name = in_quotes(path);
  // the temporary file beside it adds at most ".", "." + a process id and ".part" to the name
  const std::size_t name_bytes = fs::path(path).filename().string().size(), temporary_extra = 14;
  if (name_bytes + temporary_extra > NAME_MAX)
    throw OutputPathError("output path " + name + ": its file name has " + std::to_string(name_bytes) +
                          " bytes; at most " + std::to_string(NAME_MAX - temporary_extra) +
                          " are allowed (the temporary file beside it needs the rest of the system's " +
                          std::to_string(NAME_MAX) + ")");
  if (path.back() == '/' || fs::path(path).filename() == "." || fs::path(path).filename() == "..")
    throw OutputPathError("output path " + name + " names a directory; give a file name");
  std::error_code error;
  // through symbolic links (also dangling ones, whose target is then created): write beside the
  // final target and replace that file, so the links stay links
  target_ = through_links(fs::path(path), name);
  if (lock_file_name(target_.filename().string()))
    throw OutputPathError(
        "output path " + name + " is named as a lock file (" + in_quotes(target_.filename().string()) +
        ", which the writer of the output it names creates and removes); choose another name");
  const fs::file_status status = fs::status(target_, error);
  const bool exists = fs::exists(status);
  if (exists && fs::is_directory(status)) throw OutputPathError("output path " + name + " is a directory");
  if (exists && !fs::is_regular_file(status))
    throw OutputPathError("output path " + name + " is not a regular file (a FIFO, socket or device)");
  for (const auto& input : inputs)
    if (exists && fs::equivalent(target_, input, error))
      throw OutputPathError("output path " + name + " is the input file " + in_quotes(input) +
                            "; writing it would destroy it");
  if (exists && !force && replaceable.text_signature.empty() && !is_hdf5_file(target_))
    throw OutputPathError(
        "output path " + name +
        " exists and is not an HDF5 file; refusing to replace it (use --force to replace it)");
  if (exists && !force && !replaceable.text_signature.empty() &&
      !starts_with_text(target_, replaceable.text_signature))
    throw OutputPathError("output path " + name +
                          " exists and is not a table this command wrote (its first line does not start "
                          "with '" +
                          replaceable.text_signature +
                          "'); refusing to replace it (use --force to replace it)");
  replaced_ = exists;

  // missing parent directories, created outermost first and removed again on failure
  const fs::path parent = target_.parent_path();
  std::vector<fs::path> missing;
  for (fs::path p = parent; !p.empty() && !fs::exists(p, error); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, error) && error) {
      const std::string reason = error.message();
      for (auto d = created_directories_.rbegin(); d != created_directories_.rend(); ++d)
        fs::remove(*d, error);
      throw OutputPathError("output path " + name + ": cannot create directory " + in_quotes(it->string()) +
                            ": " + reason);
    }
    created_directories_.push_back(*it);
  }
  if (!parent.empty() && !fs::is_directory(parent, error))
    throw OutputPathError("output path " + name + ": " + in_quotes(parent.string()) + " is not a directory");
  if (::access(parent.empty() ? "." : parent.c_str(), W_OK) != 0)
    throw OutputPathError("output path " + name + ": cannot write in its directory: " + std::strerror(errno));
  try {
    lock(target_, name, "output path " + name + " is being written by another process");
    // the partial, temporary or lock file of another output: its writer's lock covers this one too
    for (fs::path at = target_;;) {
      const std::string owner = covering_output(at.filename().string());
      if (owner.empty()) break;
      at = through_links(at.parent_path() / owner, in_quotes((at.parent_path() / owner).string()));
      if (!lock(at, name,
                "output path " + name + " belongs to the output " + in_quotes(at.string()) +
                    " (its partial, temporary or lock file), which is being written by another process"))
        break;  // a link back to an output already locked
    }
  } catch (...) {
    unlock();
    for (auto d = created_directories_.rbegin(); d != created_directories_.rend(); ++d) fs::remove(*d, error);
    throw;
  }
  // temporary files of this output left by a writer that was killed: no live writer has one, since each
  // holds the lock this target now holds
  const std::string own = target_.filename().string();
  for (const auto& entry : fs::directory_iterator(parent.empty() ? fs::path(".") : parent, error))
    if (temporary_of(entry.path().filename().string(), own)) fs::remove(entry.path(), error);
  if (resumable) {
    temporary_ = target_;
    temporary_ += ".partial";
    return;
  }
  std::string hidden_name(1, '.');
  hidden_name.append(target_.filename().string())
      .append(".")
      .append(std::to_string(::getpid()))
      .append(".part");
  temporary_ = parent / hidden_name;
}

bool OutputTarget::lock(const fs::path& output, const std::string& name, const std::string& refusal) {
  std::string lock_name(1, '.');
  lock_name.append(output.filename().string()).append(".lock");
  const fs::path lock_path = output.parent_path() / lock_name;
  for (const auto& held : locks_)
    if (held.path == lock_path) return false;
  for (int attempt = 0; attempt < 16; ++attempt) {
    const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw OutputPathError("output path " + name + ": cannot create the lock file " +
                            in_quotes(lock_path.string()) + ": " + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      std::array<char, 32> pid{};
      const ssize_t n = ::pread(fd, pid.data(), pid.size() - 1, 0);
      ::close(fd);
      std::string holder(pid.data(), std::size_t(std::max<ssize_t>(n, 0)));
      while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
      // a second writer in this very process (two jobs of one Python session) is no other process
      std::string said = refusal;
      const std::string other = "another process";
      if (holder == std::to_string(::getpid()) && ends_with(said, other))
        said.replace(said.size() - other.size(), other.size(), "another job of this process");
      throw OutputPathError(said + (holder.empty() ? std::string() : " (PID " + holder + ")") +
                            "; wait for it to finish, or stop it and resume, or choose another output");
    }
    // the holder may have removed the file between our open and our lock: then take the new one
    struct stat held {
    }, named{};
    if (::fstat(fd, &held) == 0 && ::stat(lock_path.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      const std::string text = std::to_string(::getpid()) + "\n";
      // the PID only makes another process's message more helpful: a failed write is no error
      [[maybe_unused]] const bool written =
          ::ftruncate(fd, 0) == 0 && ::pwrite(fd, text.data(), text.size(), 0) == ssize_t(text.size());
      locks_.push_back({lock_path, fd});
      return true;
    }
    ::close(fd);
  }
  throw OutputPathError("output path " + name + ": the lock file " + in_quotes(lock_path.string()) +
                        " keeps changing; another process is writing there");
}

void OutputTarget::unlock() {
  std::error_code error;
  for (auto held = locks_.rbegin(); held != locks_.rend(); ++held) {
    fs::remove(held->path, error);  // before closing: nobody else can hold it meanwhile
    ::close(held->fd);
  }
  locks_.clear();
}

std::vector<std::string> OutputTarget::lock_files() const {
  std::vector<std::string> paths;
  for (const auto& held : locks_) paths.push_back(held.path.string());
  return paths;
}

void OutputTarget::claim_temporary() {
  struct stat status {};
  if (::stat(temporary_.c_str(), &status) != 0)
    throw std::runtime_error("cannot find the file just written, " + in_quotes(temporary_.string()) + ": " +
                             std::strerror(errno));
  claimed_ = std::pair{status.st_dev, status.st_ino};
}

bool OutputTarget::temporary_is_ours() const {
  struct stat status {};
  return claimed_ && ::stat(temporary_.c_str(), &status) == 0 &&
         std::pair{status.st_dev, status.st_ino} == *claimed_;
}

OutputTarget::~OutputTarget() {
  unlock();
  if (committed_) return;
  std::error_code error;
  fs::remove(temporary_, error);
  for (auto d = created_directories_.rbegin(); d != created_directories_.rend(); ++d) fs::remove(*d, error);
}

void OutputTarget::commit() {
  if (!claimed_) throw std::logic_error("OutputTarget::commit() before claim_temporary()");
  if (!temporary_is_ours())
    throw std::runtime_error(in_quotes(temporary_.string()) +
                             " is no longer the file this process wrote (another process replaced or removed "
                             "it): it is not moved into place as " +
                             in_quotes(path_));
  std::error_code error;
  fs::rename(temporary_, target_, error);
  if (error)
    throw std::runtime_error("cannot move the finished file into place as " + in_quotes(path_) + ": " +
                             error.message());
  committed_ = true;
}

}  // namespace rotorsweep::io
