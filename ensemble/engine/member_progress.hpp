// A member's way through its stops (docs/scenes.md "Row scenes", keys schedule.*): count the stops it
// closes (a row member's periods, a slider member's samples) and decide when it retires, after a fixed
// count or, where its problem tests for a steady state, once the test holds or at a cap; one state
// machine for CPU lanes and GPU threads.
#pragma once

#include "kernels/lanes/host_device.hpp"

namespace rotorsweep::ensemble {

/// The stops every member of a variant closes: `stops`, or with a steady test until it holds after
/// those, at most max_stops.
struct StopSchedule {
  int stops = 0;
  int max_stops = 0;         ///< the cap with a steady test
  bool steady_test = false;  ///< retire once the problem's steady test holds (never at the first stop)

  /// Stops a member can close at most.
  ROTORSWEEP_HD int limit() const { return steady_test && max_stops > stops ? max_stops : stops; }
};

/// Where one member stands: LaneScheduler keeps one per lane, a GPU thread or team one per member, so
/// both retire a member after the same stop.
class MemberProgress {
 public:
  /// Closes a stop at which the problem's steady test holds or not (`steady`, read only with
  /// s.steady_test); returns whether the member retires (after s.stops, or with a steady test once it
  /// holds after those, not at the first stop, or at max_stops).
  ROTORSWEEP_HD bool close_stop(const StopSchedule& s, bool steady) {
    ++stops_;
    const bool long_enough = stops_ >= s.stops;
    settled_ = long_enough && (!s.steady_test || (stops_ >= 2 && steady));
    return settled_ || (s.steady_test && stops_ >= s.max_stops);
  }

  ROTORSWEEP_HD int stops() const { return stops_; }       ///< stops closed
  ROTORSWEEP_HD bool settled() const { return settled_; }  ///< whether the schedule was met

 private:
  int stops_ = 0;
  bool settled_ = false;
};

}  // namespace rotorsweep::ensemble
