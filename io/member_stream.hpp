// Finished members on their way into a result file (docs/scale.md "Interrupting, resuming and
// splitting a sweep"): packed and buffered by the worker threads, written in batches at a bounded interval.
#pragma once

#include <chrono>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "io/result_file.hpp"
#include "io/slider_result_file.hpp"

namespace rotorsweep::io {

/// When a batch is written: after `seconds` since the last one, or once `members` are waiting.
struct FlushPolicy {
  double seconds = 5;
  std::size_t members = 4096;
};

/// Takes results from any thread (add) and writes them in batches through `write`; one thread writes
/// while the others go on computing. A failed write calls on_failure once (to stop the sweep) and is
/// thrown again by flush(). Memory: at most `members` waiting results plus those that finish while a
/// batch is being written.
template <class Result>
class ResultStream {
 public:
  using Writer = std::function<void(std::vector<Result>&&)>;
  ResultStream(Writer write, FlushPolicy policy, std::function<void()> on_failure);
  void add(Result&& result);
  /// Several results at once (a device chunk's).
  void add(std::vector<Result>&& results);
  /// Writes what is waiting (call when no thread adds any more); rethrows a failed write.
  void flush();
  /// Members written so far.
  std::size_t written() const;

 protected:
  /// Records a failure to prepare a result as a failed write: on_failure once, thrown again by flush().
  void fail(std::exception_ptr failure);

 private:
  /// Writes a batch if one is due and no other thread is writing (buffer_lock_ held by `buffer`).
  void write_if_due(std::unique_lock<std::mutex>& buffer);
  bool due() const;
  /// Writes `batch` (holding write_lock_), or records the failure.
  void write(std::vector<Result> batch);

  Writer writer_;
  FlushPolicy policy_;
  std::function<void()> on_failure_;
  mutable std::mutex buffer_lock_, write_lock_;
  std::vector<Result> buffer_;
  std::chrono::steady_clock::time_point last_write_;
  std::size_t written_ = 0;
  std::exception_ptr failure_;
};

/// A row sweep's results into its ResultFile (rows in plan order, then /members/done), each packed into
/// its row's bytes by the thread that adds it, so that the writing thread only gathers and writes.
class MemberStream : public ResultStream<PackedRow> {
 public:
  MemberStream(const ResultFile& file, const ensemble::MemberPlan& plan, FlushPolicy policy,
               std::function<void()> on_failure);
  void add(ensemble::MemberResult&& result);

 private:
  const ResultFile& file_;
  const ensemble::MemberPlan& plan_;
};

/// A slider scan's members into its SliderResultFile, each chunk's (or lane block's) members as they
/// finish: a slider member carries its series, so none waits for a batch.
class SliderMemberStream : public ResultStream<ensemble::SliderMember> {
 public:
  SliderMemberStream(const SliderResultFile& file, std::function<void()> on_failure);
};

}  // namespace rotorsweep::io
