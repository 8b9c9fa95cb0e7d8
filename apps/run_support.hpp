// What `rotorsweep run` shares with its MPI form and with `rotorsweep slider`: the output path, shards,
// partial files to resume, the header line, the disk-space check, the outcome report, stopping on signals.
#pragma once

#include <atomic>
#include <csignal>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/slider/slider_scene.hpp"
#include "io/hdf5_file.hpp"
#include "io/output_target.hpp"
#include "io/result_file.hpp"

namespace rotorsweep::apps {

/// -o, else the scene's output.path, else SCENE's stem + ".h5" in the working directory; a shard
/// without -o gets ".shard-I-of-N" before the extension, so that shards do not overwrite each other.
std::string output_path(const SceneCommandOptions& options, const std::string& scene_output_path,
                        const std::optional<io::ShardLabel>& shard);
/// "I/N" with 1 ≤ I ≤ N; nothing for an empty text; throws std::invalid_argument otherwise.
std::optional<io::ShardLabel> parse_shard(const std::string& text, std::size_t plan_members);
/// Checks that `partial` is an unfinished file of this scene (its text), program, kind and shape
/// (`check_file`: the kind's check of its attributes and datasets) and shard, and returns its done mask
/// and the wall time spent on it so far; throws std::runtime_error saying why not.
std::vector<char> check_partial(const std::string& partial, const std::string& scene_text,
                                const std::optional<io::ShardLabel>& shard, double& earlier_seconds,
                                const std::function<void(const io::Hdf5Location&)>& check_file);
/// Checks `path` and takes it (OutputTarget with OUT.h5.partial), refusing a partial file of an
/// earlier run unless `resume` or --force; says why and returns false when the command must exit 2.
bool open_resumable_target(const SceneCommandOptions& options, bool resume, const std::string& path,
                           std::optional<io::OutputTarget>& target);
/// "shard 2/3: members 1, 4, 7, ... of the plan's 12" (as many as there are, up to three), or "shard 5/8: no
/// members (the plan has 3)".
std::string shard_line(const io::ShardLabel& shard);
/// The command line that resumes a run: "rotorsweep COMMAND SCENE [-o OUT] [--shard I/N] --resume".
std::string resume_command(const std::string& command, const SceneCommandOptions& options,
                           const std::string& shard);
/// Members that did not finish, by status, and, each reason apart, those whose D is not resolved, read
/// from a written file (stderr).
void report_outcome(const io::Hdf5Location& file, const ensemble::Scene& scene);
/// Whether `needed` bytes fit on the disk of `partial` (95 % of its free space); says how much `what`
/// (plural: "the results ... need") needs, and `advice`, when not.
bool fits_on_disk(double needed, const std::string& what, const std::string& partial,
                  const std::string& advice);
/// Says "error: " and the refusal on stderr, if there is one (apps/run_needs.hpp), and whether there was.
bool refused(const std::optional<std::string>& refusal);
/// The one-line description of a slider scan on stderr (and the shard's members).
void print_slider_header(const SliderOptions& options, const ensemble::SliderScene& scene, int threads,
                         const std::optional<io::ShardLabel>& shard);
/// The one-line description of the run on stderr.
void print_header(const RunOptions& options, const ensemble::Scene& scene, std::size_t members, int threads,
                  const std::optional<io::ShardLabel>& shard);

#if ROTORSWEEP_HAVE_MPI
/// Whether the process was started by mpirun (Open MPI's or a PMI launcher's environment).
bool launched_by_mpi();
/// `rotorsweep run` as one rank of an MPI job (apps/mpi_run.cpp).
int run_sweep_mpi(const RunOptions& options, const ensemble::Scene& scene, int threads);
/// `rotorsweep slider` as one rank of an MPI job (apps/mpi_slider.cpp).
int run_slider_mpi(const SliderOptions& options, const ensemble::SliderScene& scene, int threads);
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
  /// Whether a signal came or stop() was called: the run's stop (ensemble::RunControl::stop).
  bool stopped() const { return stop_.load(std::memory_order_relaxed); }
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
