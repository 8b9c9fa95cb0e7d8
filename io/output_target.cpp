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

}  // namespace

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
                           Replaceable replaceable, bool force, bool resumable)
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
  target_ = fs::path(path);
  // through symbolic links (also dangling ones, whose target is then created): write beside the
  // final target and replace that file, so the links stay links
  for (int hops = 0; fs::is_symlink(fs::symlink_status(target_, error)); ++hops) {
    if (hops == 40) throw OutputPathError("output path " + name + ": too many levels of symbolic links");
    const fs::path next = fs::read_symlink(target_, error);
    if (error) throw OutputPathError("output path " + name + ": " + error.message());
    target_ = (next.is_absolute() ? next : target_.parent_path() / next).lexically_normal();
  }
  const fs::file_status status = fs::status(target_, error);
  const bool exists = fs::exists(status);
  if (exists && fs::is_directory(status)) throw OutputPathError("output path " + name + " is a directory");
  if (exists && !fs::is_regular_file(status))
    throw OutputPathError("output path " + name + " is not a regular file (a FIFO, socket or device)");
  for (const auto& input : inputs)
    if (exists && fs::equivalent(target_, input, error))
      throw OutputPathError("output path " + name + " is the input file " + in_quotes(input) +
                            "; writing it would destroy it");
  if (exists && replaceable == Replaceable::hdf5 && !force && !is_hdf5_file(target_))
    throw OutputPathError(
        "output path " + name +
        " exists and is not an HDF5 file; refusing to replace it (use --force to replace it)");
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
  lock(parent, name);
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

void OutputTarget::lock(const fs::path& parent, const std::string& name) {
  std::string lock_name(1, '.');
  lock_name.append(target_.filename().string()).append(".lock");
  lock_path_ = parent / lock_name;
  for (int attempt = 0; attempt < 16; ++attempt) {
    const int fd = ::open(lock_path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw OutputPathError("output path " + name + ": cannot create its lock file " +
                            in_quotes(lock_path_.string()) + ": " + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      std::array<char, 32> pid{};
      const ssize_t n = ::pread(fd, pid.data(), pid.size() - 1, 0);
      ::close(fd);
      std::string holder(pid.data(), std::size_t(std::max<ssize_t>(n, 0)));
      while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' ')) holder.pop_back();
      throw OutputPathError("output path " + name + " is being written by another process" +
                            (holder.empty() ? std::string() : " (PID " + holder + ")") +
                            "; wait for it to finish, or stop it and resume, or choose another output");
    }
    // the holder may have removed the file between our open and our lock: then take the new one
    struct stat held {
    }, named{};
    if (::fstat(fd, &held) == 0 && ::stat(lock_path_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      const std::string text = std::to_string(::getpid()) + "\n";
      // the PID only makes another process's message more helpful: a failed write is no error
      [[maybe_unused]] const bool written =
          ::ftruncate(fd, 0) == 0 && ::pwrite(fd, text.data(), text.size(), 0) == ssize_t(text.size());
      lock_fd_ = fd;
      return;
    }
    ::close(fd);
  }
  throw OutputPathError("output path " + name + ": its lock file " + in_quotes(lock_path_.string()) +
                        " keeps changing; another process is writing there");
}

void OutputTarget::unlock() {
  if (lock_fd_ < 0) return;
  std::error_code error;
  fs::remove(lock_path_, error);  // before closing: nobody else can hold it meanwhile
  ::close(lock_fd_);
  lock_fd_ = -1;
}

OutputTarget::~OutputTarget() {
  unlock();
  if (committed_) return;
  std::error_code error;
  fs::remove(temporary_, error);
  for (auto d = created_directories_.rbegin(); d != created_directories_.rend(); ++d) fs::remove(*d, error);
}

void OutputTarget::commit() {
  std::error_code error;
  fs::rename(temporary_, target_, error);
  if (error)
    throw std::runtime_error("cannot move the finished file into place as " + in_quotes(path_) + ": " +
                             error.message());
  committed_ = true;
}

}  // namespace rotorsweep::io
