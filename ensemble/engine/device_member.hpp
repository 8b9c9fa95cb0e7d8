// One member on one `double` lane from its start to its retirement: the device backend's scheduler
// (one member per GPU thread), doing in one lane what LaneScheduler does per lane (docs/model.md §3).
#pragma once

#include <cstddef>

#include "ensemble/engine/device_period_record.hpp"
#include "ensemble/engine/member_progress.hpp"
#include "ensemble/engine/member_result.hpp"
#include "ensemble/engine/member_slots.hpp"
#include "ensemble/engine/step_reducers.hpp"
#include "ensemble/rows/row_profile_integral.hpp"
#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/lane_state.hpp"

namespace rotorsweep::ensemble {

/// Runs members of Model (on the double lane) with Integrator (kernels::AdaptiveIntegrator, or
/// kernels::LeimkuhlerMatthews at T > 0). The arithmetic per step and per period is LaneScheduler's, in
/// the same order, so a member's bits do not depend on the backend.
template <class Model, class Integrator>
struct DeviceMember {
  static constexpr std::size_t nq = Model::max_quadratures;  ///< quadrature slots of the state
  static constexpr bool stochastic = Integrator::stochastic;

  /// Lane values of scratch one member of schedule `s` needs: what run() builds, counted over an
  /// arena without storage.
  ROTORSWEEP_HD static std::size_t storage_size(const SlotSchedule& s) {
    return kernels::counted_storage<double>(
        [&](kernels::LaneArena<double>& arena) { const Parts parts(s, arena); });
  }

  /// Integrates chunk member k of `slots` to its retirement and writes its slot. `storage` holds
  /// at least storage_size(s) values.
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
    model.set_lane(0, slot_parameters<Model>(s, slots, k));
    SlipCounter<double> slips(s.slip_rate, s.slip_energies);
    slips.set_damping(0, slots.g[k]);
    if constexpr (stochastic) {
      const double g = slots.g[k];
      integrator.start_lane(0, slots.noise_key[k], g, model.curvature_bound(0));
      slips.set_rate(0, thermal_slip_rate(s.slip_rate, s.temperature, g, integrator.step_size(0)));
    }
    AlignmentExtrema<double> alignment;
    DissipationSwing<double> swing;
    const bool swing_on = Q.drive && !stochastic;
    if (s.row_profiles) parts.profile.start(model, parts.profile_work, state, 0);

    MemberProgress progress;
    for (;;) {
      double t_before = 0;
      if (s.slips) {
        for (std::size_t j = 0; j < n; ++j) theta_before[j] = state.y[j];
        t_before = state.t;
      }
      if (s.row_profiles) parts.profile.before_step(model, parts.profile_work, state);
      const bool accepted = integrator.attempt(model, state);
      if (Q.alignment) alignment.accumulate(true, integrator.start_integrands()[Q.alignment_index()]);
      if (accepted) {
        if (swing_on) swing.accumulate(true, state.quad[Q.drive_index()]);
        if (s.slips) slips.accumulate(true, n, theta_before, state.y, state.t - t_before);
      }
      if (s.row_profiles) parts.profile.after_step(model, parts.profile_work, state, accepted);
      if (state.status[0] != kernels::LaneStatus::ok) break;
      if (state.t < state.t_stop) continue;

      const PeriodRecord record = device_period_record(
          s, [&](std::size_t p) { return state.quad[p]; }, Model::period, state.t, alignment, swing, swing_on,
          slips, stochastic);
      const std::size_t closed = std::size_t(progress.periods());
      double* end = slots.end_states + (k * s.end_capacity + closed % s.end_capacity) * n;
      for (std::size_t j = 0; j < n; ++j) end[j] = state.y[j];
      if (s.row_profiles)
        parts.profile.take_period(
            0, slots.profiles + (k * s.profile_capacity + closed % s.profile_capacity) * 2 * n);
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
  /// What a member builds over its scratch (storage_size counts the same); the row profile's parts
  /// only where the schedule asks for them.
  struct Parts {
    typename Integrator::Settings settings;
    Model model;
    Integrator integrator;
    kernels::LaneState<double> state;
    double* theta_before;  ///< θ at the start of an attempt (slip counter)
    RowProfileIntegral<Model, stochastic> profile;
    typename Model::Workspace profile_work;  ///< the profile's evaluations (apart from the stepper's)

    ROTORSWEEP_HD Parts(const SlotSchedule& s, kernels::LaneArena<double>& arena)
        : settings(integrator_settings(s)),
          model(s.rows, arena, s.quadratures),
          integrator(make_integrator(model, s, settings, arena)),
          state(s.rows, nq, arena),
          theta_before(arena.take(s.rows)),
          profile(s.row_profiles ? s.rows : 0, arena),
          profile_work(s.row_profiles ? s.rows : 0, arena) {}
  };

  ROTORSWEEP_HD static typename Integrator::Settings integrator_settings(const SlotSchedule& s) {
    if constexpr (stochastic)
      return {s.temperature, s.steps_per_period, s.step_fraction};
    else
      return {kernels::stepper_method<typename Integrator::Method>(s.stepper),
              {s.rtol, s.atol},
              {.h_max = s.h_max, .max_steps = s.max_steps, .controller = s.controller}};
  }

  ROTORSWEEP_HD static Integrator make_integrator(const Model& model, const SlotSchedule& s,
                                                  const typename Integrator::Settings& settings,
                                                  kernels::LaneArena<double>& arena) {
    if constexpr (stochastic)
      return Integrator(model, settings, arena);
    else
      return Integrator(model, settings.method, settings.tolerances, settings.limits, s.first_step_scale, arena);
  }

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
