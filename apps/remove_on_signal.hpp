// Commands that write one file at the end (landscape, table -o, couplings -o, merge; bench host's scratch
// file): SIGINT or SIGTERM removes the temporary file and the directories made for it and ends with 128 + signal.
#pragma once

#include <filesystem>

#include "io/output_target.hpp"

namespace rotorsweep::apps {

/// While an instance lives, SIGINT and SIGTERM end the process at once (the computations these
/// commands run have no stopping points), also where the process was started ignoring them: the
/// handler unlinks `target`'s temporary file and lock files, removes the directories made for it,
/// says so on stderr and exits with 128 + the signal's number (130, 143). Without a target (the
/// computation before the file exists) there is nothing to remove. The previous handlers come back
/// after it, and an instance nested in another leaves the outer one nothing to remove.
class RemoveOnSignal {
 public:
  RemoveOnSignal();
  explicit RemoveOnSignal(const io::OutputTarget& target);
  /// A scratch file a command writes and removes itself (bench host): the signal removes it too.
  explicit RemoveOnSignal(const std::filesystem::path& scratch);
  ~RemoveOnSignal();
  RemoveOnSignal(const RemoveOnSignal&) = delete;
  RemoveOnSignal& operator=(const RemoveOnSignal&) = delete;

 private:
  void (*previous_int_)(int);
  void (*previous_term_)(int);
};

}  // namespace rotorsweep::apps
