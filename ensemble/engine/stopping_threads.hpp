// Work on OpenMP threads that stop together (docs/architecture.md "Layers"): the one threads driver of
// the CPU sweeps (rows and slider); the first exception stops every thread and is rethrown at the end.
#pragma once

#include <omp.h>

#include <atomic>
#include <exception>
#include <mutex>

namespace rotorsweep::ensemble {

/// Runs work(stopped) on `threads` OpenMP threads, each taking members until none is left or stopped()
/// holds: once `external()` did, or once a thread threw. The first exception is rethrown here after
/// every thread has returned (the members finished before it have reached their sinks).
template <class External, class Work>
void run_on_threads(int threads, const External& external, Work&& work) {
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  std::mutex failure_lock;
  const auto stopped = [&] { return failed.load(std::memory_order_relaxed) || external(); };
#pragma omp parallel num_threads(threads)
  try {
    work(stopped);
  } catch (...) {
    const std::lock_guard guard(failure_lock);
    if (!failure) failure = std::current_exception();
    failed = true;
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace rotorsweep::ensemble
