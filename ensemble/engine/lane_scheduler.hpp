// The lane scheduler (docs/architecture.md "Layers"): takes a problem's members into the lanes of
// its integration loop, closes their stops (periods, samples), and retires and refills lanes; it knows
// no model.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "ensemble/engine/lane_problem.hpp"
#include "ensemble/engine/member_progress.hpp"

namespace rotorsweep::ensemble {

/// Runs the members of a Problem (the LaneProblem concept: ensemble/rows/row_problem.hpp for the row
/// models, ensemble/slider/slider_problem.hpp for the slider) through its `width` lanes; the steady test
/// close_stop() answers is read where the member's schedule has one. Each lane owns its member and its
/// MemberProgress (stops closed, steady state, when it retires: the state machine DeviceMember keeps on
/// a GPU thread); a member that finishes or fails retires at once and (with refill()) its lane takes
/// the next.
template <LaneProblem Problem>
class LaneScheduler {
 public:
  using Member = typename Problem::Member;
  using Result = typename Problem::Result;
  static constexpr std::size_t width = Problem::width;

  /// Builds the problem in place from `arguments` (it owns the loop's storage).
  template <class... Arguments>
  explicit LaneScheduler(Arguments&&... arguments)
      : problem_(std::forward<Arguments>(arguments)...), lanes_(width) {}

  /// Takes members from next_member() (a std::optional<Member>; empty when the plan is
  /// exhausted) until none is left and every lane has retired; hands each result to retire().
  /// Returns at once, abandoning the members in its lanes, when stopped() turns true.
  /// stop_closed() is called after each stop a member closes.
  struct Nothing {
    void operator()() const {}
  };
  template <class NextMember, class Retire, class Stopped, class StopClosed = Nothing>
  void run(NextMember&& next_member, Retire&& retire, Stopped&& stopped, StopClosed&& stop_closed = {}) {
    for (;;) {
      if (stopped()) return;
      if (problem_.refill() || occupied_ == 0) fill_idle_lanes(next_member);
      if (occupied_ == 0) return;
      problem_.step();
      busy_ += double(occupied_);
      total_ += double(width);
      const bool stops_reached = problem_.any_stop_reached();
      for (std::size_t l = 0; l < width; ++l) {
        if (!lanes_[l].occupied) continue;
        if (problem_.failed(l))
          finish(l, false, retire);
        else if (stops_reached && problem_.stop_reached(l))
          close_stop(l, retire, stop_closed);
      }
    }
  }

  double lane_steps_busy() const { return busy_; }    ///< Σ over attempts of lanes holding a member
  double lane_steps_total() const { return total_; }  ///< Σ over attempts of all lanes

 private:
  struct Lane {
    bool occupied = false;
    MemberProgress progress;  ///< stops closed, steady state
    StopSchedule schedule;    ///< the member's (the scene's, or a shadow run's)
  };

  /// Idle lanes take the problem's queued members, then members of the plan.
  template <class NextMember>
  void fill_idle_lanes(NextMember& next_member) {
    for (std::size_t l = 0; l < width && occupied_ < width && (!plan_exhausted_ || problem_.has_queued());
         ++l) {
      if (lanes_[l].occupied) continue;
      if (std::optional<Member> queued = problem_.take_queued()) {
        start(l, *queued, true);
        continue;
      }
      const std::optional<Member> member = next_member();
      plan_exhausted_ = !member;
      if (plan_exhausted_) break;
      start(l, *member, false);
    }
  }

  void start(std::size_t l, const Member& member, bool queued) {
    lanes_[l].schedule = problem_.start(l, member, queued);
    lanes_[l].progress = MemberProgress{};
    lanes_[l].occupied = true;
    ++occupied_;
  }

  template <class Retire, class StopClosed>
  void close_stop(std::size_t l, Retire& retire, StopClosed& stop_closed) {
    const bool steady = problem_.close_stop(l);
    stop_closed();
    if (lanes_[l].progress.close_stop(lanes_[l].schedule, steady)) {
      finish(l, lanes_[l].progress.settled(), retire);
      return;
    }
    problem_.next_stop(l);
  }

  template <class Retire>
  void finish(std::size_t l, bool settled, Retire& retire) {
    lanes_[l].occupied = false;
    --occupied_;
    problem_.finish(l, lanes_[l].progress, settled, retire);
  }

  Problem problem_;
  std::vector<Lane> lanes_;
  std::size_t occupied_ = 0;
  bool plan_exhausted_ = false;
  double busy_ = 0, total_ = 0;
};

}  // namespace rotorsweep::ensemble
