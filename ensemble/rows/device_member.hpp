// One member on one `double` lane from its start to its retirement: the device backend's scheduler
// (one member per GPU thread), run_member's loop over the member's rows on one thread (docs/model.md §3).
#pragma once

#include <cstddef>

#include "ensemble/rows/member_loop.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/row_profile_integral.hpp"
#include "ensemble/rows/step_reducers.hpp"
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
    kernels::LaneArena<double> arena(storage, capacity);
    Parts parts(s, arena);
    Body body{parts, s};
    body.start(slots, k);
    run_member(body, s, slots, k);
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
          model(slot_model<Model>(s, arena)),
          integrator(make_integrator(model, s, settings, arena)),
          state(s.rows, nq, arena),
          theta_before(arena.take(s.rows)),
          profile(s.row_profiles ? s.rows : 0, arena),
          profile_work(s.row_profiles ? s.rows : 0, arena) {}
  };

  /// The member on its one lane, as run_member asks (ensemble/rows/member_loop.hpp).
  struct Body {
    static constexpr bool stochastic = DeviceMember::stochastic;
    static constexpr double period = Model::period;
    Parts& parts;
    const SlotSchedule& s;

    ROTORSWEEP_HD void start(const SlotViews& slots, std::size_t k) {
      kernels::LaneState<double>& state = parts.state;
      for (std::size_t j = 0; j < s.rows; ++j) state.y[j] = slots.y0[k * s.rows + j];
      state.t_stop = Model::period;
      state.tolerance_scale = slots.tolerance_scale[k];
      parts.model.set_lane(0, slot_parameters<Model>(s, slots, k));
      if constexpr (stochastic)
        parts.integrator.start_lane(0, slots.noise_key[k], slots.g[k], parts.model.curvature_bound(0));
    }
    ROTORSWEEP_HD bool attempt() { return parts.integrator.attempt(parts.model, parts.state); }
    ROTORSWEEP_HD double t() const { return parts.state.t; }
    ROTORSWEEP_HD double t_stop() const { return parts.state.t_stop; }
    ROTORSWEEP_HD kernels::LaneStatus status() const { return parts.state.status[0]; }
    ROTORSWEEP_HD double quadrature(std::size_t p) const { return parts.state.quad[p]; }
    ROTORSWEEP_HD double drive() const { return parts.state.quad[s.quadratures.drive_index()]; }
    ROTORSWEEP_HD double alignment_integrand() const {
      return parts.integrator.start_integrands()[s.quadratures.alignment_index()];
    }
    ROTORSWEEP_HD double slip_rate(const SlotSchedule& schedule, double g) const {
      return thermal_slip_rate(schedule.slip_rate, schedule.temperature, g, parts.integrator.step_size(0));
    }
    ROTORSWEEP_HD void keep_before() {
      for (std::size_t j = 0; j < s.rows; ++j) parts.theta_before[j] = parts.state.y[j];
    }
    ROTORSWEEP_HD SlipTurns turns(bool squares) const {
      SlipTurns out;
      for (std::size_t j = 0; j < s.rows; ++j) {
        const double turn = parts.state.y[j] - parts.theta_before[j];
        out.largest = kernels::lane_max(out.largest, kernels::lane_abs(turn));
        if (squares) out.squares += turn * turn;
      }
      return out;
    }
    ROTORSWEEP_HD void write_rows(double* out) const {
      for (std::size_t j = 0; j < s.rows; ++j) out[j] = parts.state.y[j];
    }
    template <class F>
    ROTORSWEEP_HD void one(F&& f) const {
      f();
    }
    /// IntegrationLoop::next_period on the one lane.
    ROTORSWEEP_HD void next_period(bool wrap) {
      kernels::LaneState<double>& state = parts.state;
      for (std::size_t p = 0; p <= nq; ++p) state.quad[p] = 0.0;
      if (!wrap) {
        state.t_stop = state.t + Model::period;
        return;
      }
      state.t = 0.0;
      state.t_stop = Model::period;
      for (std::size_t j = 0; j < s.rows; ++j) state.y[j] = kernels::wrap_2pi(state.y[j]);
    }
    ROTORSWEEP_HD double steps_accepted() const { return parts.state.steps_accepted; }
    ROTORSWEEP_HD double steps_rejected() const { return parts.state.steps_rejected; }
    // the row profile, for a model that reports one (as RowProfileObserver on the CPU)
    static constexpr bool profiles = kernels::ReportsRowProfile<Model>;
    ROTORSWEEP_HD void profile_start() {
      if constexpr (profiles) parts.profile.start(parts.model, parts.profile_work, parts.state, 0);
    }
    ROTORSWEEP_HD void profile_before() {
      if constexpr (profiles) parts.profile.before_step(parts.model, parts.profile_work, parts.state);
    }
    ROTORSWEEP_HD void profile_after(bool accepted) {
      if constexpr (profiles)
        parts.profile.after_step(parts.model, parts.profile_work, parts.state, accepted);
    }
    ROTORSWEEP_HD void profile_take(double* out) {
      if constexpr (profiles) parts.profile.take_period(0, out);
    }
  };

  ROTORSWEEP_HD static typename Integrator::Settings integrator_settings(const SlotSchedule& s) {
    if constexpr (stochastic)
      return {s.temperature, s.steps_per_period, s.step_fraction};
    else
      return {s.methods.template get<typename Integrator::Method>(),
              {s.rtol, s.atol},
              {.h_max = s.h_max, .max_steps = s.max_steps, .controller = s.controller}};
  }

  ROTORSWEEP_HD static Integrator make_integrator(const Model& model, const SlotSchedule& s,
                                                  const typename Integrator::Settings& settings,
                                                  kernels::LaneArena<double>& arena) {
    if constexpr (stochastic)
      return Integrator(model, settings, arena);
    else
      return Integrator(model, settings.method, settings.tolerances, settings.limits, s.first_step_scale,
                        arena);
  }
};

}  // namespace rotorsweep::ensemble
