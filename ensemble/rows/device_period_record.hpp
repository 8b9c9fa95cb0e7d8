// The record of a period that a member closes on a device (docs/model.md §3): its quadratures'
// channels and its step reducers' (alignment extrema, the error of D from the swing, slips).
#pragma once

#include <limits>

#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/step_reducers.hpp"
#include "kernels/lanes/host_device.hpp"

namespace rotorsweep::ensemble {

/// The period ending at t of a member of schedule s with quadratures quad(p), closed on one lane as
/// LaneScheduler closes it (DeviceMember, TeamMember): the reducers start their next period; at
/// T > 0 (stochastic) there is no integration error of D.
template <class Quadrature>
ROTORSWEEP_HD PeriodRecord device_period_record(const SlotSchedule& s, Quadrature&& quad, double period,
                                                double t, AlignmentExtrema<double>& alignment,
                                                DissipationSwing<double>& swing, bool swing_on,
                                                SlipCounter<double>& slips, bool stochastic) {
  const kernels::Integrals Q = s.quadratures;
  PeriodRecord record;
  record_quadratures(s.channels, Q, record, quad, period, t);
  if (Q.alignment) alignment.end_period(0, record);
  if (swing_on) swing.end_period(0, s.error_rtol, s.atol, record);
  if (s.slips) slips.end_period(0, record);
  if (stochastic) record[Channel::dissipation_error] = std::numeric_limits<double>::quiet_NaN();
  return record;
}

}  // namespace rotorsweep::ensemble
