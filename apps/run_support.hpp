// What `rotorsweep run` shares between its single-process and its MPI form: the output path, the
// header line, the disk-space check, the outcome report, and stopping on SIGINT and SIGTERM.
#pragma once

#include <atomic>
#include <csignal>
#include <optional>
#include <string>

#include "commands.hpp"
#include "ensemble/rows/scene.hpp"
#include "io/hdf5_file.hpp"
#include "io/result_file.hpp"

namespace rotorsweep::apps {

/// -o, else output.path, else SCENE's stem + ".h5" in the working directory; a shard without -o
/// gets ".shard-I-of-N" before the extension, so that shards do not overwrite each other.
std::string output_path(const RunOptions& options, const ensemble::Scene& scene,
                        const std::optional<io::ShardLabel>& shard);
/// Members that did not finish, by status, and unresolved D, read from a written file (stderr).
void report_outcome(const io::Hdf5Location& file, const ensemble::Scene& scene);
/// Whether `rows` members' file fits on the disk of `partial`; says how much it needs when not.
bool fits_on_disk(const ensemble::Scene& scene, std::size_t rows, const std::string& partial);
/// Whether every thread's lane block fits in 80 % of the memory this process may use; says how much
/// it needs when not.
bool fits_in_memory(const ensemble::Scene& scene, int threads);
/// The one-line description of the run on stderr.
void print_header(const RunOptions& options, const ensemble::Scene& scene, std::size_t members, int threads,
                  const std::optional<io::ShardLabel>& shard);

#if ROTORSWEEP_HAVE_MPI
/// Whether the process was started by mpirun (Open MPI's or a PMI launcher's environment).
bool launched_by_mpi();
/// `rotorsweep run` as one rank of an MPI job (apps/mpi_run.cpp).
int run_sweep_mpi(const RunOptions& options, const ensemble::Scene& scene, int threads);
#endif

/// SIGINT and SIGTERM raise the sweep's stop flag while an instance lives (the previous handlers
/// come back after it); signal() names the signal that came, 0 for none.
class StopOnSignals {
 public:
  StopOnSignals() {
    stop_ = false;
    signal_ = 0;
    previous_int_ = std::signal(SIGINT, &StopOnSignals::handle);
    previous_term_ = std::signal(SIGTERM, &StopOnSignals::handle);
  }
  ~StopOnSignals() {
    std::signal(SIGINT, previous_int_);
    std::signal(SIGTERM, previous_term_);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;
  const std::atomic<bool>* flag() const { return &stop_; }
  /// Stops the sweep as a signal would, for another reason (signal() stays 0).
  void stop() const { stop_ = true; }
  int signal() const { return signal_; }

 private:
  static void handle(int number) {
    signal_ = number;
    stop_ = true;
  }
  static inline std::atomic<bool> stop_{false};
  static inline volatile std::sig_atomic_t signal_ = 0;
  void (*previous_int_)(int) = SIG_DFL;
  void (*previous_term_)(int) = SIG_DFL;
};

}  // namespace rotorsweep::apps
