// How `rotorsweep run` and `rotorsweep slider` end a run streamed into its partial file: failed, stopped
// or finished, each with what is kept and how to resume.
#include "streamed_run.hpp"

#include <csignal>
#include <cstdio>
#include <iostream>

namespace rotorsweep::apps {

bool partial_lost(const io::OutputTarget& target, std::size_t done) {
  if (target.temporary_is_ours()) return false;
  std::fprintf(stderr,
               "error: %s is no longer the file this run wrote (another process replaced or removed it): the "
               "%zu members done are lost\n",
               target.temporary().c_str(), done);
  return true;
}

std::optional<int> end_unfinished_run(io::OutputTarget& target, const StreamedSweep& streamed, bool stopped,
                                      const std::string& what, const std::function<void()>& keep_partial,
                                      std::size_t done, std::size_t rows, const std::string& resume) {
  if (!streamed.write_error.empty() || !streamed.sweep_error.empty()) {
    target.keep();  // the rows marked done are on disk: keep them for --resume, and say so
    std::fprintf(
        stderr, "error: %s\n",
        (streamed.write_error.empty() ? what + " failed: " + streamed.sweep_error
                                      : "writing " + target.temporary() + " failed: " + streamed.write_error)
            .c_str());
    if (partial_lost(target, done)) return 1;
    std::fprintf(
        stderr,
        "%zu of %zu members are kept in %s (not a result: complete = FALSE); once the cause is fixed, "
        "resume with: %s\n",
        done, rows, target.temporary().c_str(), resume.c_str());
    return 1;
  }
  if (!stopped) return std::nullopt;
  const int signal_number = streamed.signal_number;
  const char* name = signal_number == SIGTERM ? "SIGTERM" : "SIGINT";
  try {
    keep_partial();
  } catch (const std::exception& e) {
    std::cerr << "\nstopped by " << name << "; closing " << target.temporary() << " failed: " << e.what()
              << "\n";
  }
  target.keep();
  if (partial_lost(target, done)) return 128 + (signal_number ? signal_number : SIGINT);
  std::fprintf(stderr,
               "\nstopped by %s: %zu of %zu members done, kept in %s (not a result: complete = FALSE).\n"
               "resume with: %s\n",
               name, done, rows, target.temporary().c_str(), resume.c_str());
  return 128 + (signal_number ? signal_number : SIGINT);
}

bool finish_streamed_run(io::OutputTarget& target, const std::function<void()>& finish,
                         const std::string& path, std::size_t rows, const std::string& resume) {
  try {
    finish();
    target.commit();
    return true;
  } catch (const std::exception& e) {
    target.keep();
    std::cerr << "error: finishing " << path << " failed: " << e.what() << "\n";
    if (!partial_lost(target, rows))
      std::cerr << "the members are kept in " << target.temporary()
                << " (complete = FALSE); resume with: " << resume << "\n";
    return false;
  }
}

}  // namespace rotorsweep::apps
