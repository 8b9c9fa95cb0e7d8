// A sweep running on its own thread for the Python module: the caller polls wait() with the GIL
// released, reads done() and periods() for its progress line, and cancel() stops it within one step (Ctrl-C).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/output_target.hpp"
#include "io/result_file.hpp"

namespace rotorsweep::python {

/// As `rotorsweep run` and `slider` refuse without --force: throws io::OutputPathError where `target`'s
/// partial file holds the members of an earlier run that stopped early, unless `force`; the partial
/// file is then kept as it is.
void refuse_earlier_partial(io::OutputTarget& target, bool force);

class SweepJob {
 public:
  /// Starts the scene's whole plan on `threads` threads (0: OpenMP's default). With an output
  /// path the result goes to that file exactly as `rotorsweep run` writes it (checked here,
  /// before the start: io::OutputPathError), through OUTPUT.partial, which keeps the finished members
  /// of a cancelled sweep for `rotorsweep run --resume`; without, it is kept as an in-memory HDF5 image.
  SweepJob(ensemble::Scene scene, int threads, const std::string& output, bool force,
           const io::Provenance& provenance);
  SweepJob(const SweepJob&) = delete;
  SweepJob& operator=(const SweepJob&) = delete;
  /// Cancels and joins.
  ~SweepJob();

  /// Waits up to `seconds` (forever when negative); true once the sweep has ended.
  bool wait(double seconds);
  std::size_t done() const { return done_.load(std::memory_order_relaxed); }
  /// Periods the members have closed so far (the command line's "periods closed").
  std::size_t periods() const { return periods_.load(std::memory_order_relaxed); }
  std::size_t total() const { return members_.size(); }
  /// Stops taking members and abandons those in lanes; with an output path the finished members are
  /// kept in OUTPUT.partial (kept()), else nothing is written.
  void cancel() { stop_.store(true, std::memory_order_relaxed); }
  bool cancelled() const { return stop_.load(std::memory_order_relaxed); }
  /// After wait() returned true: the members a cancelled sweep kept in OUTPUT.partial, if it kept any file.
  std::optional<std::size_t> kept() const { return kept_; }
  /// After wait() returned true: rethrows the sweep's or the writer's error, else returns the
  /// in-memory file's bytes (empty when the result went to the output path).
  std::vector<unsigned char> take_image();

 private:
  void run(int threads);
  /// The finished members of a cancelled sweep into the partial file, which stays for --resume.
  void keep_finished(const ensemble::SweepOutcome& outcome);

  ensemble::Scene scene_;
  std::vector<ensemble::Member> members_;
  std::optional<io::OutputTarget> target_;
  std::optional<io::ResultFile> file_;
  std::atomic<bool> stop_{false};
  std::atomic<std::size_t> done_{0};
  std::atomic<std::size_t> periods_{0};
  std::mutex lock_;
  std::condition_variable ended_;
  bool finished_ = false;
  std::exception_ptr error_;
  std::optional<std::size_t> kept_;
  std::vector<unsigned char> image_;
  std::thread worker_;
};

}  // namespace rotorsweep::python
