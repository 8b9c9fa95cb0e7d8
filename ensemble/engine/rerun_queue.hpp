// Reruns of finished members and the primaries that wait for them (docs/architecture.md "The problem
// seam"): one queue that the CPU's lanes drain as lanes free up and a device between its chunks.
#pragma once

#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace rotorsweep::ensemble {

/// Members to run again (`Member`, each naming its primary by `index`) and the primaries' results
/// (`Result`) held until every rerun of theirs has finished. Not thread-safe: a caller with several
/// threads locks around it.
template <class Member, class Result>
class RerunQueue {
 public:
  /// Holds member `index`'s result until each of `reruns` has finished, and queues them (in order).
  void hold(std::size_t index, Result&& primary, std::vector<Member>&& reruns) {
    held_.emplace(index, Held{std::move(primary), reruns.size()});
    for (Member& rerun : reruns) queued_.push_back(std::move(rerun));
  }

  /// The next queued rerun, first in first out.
  std::optional<Member> take() {
    if (queued_.empty()) return std::nullopt;
    Member rerun = std::move(queued_.front());
    queued_.pop_front();
    return rerun;
  }

  /// A rerun of member `index` finished: complete(primary) takes its result into the held primary,
  /// which is returned once its last rerun has finished.
  template <class Complete>
  std::optional<Result> finish(std::size_t index, Complete&& complete) {
    const auto at = held_.find(index);
    complete(at->second.primary);
    if (--at->second.pending > 0) return std::nullopt;
    Result primary = std::move(at->second.primary);
    held_.erase(at);
    return primary;
  }

  std::size_t queued() const { return queued_.size(); }  ///< reruns waiting to start
  std::size_t held() const { return held_.size(); }      ///< primaries waiting for reruns

 private:
  struct Held {
    Result primary;
    std::size_t pending = 0;  ///< its reruns not yet finished
  };
  std::deque<Member> queued_;
  std::map<std::size_t, Held> held_;
};

}  // namespace rotorsweep::ensemble
