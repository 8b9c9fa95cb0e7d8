// One device member's way from its start to its retirement (docs/model.md §3, §7 at T > 0), written once
// for every way a device holds a member's rows: on one thread, on a team, in a warp's registers.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ensemble/engine/member_progress.hpp"
#include "ensemble/rows/device_period_record.hpp"
#include "ensemble/rows/member_body.hpp"
#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/steady_dissipation.hpp"
#include "ensemble/rows/step_reducers.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/steppers/lane_status.hpp"

namespace rotorsweep::ensemble {

/// Integrates chunk member k of `slots` with schedule s to its retirement and writes its slot: per
/// step and per period what LaneScheduler does per lane (the same reducers, records and MemberProgress
/// in the same order). `body` holds the member's rows and integrator, already started at slot k (the
/// MemberBody concept: ensemble/rows/member_body.hpp).
template <MemberBody Body>
ROTORSWEEP_HD void run_member(Body& body, const SlotSchedule& s, const SlotViews& slots, std::size_t k) {
  const std::size_t n = s.rows;
  const kernels::Integrals Q = s.quadratures;
  constexpr bool stochastic = Body::stochastic;
  SlipCounter<double> slips(s.slip_rate, s.slip_energies);
  slips.set_damping(0, slots.g[k]);
  if constexpr (stochastic) slips.set_rate(0, body.slip_rate(s, slots.g[k]));
  AlignmentExtrema<double> alignment;
  DissipationSwing<double> swing;
  const bool swing_on = Q.drive && !stochastic;
  if (s.row_profiles) body.profile_start();

  MemberProgress progress;
  SteadyDissipation steady{s.steady_tol};
  for (;;) {
    if (s.slips) body.keep_before();
    const double t_before = body.t();
    if (s.row_profiles) body.profile_before();
    const bool accepted = body.attempt();
    if (Q.alignment) alignment.accumulate(true, body.alignment_integrand());
    if (accepted) {
      if (swing_on) swing.accumulate(true, body.drive());
      if (s.slips) {
        const SlipTurns turns = body.turns(s.slip_energies);
        slips.accumulate_turns(true, turns.largest, turns.squares, body.t() - t_before);
      }
    }
    if (s.row_profiles) body.profile_after(accepted);
    if (body.status() != kernels::LaneStatus::ok) break;
    if (body.t() < body.t_stop()) continue;

    const PeriodRecord record = device_period_record(
        s, [&](std::size_t p) { return body.quadrature(p); }, Body::period, body.t(), alignment, swing,
        swing_on, slips, stochastic);
    const std::size_t closed = std::size_t(progress.stops());
    body.write_rows(slots.end_states + (k * s.end_capacity + closed % s.end_capacity) * n);
    if (s.row_profiles)
      body.profile_take(slots.profiles + (k * s.profile_capacity + closed % s.profile_capacity) * 2 * n);
    body.one([&] {
      double* slot = slots.records + (k * s.record_capacity + closed % s.record_capacity) * channel_count;
      for (std::size_t c = 0; c < channel_count; ++c) slot[c] = record.values[c];
    });
    if (progress.close_stop(s.periods, steady.close(record.dissipation()))) break;
    body.next_period(s.wrap_angles);
  }
  body.one([&] {
    slots.status[k] = std::uint8_t(body.status());
    slots.settled[k] = progress.settled() ? 1 : 0;
    slots.periods[k] = progress.stops();
    slots.steps[2 * k] = body.steps_accepted();
    slots.steps[2 * k + 1] = body.steps_rejected();
  });
  body.write_rows(slots.theta + k * n);
}

}  // namespace rotorsweep::ensemble
