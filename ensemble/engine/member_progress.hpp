// A member's way through its period schedule (README "schedule.*"): count the periods it closes and
// decide when it retires, after a fixed count or, where its problem tests for a steady state, once the
// test holds or at a cap; one state machine for CPU lanes and GPU threads.
#pragma once

#include "kernels/lanes/host_device.hpp"

namespace rotorsweep::ensemble {

/// The schedule every member of a variant follows.
struct PeriodSchedule {
  int relax_periods = 0;
  int average_periods = 0;
  int max_periods = 0;       ///< the cap with a steady test
  bool steady_test = false;  ///< retire once the problem's steady test holds (never at the first period)

  /// Periods a member can run at most.
  ROTORSWEEP_HD int limit() const {
    const int schedule = relax_periods + average_periods;
    return steady_test && max_periods > schedule ? max_periods : schedule;
  }
};

/// Where one member stands: LaneScheduler keeps one per lane, a GPU thread or team one per member, so
/// both retire a member after the same period.
class MemberProgress {
 public:
  /// Closes a period at which the problem's steady test holds or not (`steady`, read only with
  /// s.steady_test); returns whether the member retires (after relax + average periods, or with a steady
  /// test once it holds after those, not at the first period, or at max_periods).
  ROTORSWEEP_HD bool close_period(const PeriodSchedule& s, bool steady) {
    ++periods_;
    const bool long_enough = periods_ >= s.relax_periods + s.average_periods;
    settled_ = long_enough && (!s.steady_test || (periods_ >= 2 && steady));
    return settled_ || (s.steady_test && periods_ >= s.max_periods);
  }

  ROTORSWEEP_HD int periods() const { return periods_; }   ///< periods closed
  ROTORSWEEP_HD bool settled() const { return settled_; }  ///< whether the schedule was met

 private:
  int periods_ = 0;
  bool settled_ = false;
};

}  // namespace rotorsweep::ensemble
