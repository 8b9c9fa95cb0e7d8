// One member on a team of threads from its start to its retirement (docs/architecture.md "Teams"):
// run_member's loop (docs/model.md §3, §7 at T > 0) with its row loops over each rank's rows.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ensemble/rows/member_loop.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/step_reducers.hpp"
#include "ensemble/rows/team_row_profile.hpp"
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
    kernels::LaneArena<double> arena(storage, capacity);
    Parts parts(s, team.size(), arena);
    team.sync();
    Body body{team, parts, s, {}};
    body.start(slots, k);
    run_member(body, s, slots, k);
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
        : model(slot_model<Model>(s, arena)),
          integrator(make_integrator(model, s, ranks, arena)),
          theta(arena.take(s.rows)),
          theta_before(arena.take(s.rows)),
          profile(s.row_profiles ? s.rows : 0, arena) {}
  };

  /// The member on the team, as run_member asks (ensemble/rows/member_loop.hpp): each rank its rows,
  /// the team's sums and maxima where one thread's run sums over rows.
  struct Body {
    static constexpr bool stochastic = TeamMember::stochastic;
    static constexpr double period = Model::period;
    Team& team;
    Parts& parts;
    const SlotSchedule& s;
    kernels::TeamMemberState state;

    ROTORSWEEP_HD void start(const SlotViews& slots, std::size_t k) {
      parts.model.set_lane(0, slot_parameters<Model>(s, slots, k));
      state.y = parts.theta;
      each_row([&](std::size_t j) { state.y[j] = slots.y0[k * s.rows + j]; });
      state.t_stop = Model::period;
      state.tolerance_scale = slots.tolerance_scale[k];
      if constexpr (stochastic)
        parts.integrator.start(slots.noise_key[k], slots.g[k], parts.model.curvature_bound(0));
    }
    ROTORSWEEP_HD bool attempt() { return parts.integrator.attempt(team, parts.model, state); }
    ROTORSWEEP_HD double t() const { return state.t; }
    ROTORSWEEP_HD double t_stop() const { return state.t_stop; }
    ROTORSWEEP_HD kernels::LaneStatus status() const { return state.status; }
    ROTORSWEEP_HD double quadrature(std::size_t p) const { return state.quad[p]; }
    ROTORSWEEP_HD double drive() const { return state.quad[s.quadratures.drive_index()]; }
    ROTORSWEEP_HD double alignment_integrand() const {
      return parts.integrator.start_integrands()[s.quadratures.alignment_index()];
    }
    ROTORSWEEP_HD double slip_rate(const SlotSchedule& schedule, double g) const {
      return thermal_slip_rate(schedule.slip_rate, schedule.temperature, g, parts.integrator.step_size());
    }
    ROTORSWEEP_HD void keep_before() {
      each_row([&](std::size_t j) { parts.theta_before[j] = state.y[j]; });
    }
    ROTORSWEEP_HD SlipTurns turns(bool squares) const {
      const std::size_t n = s.rows, ranks = team.size();
      SlipTurns out;
      out.largest = team.max([&](std::size_t r) {
        const kernels::TeamRows rows = kernels::team_rows(n, ranks, r);
        double m = 0.0;
        for (std::size_t j = rows.begin; j < rows.end; ++j)
          m = kernels::lane_max(m, kernels::lane_abs(state.y[j] - parts.theta_before[j]));
        return m;
      });
      if (squares)
        out.squares = team.sum([&](std::size_t r) {
          const kernels::TeamRows rows = kernels::team_rows(n, ranks, r);
          double sum = 0.0;
          for (std::size_t j = rows.begin; j < rows.end; ++j) {
            const double turn = state.y[j] - parts.theta_before[j];
            sum += turn * turn;
          }
          return sum;
        });
      return out;
    }
    ROTORSWEEP_HD void write_rows(double* out) const {
      each_row([&](std::size_t j) { out[j] = state.y[j]; });
    }
    template <class F>
    ROTORSWEEP_HD void one(F&& f) const {
      team.one(f);
    }
    ROTORSWEEP_HD void next_period(bool wrap) {
      for (double& q : state.quad) q = 0.0;
      if (wrap) {
        state.t = 0.0;
        state.t_stop = Model::period;
        each_row([&](std::size_t j) { state.y[j] = kernels::wrap_2pi(state.y[j]); });
      } else {
        state.t_stop = state.t + Model::period;
      }
    }
    ROTORSWEEP_HD double steps_accepted() const { return state.steps_accepted; }
    ROTORSWEEP_HD double steps_rejected() const { return state.steps_rejected; }
    ROTORSWEEP_HD void profile_start() { parts.profile.start(team, parts.model, state); }
    ROTORSWEEP_HD void profile_before() { parts.profile.before_step(team, parts.model, state); }
    ROTORSWEEP_HD void profile_after(bool accepted) {
      parts.profile.after_step(team, parts.model, state, accepted);
    }
    ROTORSWEEP_HD void profile_take(double* out) { parts.profile.take_period(team, out); }

    /// row(j) for every row, each rank its own.
    template <class Row>
    ROTORSWEEP_HD void each_row(Row&& row) const {
      team.each([&](std::size_t r) {
        const kernels::TeamRows rows = kernels::team_rows(s.rows, team.size(), r);
        for (std::size_t j = rows.begin; j < rows.end; ++j) row(j);
      });
    }
  };

  ROTORSWEEP_HD static Integrator make_integrator(const Model& model, const SlotSchedule& s,
                                                  std::size_t ranks, kernels::LaneArena<double>& arena) {
    if constexpr (stochastic)
      return Integrator(model, ranks, {s.temperature, s.steps_per_period, s.step_fraction}, arena);
    else
      return Integrator(model, ranks, s.methods.template get<typename Integrator::Method>(), {s.rtol, s.atol},
                        {.h_max = s.h_max, .max_steps = s.max_steps, .controller = s.controller},
                        s.first_step_scale, arena);
  }
};

}  // namespace rotorsweep::ensemble
