// MemberStream: a buffer under one lock, batches written under another by whichever worker
// thread finds a batch due and the writer free, so writing overlaps with computing.
#include "io/member_stream.hpp"

namespace rotorsweep::io {

MemberStream::MemberStream(const ResultFile& file, const ensemble::MemberPlan& plan, FlushPolicy policy,
                           std::function<void()> on_failure)
    : file_(file),
      plan_(plan),
      policy_(policy),
      on_failure_(std::move(on_failure)),
      last_write_(std::chrono::steady_clock::now()) {}

bool MemberStream::due() const {
  return buffer_.size() >= policy_.members ||
         std::chrono::duration<double>(std::chrono::steady_clock::now() - last_write_).count() >=
             policy_.seconds;
}

void MemberStream::add(ensemble::MemberResult&& result) {
  std::unique_lock buffer(buffer_lock_);
  buffer_.push_back(std::move(result));
  if (!due()) return;
  std::unique_lock writer(write_lock_, std::try_to_lock);
  if (!writer.owns_lock()) return;  // another thread is writing; the next add takes the rest
  std::vector<ensemble::MemberResult> batch;
  batch.swap(buffer_);
  last_write_ = std::chrono::steady_clock::now();
  buffer.unlock();
  write(std::move(batch));
}

void MemberStream::write(std::vector<ensemble::MemberResult> batch) {
  if (failure_ || batch.empty()) return;
  const std::size_t count = batch.size();
  try {
    file_.write_results(plan_, std::move(batch));
    const std::lock_guard buffer(buffer_lock_);
    written_ += count;
  } catch (...) {
    failure_ = std::current_exception();
    if (on_failure_) on_failure_();
  }
}

void MemberStream::flush() {
  const std::lock_guard writer(write_lock_);
  std::vector<ensemble::MemberResult> batch;
  {
    const std::lock_guard buffer(buffer_lock_);
    batch.swap(buffer_);
    last_write_ = std::chrono::steady_clock::now();
  }
  write(std::move(batch));
  if (failure_) std::rethrow_exception(failure_);
}

std::size_t MemberStream::written() const {
  const std::lock_guard buffer(buffer_lock_);
  return written_;
}

}  // namespace rotorsweep::io
