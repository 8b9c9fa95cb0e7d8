// One member on one `double` lane from its start to its retirement: the device backend's scheduler
// (one member per GPU thread), doing in one lane what LaneScheduler does per lane (docs/model.md §3).
#pragma once

#include <cstddef>

#include "ensemble/engine/member_progress.hpp"
#include "ensemble/engine/member_result.hpp"
#include "ensemble/engine/member_slots.hpp"
#include "ensemble/engine/step_reducers.hpp"
#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/lane_state.hpp"

namespace rotorsweep::ensemble {

/// Runs members of Model (on the double lane) with Stepper. The arithmetic per step and per
/// period is LaneScheduler's, in the same order, so a member's bits do not depend on the backend.
template <class Model, class Stepper>
struct DeviceMember {
  using Integrator = kernels::AdaptiveIntegrator<Model, Stepper>;
  static constexpr std::size_t nq = Model::max_quadratures;  ///< quadrature slots of the state

  /// Lane values of scratch one member needs at N rows: what run() builds, counted over an arena
  /// without storage.
  ROTORSWEEP_HD static std::size_t storage_size(std::size_t n) {
    return kernels::counted_storage<double>([&](kernels::LaneArena<double>& arena) {
      SlotSchedule schedule;
      schedule.rows = n;
      const Parts parts(schedule, arena);
    });
  }

  /// Integrates chunk member k of `slots` to its retirement and writes its slot. `storage` holds
  /// at least storage_size(rows) values.
  ROTORSWEEP_HD static void run(const SlotSchedule& s, const SlotViews& slots, std::size_t k, double* storage,
                                std::size_t capacity) {
    const std::size_t n = s.rows;
    kernels::LaneArena<double> arena(storage, capacity);
    Parts parts(s, arena);
    const kernels::Integrals Q = s.quadratures;
    Model& model = parts.model;
    Integrator& integrator = parts.integrator;
    kernels::LaneState<double>& state = parts.state;
    double* theta_before = parts.theta_before;

    for (std::size_t j = 0; j < n; ++j) state.y[j] = slots.y0[k * n + j];
    state.t_stop = Model::period;
    state.tolerance_scale = slots.tolerance_scale[k];
    model.set_lane(0, {slots.A[k], slots.g[k], slots.strict_fm[k] != 0});
    AlignmentExtrema<double> alignment;
    DissipationSwing<double> swing;
    SlipCounter<double> slips(s.slip_rate);

    MemberProgress progress;
    for (;;) {
      double t_before = 0;
      if (s.slips) {
        for (std::size_t j = 0; j < n; ++j) theta_before[j] = state.y[j];
        t_before = state.t;
      }
      const bool accepted = integrator.attempt(model, state);
      if (Q.alignment) alignment.accumulate(true, integrator.start_integrands()[Q.alignment_index()]);
      if (accepted) {
        if (Q.drive) swing.accumulate(true, state.quad[Q.drive_index()]);
        if (s.slips) slips.accumulate(true, n, theta_before, state.y, state.t - t_before);
      }
      if (state.status[0] != kernels::LaneStatus::ok) break;
      if (state.t < state.t_stop) continue;

      PeriodRecord record;
      record_quadratures(
          s.channels, Q, record, [&](std::size_t p) { return state.quad[p]; }, Model::period);
      if (Q.alignment) alignment.end_period(0, record);
      if (Q.drive) swing.end_period(0, s.error_rtol, s.atol, record);
      if (s.slips) slips.end_period(0, record);
      const std::size_t closed = std::size_t(progress.periods());
      double* end = slots.end_states + (k * s.end_capacity + closed % s.end_capacity) * n;
      for (std::size_t j = 0; j < n; ++j) end[j] = state.y[j];
      const std::size_t ring = s.record_capacity;
      double* slot = slots.records + (k * ring + closed % ring) * channel_count;
      for (std::size_t c = 0; c < channel_count; ++c) slot[c] = record.values[c];
      if (progress.close_period(s.periods, record.dissipation())) break;
      next_period(s, state);
    }
    slots.status[k] = std::uint8_t(state.status[0]);
    slots.settled[k] = progress.settled() ? 1 : 0;
    slots.periods[k] = progress.periods();
    slots.steps[2 * k] = state.steps_accepted;
    slots.steps[2 * k + 1] = state.steps_rejected;
    for (std::size_t j = 0; j < n; ++j) slots.theta[k * n + j] = state.y[j];
  }

 private:
  /// What a member builds over its scratch (storage_size counts the same).
  struct Parts {
    Model model;
    Integrator integrator;
    kernels::LaneState<double> state;
    double* theta_before;  ///< θ at the start of an attempt (slip counter)

    ROTORSWEEP_HD Parts(const SlotSchedule& s, kernels::LaneArena<double>& arena)
        : model(s.rows, arena, s.quadratures),
          integrator(model, {s.rtol, s.atol},
                     {.h_max = s.h_max, .max_steps = s.max_steps, .controller = s.controller},
                     s.first_step_scale, arena),
          state(s.rows, nq, arena),
          theta_before(arena.take(s.rows)) {}
  };

  /// IntegrationLoop::next_period on the one lane.
  ROTORSWEEP_HD static void next_period(const SlotSchedule& s, kernels::LaneState<double>& state) {
    for (std::size_t p = 0; p <= nq; ++p) state.quad[p] = 0.0;
    if (!s.wrap_angles) {
      state.t_stop = state.t + Model::period;
      return;
    }
    state.t = 0.0;
    state.t_stop = Model::period;
    for (std::size_t j = 0; j < s.rows; ++j) state.y[j] = kernels::wrap_2pi(state.y[j]);
  }
};

}  // namespace rotorsweep::ensemble
