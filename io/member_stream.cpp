// ResultStream: a buffer under one lock, batches written under another by whichever worker
// thread finds a batch due and the writer free, so writing overlaps with computing.
#include "io/member_stream.hpp"

namespace rotorsweep::io {

template <class Result>
ResultStream<Result>::ResultStream(Writer write, FlushPolicy policy, std::function<void()> on_failure)
    : writer_(std::move(write)),
      policy_(policy),
      on_failure_(std::move(on_failure)),
      last_write_(std::chrono::steady_clock::now()) {}

template <class Result>
bool ResultStream<Result>::due() const {
  return buffer_.size() >= policy_.members ||
         std::chrono::duration<double>(std::chrono::steady_clock::now() - last_write_).count() >=
             policy_.seconds;
}

template <class Result>
void ResultStream<Result>::add(Result&& result) {
  std::unique_lock buffer(buffer_lock_);
  buffer_.push_back(std::move(result));
  write_if_due(buffer);
}

template <class Result>
void ResultStream<Result>::add(std::vector<Result>&& results) {
  std::unique_lock buffer(buffer_lock_);
  for (Result& r : results) buffer_.push_back(std::move(r));
  write_if_due(buffer);
}

template <class Result>
void ResultStream<Result>::write_if_due(std::unique_lock<std::mutex>& buffer) {
  if (!due()) return;
  std::unique_lock writer(write_lock_, std::try_to_lock);
  if (!writer.owns_lock()) return;  // another thread is writing; the next add takes the rest
  std::vector<Result> batch;
  batch.swap(buffer_);
  // the next batch, as large as this one, moved in once rather than again at every growth
  buffer_.reserve(batch.size());
  last_write_ = std::chrono::steady_clock::now();
  buffer.unlock();
  write(std::move(batch));
}

template <class Result>
void ResultStream<Result>::write(std::vector<Result> batch) {
  if (failure_ || batch.empty()) return;
  const std::size_t count = batch.size();
  try {
    writer_(std::move(batch));
    const std::lock_guard buffer(buffer_lock_);
    written_ += count;
  } catch (...) {
    failure_ = std::current_exception();
    if (on_failure_) on_failure_();
  }
}

template <class Result>
void ResultStream<Result>::fail(std::exception_ptr failure) {
  const std::lock_guard writer(write_lock_);
  if (failure_) return;
  failure_ = std::move(failure);
  if (on_failure_) on_failure_();
}

template <class Result>
void ResultStream<Result>::flush() {
  const std::lock_guard writer(write_lock_);
  std::vector<Result> batch;
  {
    const std::lock_guard buffer(buffer_lock_);
    batch.swap(buffer_);
    last_write_ = std::chrono::steady_clock::now();
  }
  write(std::move(batch));
  if (failure_) std::rethrow_exception(failure_);
}

template <class Result>
std::size_t ResultStream<Result>::written() const {
  const std::lock_guard buffer(buffer_lock_);
  return written_;
}

template class ResultStream<PackedRow>;
template class ResultStream<ensemble::SliderMember>;

MemberStream::MemberStream(const ResultFile& file, const ensemble::MemberPlan& plan, FlushPolicy policy,
                           std::function<void()> on_failure)
    : ResultStream([&file](std::vector<PackedRow>&& batch) { file.write_packed(std::move(batch)); }, policy,
                   std::move(on_failure)),
      file_(file),
      plan_(plan) {}

void MemberStream::add(ensemble::MemberResult&& result) {
  PackedRow row;
  try {
    row = file_.pack(plan_[result.index], result);
  } catch (...) {  // a text longer than its column: the run stops as on a failed write
    fail(std::current_exception());
    return;
  }
  ResultStream::add(std::move(row));
}

SliderMemberStream::SliderMemberStream(const SliderResultFile& file, std::function<void()> on_failure)
    : ResultStream([&file](std::vector<ensemble::SliderMember>&& batch) { file.write_members(batch); },
                   {0.0, 1}, std::move(on_failure)) {}

}  // namespace rotorsweep::io
