// A member's way through its period schedule (README "schedule.*"): count the periods it closes,
// test steady state, decide when it retires; one state machine for CPU lanes and GPU threads.
#pragma once

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"

namespace rotorsweep::ensemble {

/// Whether two successive periods' dissipations agree: |D_k - D_{k-1}| <= tol · max(|D_k|, |D_{k-1}|).
ROTORSWEEP_HD inline bool dissipations_agree(double before, double now, double tol) {
  const double a = kernels::lane_abs(now), b = kernels::lane_abs(before);
  return kernels::lane_abs(now - before) <= tol * (a < b ? b : a);
}

/// The schedule every member of a variant follows.
struct PeriodSchedule {
  int relax_periods = 0;
  int average_periods = 0;
  int max_periods = 0;    ///< the cap with steady_tol
  double steady_tol = 0;  ///< > 0: retire once two successive periods' D agree (dissipations_agree)

  /// Periods a member can run at most.
  ROTORSWEEP_HD int limit() const {
    const int schedule = relax_periods + average_periods;
    return steady_tol > 0 && max_periods > schedule ? max_periods : schedule;
  }
};

/// Where one member stands: LaneScheduler keeps one per lane, DeviceMember one per GPU thread, so
/// both retire a member after the same period.
class MemberProgress {
 public:
  /// Closes a period whose dissipation is `dissipation`; returns whether the member retires (after
  /// relax + average periods, or with steady_tol once settled or at max_periods).
  ROTORSWEEP_HD bool close_period(const PeriodSchedule& s, double dissipation) {
    const double before = last_dissipation_;
    last_dissipation_ = dissipation;
    ++periods_;
    const bool long_enough = periods_ >= s.relax_periods + s.average_periods;
    settled_ = long_enough;
    if (s.steady_tol > 0)
      settled_ = long_enough && periods_ >= 2 && dissipations_agree(before, dissipation, s.steady_tol);
    return settled_ || (s.steady_tol > 0 && periods_ >= s.max_periods);
  }

  ROTORSWEEP_HD int periods() const { return periods_; }   ///< periods closed
  ROTORSWEEP_HD bool settled() const { return settled_; }  ///< whether the schedule was met

 private:
  int periods_ = 0;
  double last_dissipation_ = 0;
  bool settled_ = false;
};

}  // namespace rotorsweep::ensemble
