// One member whose rows live in registers across L lanes of a warp, from its start to its retirement
// (docs/architecture.md "Register kernels"): run_member's loop over WarpRows with WarpIntegrator.
#pragma once

#include <cstddef>

#include "ensemble/rows/member_loop.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/warp.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

/// Runs members of Model (kernels::WarpRows: nearest-neighbour rows, uniform or disordered) with
/// Integrator (kernels::WarpIntegrator) at T = 0: each lane its slots' rows, every decision alike in
/// every lane, the member's scalar writes by one lane. The arithmetic is the CPU lanes' but for the
/// order of the sums over rows and the stage solve's eliminations, so members follow the CPU lanes to
/// rounding, not bit for bit.
template <class Model, class Integrator>
struct WarpMember {
  using W = typename Model::Warp;
  using V = typename Model::V;
  using Slots = typename Model::Slots;
  static constexpr std::size_t R = Model::slots_per_lane;
  static constexpr std::size_t kinds = Model::kinds;

  /// Whether members of schedule s run in registers: T = 0, no row profiles, N rows that fill every
  /// lane and fit its R slots, quadratures the instantiation carries, disorder only where it keeps
  /// factors per row.
  static bool fits(const SlotSchedule& s, kernels::Integrals carriable) {
    const kernels::Integrals Q = s.quadratures;
    const bool disordered = s.A_rows || s.anisotropy_rows || s.coupling_rows;
    return !s.stochastic && !s.row_profiles && Slots::fits(s.rows) && (Q | carriable) == carriable &&
           (Model::per_row || !disordered);
  }

  /// Integrates chunk member k of `slots` to its retirement and writes its slot (each lane its rows).
  ROTORSWEEP_HD static void run(const SlotSchedule& s, const SlotViews& slots, std::size_t k) {
    const Slots rows(s.rows);
    Model model(rows, s.quadratures, slot_parameters<Model>(s, slots, k));
    const kernels::RosenbrockTableau& method = s.methods.rosenbrock;
    Integrator integrator(method, {s.rtol, s.atol},
                          {.h_max = s.h_max, .max_steps = s.max_steps, .controller = s.controller},
                          s.first_step_scale);
    Body body{model, integrator, s, {}, {}};
    body.start(slots, k);
    run_member(body, s, slots, k);
  }

 private:
  /// The member in its lanes' registers, as run_member asks (ensemble/rows/member_loop.hpp).
  struct Body {
    static constexpr bool stochastic = false;
    static constexpr double period = Model::period;
    Model& model;
    Integrator& integrator;
    const SlotSchedule& s;
    typename Integrator::State state;
    V theta_before[R];

    ROTORSWEEP_HD void start(const SlotViews& slots, std::size_t k) {
      const Slots& rows = model.slots();
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) {
        const auto real = rows.real(r);
        state.y[r] = kernels::lane_select(real, W::load(slots.y0 + k * s.rows, row_index(r)), V(0.0));
      }
      state.t_stop = Model::period;
      state.tolerance_scale = slots.tolerance_scale[k];
    }
    ROTORSWEEP_HD bool attempt() { return integrator.attempt(model, state); }
    ROTORSWEEP_HD double t() const { return state.t; }
    ROTORSWEEP_HD double t_stop() const { return state.t_stop; }
    ROTORSWEEP_HD kernels::LaneStatus status() const { return state.status; }
    ROTORSWEEP_HD double quadrature(std::size_t p) const { return model.carried_quadrature(state.quad, p); }
    ROTORSWEEP_HD double drive() const { return state.quad[Model::drive_kind]; }
    ROTORSWEEP_HD double alignment_integrand() const {
      return integrator.start_integrands()[Model::alignment_kind];
    }
    ROTORSWEEP_HD double slip_rate(const SlotSchedule& schedule, double) const { return schedule.slip_rate; }
    ROTORSWEEP_HD void keep_before() {
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) theta_before[r] = state.y[r];
    }
    /// Padding slots stay 0 in both states, so they turn by 0.
    ROTORSWEEP_HD SlipTurns turns(bool squares) const {
      V largest(0.0), sum(0.0);
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) {
        const V turn = state.y[r] - theta_before[r];
        largest = kernels::lane_max(largest, kernels::lane_abs(turn));
        sum = sum + turn * turn;
      }
      return {W::max(largest), squares ? W::sum(sum) : 0.0};
    }
    ROTORSWEEP_HD void write_rows(double* out) const {
      const Slots& rows = model.slots();
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) W::store(out, row_index(r), state.y[r], rows.real(r));
    }
    template <class F>
    ROTORSWEEP_HD void one(F&& f) const {
      W::one(f);
    }
    ROTORSWEEP_HD void next_period(bool wrap) {
      ROTORSWEEP_UNROLL
      for (std::size_t kind = 0; kind < kinds; ++kind) state.quad[kind] = 0.0;
      if (!wrap) {
        state.t_stop = state.t + Model::period;
        return;
      }
      state.t = 0.0;
      state.t_stop = Model::period;
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) {
        const V y = state.y[r];
        state.y[r] =
            kernels::lane_from<V>([&](std::size_t l) { return kernels::wrap_2pi(kernels::lane_get(y, l)); });
      }
    }
    ROTORSWEEP_HD double steps_accepted() const { return state.steps_accepted; }
    ROTORSWEEP_HD double steps_rejected() const { return state.steps_rejected; }
    // no row profiles in registers (fits() sends such scenes elsewhere)
    ROTORSWEEP_HD void profile_start() {}
    ROTORSWEEP_HD void profile_before() {}
    ROTORSWEEP_HD void profile_after(bool) {}
    ROTORSWEEP_HD void profile_take(double*) {}

    /// Slot r's ring index where it holds a row, 0 at padding (a safe address that is never written).
    ROTORSWEEP_HD V row_index(std::size_t r) const {
      const Slots& rows = model.slots();
      return kernels::lane_select(rows.real(r), rows.row(r), V(0.0));
    }
  };
};

}  // namespace rotorsweep::ensemble
