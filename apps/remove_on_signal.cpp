// RemoveOnSignal: the paths copied into static buffers beforehand, so that the handler uses only
// async-signal-safe calls (unlink, rmdir, write, _exit).
#include "remove_on_signal.hpp"

#include <unistd.h>

#include <csignal>
#include <cstring>

namespace rotorsweep::apps {

namespace {

constexpr std::size_t path_bytes = 4096, most_directories = 16, most_locks = 8;
char temporary_path[path_bytes];
char lock_paths[most_locks][path_bytes];
std::size_t lock_count = 0;
char directories[most_directories][path_bytes];
std::size_t directory_count = 0;

/// Copies `path` into `buffer` when it fits (with its terminating NUL); false otherwise.
bool copy_path(const std::string& path, char* buffer) {
  if (path.size() + 1 > path_bytes) return false;
  std::memcpy(buffer, path.c_str(), path.size() + 1);
  return true;
}

extern "C" void remove_and_exit(int number) {
  if (temporary_path[0]) ::unlink(temporary_path);
  for (std::size_t i = 0; i < lock_count; ++i) ::unlink(lock_paths[i]);     // the locks go with the process
  for (std::size_t i = directory_count; i-- > 0;) ::rmdir(directories[i]);  // innermost first
  const char* message =
      number == SIGTERM ? "stopped by SIGTERM: nothing written\n" : "stopped by SIGINT: nothing written\n";
  [[maybe_unused]] const auto written = ::write(STDERR_FILENO, message, std::strlen(message));
  ::_exit(128 + number);
}

}  // namespace

RemoveOnSignal::RemoveOnSignal() {
  previous_int_ = std::signal(SIGINT, &remove_and_exit);
  previous_term_ = std::signal(SIGTERM, &remove_and_exit);
}

RemoveOnSignal::RemoveOnSignal(const io::OutputTarget& target) {
  // the handler may run while the paths are being copied: it sees a count only once its paths are there
  if (!copy_path(target.temporary(), temporary_path)) temporary_path[0] = '\0';
  for (const auto& lock : target.lock_files())
    if (lock_count < most_locks && copy_path(lock, lock_paths[lock_count])) ++lock_count;
  for (const auto& directory : target.created_directories())
    if (directory_count < most_directories && copy_path(directory.string(), directories[directory_count]))
      ++directory_count;
  previous_int_ = std::signal(SIGINT, &remove_and_exit);
  previous_term_ = std::signal(SIGTERM, &remove_and_exit);
}

RemoveOnSignal::RemoveOnSignal(const std::filesystem::path& scratch) {
  if (!copy_path(scratch.string(), temporary_path)) temporary_path[0] = '\0';
  previous_int_ = std::signal(SIGINT, &remove_and_exit);
  previous_term_ = std::signal(SIGTERM, &remove_and_exit);
}

RemoveOnSignal::~RemoveOnSignal() {
  std::signal(SIGINT, previous_int_);
  std::signal(SIGTERM, previous_term_);
  temporary_path[0] = '\0';
  lock_count = 0;
  directory_count = 0;
}

}  // namespace rotorsweep::apps
