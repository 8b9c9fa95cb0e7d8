// Finished members on their way into a ResultFile (README "Interrupting, resuming and splitting
// a sweep"): buffered from the worker threads and written in batches at a bounded interval.
#pragma once

#include <chrono>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"
#include "io/result_file.hpp"

namespace rotorsweep::io {

/// When a batch is written: after `seconds` since the last one, or once `members` are waiting.
struct FlushPolicy {
  double seconds = 5;
  std::size_t members = 4096;
};

/// Takes results from any thread (add) and writes them in batches; one thread writes while the
/// others go on computing. A failed write calls on_failure once (to stop the sweep) and is thrown
/// again by flush(). Memory: at most `members` waiting results plus those that finish while a
/// batch is being written.
class MemberStream {
 public:
  MemberStream(const ResultFile& file, const ensemble::MemberPlan& plan, FlushPolicy policy,
               std::function<void()> on_failure);
  void add(ensemble::MemberResult&& result);
  /// Writes what is waiting (call when no thread adds any more); rethrows a failed write.
  void flush();
  /// Members written so far.
  std::size_t written() const;

 private:
  bool due() const;
  /// Writes `batch` (holding write_lock_), or records the failure.
  void write(std::vector<ensemble::MemberResult> batch);

  const ResultFile& file_;
  const ensemble::MemberPlan& plan_;
  FlushPolicy policy_;
  std::function<void()> on_failure_;
  mutable std::mutex buffer_lock_, write_lock_;
  std::vector<ensemble::MemberResult> buffer_;
  std::chrono::steady_clock::time_point last_write_;
  std::size_t written_ = 0;
  std::exception_ptr failure_;
};

}  // namespace rotorsweep::io
