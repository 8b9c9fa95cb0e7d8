// One member on a team of threads from its start to its retirement (docs/architecture.md "Teams"):
// DeviceMember's state machine (docs/model.md §3, §7 at T > 0), its row loops over each rank's rows.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ensemble/engine/device_period_record.hpp"
#include "ensemble/engine/member_progress.hpp"
#include "ensemble/engine/member_result.hpp"
#include "ensemble/engine/member_slots.hpp"
#include "ensemble/engine/step_reducers.hpp"
#include "ensemble/engine/team_row_profile.hpp"
#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/team_integrator.hpp"

namespace rotorsweep::ensemble {

/// Runs members of a row model on a team with Integrator (TeamIntegrator<Team, Stepper>, or
/// TeamLeimkuhlerMatthews<Team, Model> at T > 0): per step and per period what DeviceMember does on one
/// thread (the same reducers, records, MemberProgress, wrap and slot), the rows split among the ranks
/// and the team's sums where DeviceMember sums over rows. It runs every observable of nearest-neighbour
/// rows (uniform or disordered) and of coupling tables (periodic or open), the row profiles included.
template <class Team, class Integrator>
struct TeamMember {
  using Model = typename Integrator::Model;
  static constexpr bool stochastic = Integrator::stochastic;

  /// Whether this team member runs members of schedule s: those of its kind of integrator.
  static bool team_schedule_fits(const SlotSchedule& s) { return s.stochastic == stochastic; }

  /// Values of scratch a member of schedule s needs on a team of `ranks`, shared by the team.
  ROTORSWEEP_HD static std::size_t storage_size(const SlotSchedule& s, std::size_t ranks) {
    return kernels::counted_storage<double>(
        [&](kernels::LaneArena<double>& arena) { const Parts parts(s, ranks, arena); });
  }

  /// Integrates chunk member k of `slots` to its retirement on `team` and writes its slot; `storage`
  /// (the team's, at least storage_size values) holds its vectors.
  ROTORSWEEP_HD static void run(Team& team, const SlotSchedule& s, const SlotViews& slots, std::size_t k,
                                double* storage, std::size_t capacity) {
    const std::size_t n = s.rows, ranks = team.size();
    kernels::LaneArena<double> arena(storage, capacity);
    Parts parts(s, ranks, arena);
    team.sync();
    const kernels::Integrals Q = s.quadratures;
    Model& model = parts.model;
    model.set_lane(0, slot_parameters<Model>(s, slots, k));
    kernels::TeamMemberState state;
    state.y = parts.theta;
    each_row(team, n, [&](std::size_t j) { state.y[j] = slots.y0[k * n + j]; });
    state.t_stop = Model::period;
    state.tolerance_scale = slots.tolerance_scale[k];
    SlipCounter<double> slips(s.slip_rate, s.slip_energies);
    slips.set_damping(0, slots.g[k]);
    if constexpr (stochastic) {
      const double g = slots.g[k];
      parts.integrator.start(slots.noise_key[k], g, model.curvature_bound(0));
      slips.set_rate(0, thermal_slip_rate(s.slip_rate, s.temperature, g, parts.integrator.step_size()));
    }
    AlignmentExtrema<double> alignment;
    DissipationSwing<double> swing;
    const bool swing_on = Q.drive && !stochastic;
    if (s.row_profiles) parts.profile.start(team, model, state);

    MemberProgress progress;
    for (;;) {
      if (s.slips) each_row(team, n, [&](std::size_t j) { parts.theta_before[j] = state.y[j]; });
      const double t_before = state.t;
      if (s.row_profiles) parts.profile.before_step(team, model, state);
      const bool accepted = parts.integrator.attempt(team, model, state);
      if (Q.alignment) alignment.accumulate(true, parts.integrator.start_integrands()[Q.alignment_index()]);
      if (accepted) {
        if (swing_on) swing.accumulate(true, state.quad[Q.drive_index()]);
        if (s.slips) {
          const double largest = team.max([&](std::size_t r) {
            const kernels::TeamRows rows = kernels::team_rows(n, ranks, r);
            double m = 0.0;
            for (std::size_t j = rows.begin; j < rows.end; ++j) {
              const double turn = state.y[j] - parts.theta_before[j];
              m = kernels::lane_max(m, kernels::lane_abs(turn));
            }
            return m;
          });
          const double squares = !s.slip_energies ? 0.0 : team.sum([&](std::size_t r) {
            const kernels::TeamRows rows = kernels::team_rows(n, ranks, r);
            double sum = 0.0;
            for (std::size_t j = rows.begin; j < rows.end; ++j) {
              const double turn = state.y[j] - parts.theta_before[j];
              sum += turn * turn;
            }
            return sum;
          });
          slips.accumulate_turns(true, largest, squares, state.t - t_before);
        }
      }
      if (s.row_profiles) parts.profile.after_step(team, model, state, accepted);
      if (state.status != kernels::LaneStatus::ok) break;
      if (state.t < state.t_stop) continue;

      const PeriodRecord record = device_period_record(
          s, [&](std::size_t p) { return state.quad[p]; }, Model::period, state.t, alignment, swing, swing_on,
          slips, stochastic);
      const std::size_t closed = std::size_t(progress.periods());
      double* end = slots.end_states + (k * s.end_capacity + closed % s.end_capacity) * n;
      each_row(team, n, [&](std::size_t j) { end[j] = state.y[j]; });
      if (s.row_profiles)
        parts.profile.take_period(
            team, slots.profiles + (k * s.profile_capacity + closed % s.profile_capacity) * 2 * n);
      team.one([&] {
        double* slot = slots.records + (k * s.record_capacity + closed % s.record_capacity) * channel_count;
        for (std::size_t c = 0; c < channel_count; ++c) slot[c] = record.values[c];
      });
      if (progress.close_period(s.periods, record.dissipation())) break;
      for (double& q : state.quad) q = 0.0;
      if (s.wrap_angles) {
        state.t = 0.0;
        state.t_stop = Model::period;
        each_row(team, n, [&](std::size_t j) { state.y[j] = kernels::wrap_2pi(state.y[j]); });
      } else {
        state.t_stop = state.t + Model::period;
      }
    }
    team.one([&] {
      slots.status[k] = std::uint8_t(state.status);
      slots.settled[k] = progress.settled() ? 1 : 0;
      slots.periods[k] = progress.periods();
      slots.steps[2 * k] = state.steps_accepted;
      slots.steps[2 * k + 1] = state.steps_rejected;
    });
    each_row(team, n, [&](std::size_t j) { slots.theta[k * n + j] = state.y[j]; });
  }

 private:
  /// What a member builds over the team's scratch (storage_size counts the same).
  struct Parts {
    Model model;
    Integrator integrator;
    double* theta;         ///< the state θ
    double* theta_before;  ///< θ at the start of an attempt (slip counter)
    TeamRowProfileIntegral<Team, Model, stochastic> profile;  ///< sized only where the schedule asks for it

    ROTORSWEEP_HD Parts(const SlotSchedule& s, std::size_t ranks, kernels::LaneArena<double>& arena)
        : model(s.rows, arena, s.quadratures),
          integrator(make_integrator(model, s, ranks, arena)),
          theta(arena.take(s.rows)),
          theta_before(arena.take(s.rows)),
          profile(s.row_profiles ? s.rows : 0, arena) {}
  };

  ROTORSWEEP_HD static Integrator make_integrator(const Model& model, const SlotSchedule& s,
                                                  std::size_t ranks, kernels::LaneArena<double>& arena) {
    if constexpr (stochastic)
      return Integrator(model, ranks, {s.temperature, s.steps_per_period, s.step_fraction}, arena);
    else
      return Integrator(model, ranks, kernels::stepper_method<typename Integrator::Method>(s.stepper),
                        {s.rtol, s.atol}, {.h_max = s.h_max, .max_steps = s.max_steps, .controller = s.controller},
                        s.first_step_scale, arena);
  }

  /// row(j) for every row, each rank its own.
  template <class Row>
  ROTORSWEEP_HD static void each_row(Team& team, std::size_t n, Row&& row) {
    team.each([&](std::size_t r) {
      const kernels::TeamRows rows = kernels::team_rows(n, team.size(), r);
      for (std::size_t j = rows.begin; j < rows.end; ++j) row(j);
    });
  }
};

}  // namespace rotorsweep::ensemble
