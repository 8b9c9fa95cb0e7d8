// A job on a thread of its own for the Python module (a row sweep, a slider scan): the caller polls
// wait() with the GIL released, reads done() and periods() for its progress line, and cancel() stops it.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

namespace rotorsweep::python {

class BackgroundJob {
 public:
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;
  virtual ~BackgroundJob() = default;

  /// Waits up to `seconds` (forever when negative); true once the job has ended.
  bool wait(double seconds) {
    std::unique_lock guard(lock_);
    if (seconds < 0)
      ended_.wait(guard, [this] { return finished_; });
    else
      ended_.wait_for(guard, std::chrono::duration<double>(seconds), [this] { return finished_; });
    return finished_;
  }
  std::size_t done() const { return done_.load(std::memory_order_relaxed); }
  std::size_t total() const { return total_; }
  /// Periods the members have closed so far, where the job counts them (a row sweep's, the command
  /// line's "periods closed"; a slider scan's progress counts members only: 0).
  std::size_t periods() const { return periods_.load(std::memory_order_relaxed); }
  /// Stops taking members and abandons those running, within one step; with an output path the
  /// finished members are kept in OUTPUT.partial (kept()), else nothing is written.
  void cancel() { stop_.store(true, std::memory_order_relaxed); }
  bool cancelled() const { return stop_.load(std::memory_order_relaxed); }
  /// After wait() returned true: the members a cancelled job kept in OUTPUT.partial, if it kept a file.
  std::optional<std::size_t> kept() const { return kept_; }

 protected:
  BackgroundJob() = default;

  /// Starts work() on the job's thread; what it throws is kept for rethrow().
  void start(std::function<void()> work) {
    worker_ = std::thread([this, work = std::move(work)] {
      try {
        work();
      } catch (...) {
        error_ = std::current_exception();
      }
      const std::lock_guard guard(lock_);
      finished_ = true;
      ended_.notify_all();
    });
  }
  /// Cancels and joins: a derived job's destructor, before its members go.
  void stop() {
    cancel();
    if (worker_.joinable()) worker_.join();
  }
  /// After the job has ended: rethrows its error.
  void rethrow() {
    if (!wait(0)) throw std::logic_error("the job is still running");
    if (worker_.joinable()) worker_.join();
    if (error_) std::rethrow_exception(error_);
  }

  /// The end of a job that streamed its members into a file: flushes `stream`; a cancelled job hands
  /// keep() the members written (to keep its partial file for --resume, where it keeps one) and returns
  /// false; a failed write throws "writing <what> failed: …"; else done() becomes total() and it returns
  /// true (the caller then finishes its file).
  template <class Stream, class Keep>
  bool end_stream(Stream& stream, const std::string& what, Keep&& keep) {
    std::string write_error;
    try {
      stream.flush();
    } catch (const std::exception& e) {
      write_error = e.what();
    }
    if (cancelled()) {
      keep(stream.written());
      return false;
    }
    if (!write_error.empty()) throw std::runtime_error("writing " + what + " failed: " + write_error);
    done_.store(total_, std::memory_order_relaxed);
    return true;
  }

  std::atomic<bool> stop_{false};
  std::atomic<std::size_t> done_{0};
  std::atomic<std::size_t> periods_{0};
  std::optional<std::size_t> kept_;  ///< written by the job's thread before it ends
  std::size_t total_ = 0;            ///< members of the whole job, set before start()

 private:
  std::mutex lock_;
  std::condition_variable ended_;
  bool finished_ = false;
  std::exception_ptr error_;
  std::thread worker_;
};

}  // namespace rotorsweep::python
