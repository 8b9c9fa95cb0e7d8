// What a problem gives the lane scheduler (docs/architecture.md "Layers"): its members' lanes, stops and
// retirement, as a concept the compiler checks against every problem (rows, slider, a test's model).
#pragma once

#include <concepts>
#include <cstddef>
#include <optional>

#include "ensemble/engine/member_progress.hpp"

namespace rotorsweep::ensemble {

/// A retire() a problem hands its finished members to (the concept's stand-in for the scheduler's).
template <class Result>
struct RetireSink {
  void operator()(Result&&) const {}
};

/// The problem of a LaneScheduler: it owns the integration loop and says what a member is and what it
/// leaves. Member, Result, width, refill(); start(lane, member, queued) → the member's StopSchedule;
/// step(); failed(lane), any_stop_reached(), stop_reached(lane); close_stop(lane) → whether its steady
/// test holds; next_stop(lane); finish(lane, progress, settled, retire) hands zero or one Result to
/// retire(); take_queued() / has_queued(): members it adds itself (shadow runs, symmetry probes), run
/// before the plan's.
template <class P>
concept LaneProblem = requires(P& problem, const P& constant, std::size_t lane, const typename P::Member& member,
                               const MemberProgress& progress, RetireSink<typename P::Result>& retire) {
  typename P::Member;
  typename P::Result;
  { P::width } -> std::convertible_to<std::size_t>;
  { constant.refill() } -> std::convertible_to<bool>;
  { problem.start(lane, member, true) } -> std::same_as<StopSchedule>;
  problem.step();
  { constant.failed(lane) } -> std::convertible_to<bool>;
  { constant.any_stop_reached() } -> std::convertible_to<bool>;
  { constant.stop_reached(lane) } -> std::convertible_to<bool>;
  { problem.close_stop(lane) } -> std::convertible_to<bool>;
  problem.next_stop(lane);
  problem.finish(lane, progress, true, retire);
  { problem.take_queued() } -> std::same_as<std::optional<typename P::Member>>;
  { constant.has_queued() } -> std::convertible_to<bool>;
};

}  // namespace rotorsweep::ensemble
