// The lane-parallel Rosenbrock stepper (Hairer & Wanner Eq. IV.7.25; its stages: RosenbrockStages) for a
// LaneModel with quadrature states, y' = f(y, t), q' = p(y, t) (docs/model.md §3): one member per lane.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/lane_member_form.hpp"
#include "kernels/steppers/model_concept.hpp"
#include "kernels/steppers/rosenbrock_stages.hpp"

namespace rotorsweep::kernels {

/// RosenbrockStages' form for a block of lanes: LaneMemberForm's parts and evaluate, evaluate_displaced where
/// the model has one, the model's own linearize and stage matrix, the running dot products in component
/// order, and the verdict a mask: the lanes whose stage matrix is positive definite where the Jacobian tells.
template <LaneModel System>
class LaneStageForm : public LaneMemberForm<System> {
  using Base = LaneMemberForm<System>;

 public:
  using typename Base::Context;
  using typename Base::value_type;
  using resolved_type = lane_mask<value_type>;
  static constexpr bool displaced = EvaluatesDisplaced<System>;
  static constexpr bool copies_table = true;

  ROTORSWEEP_HD LaneStageForm(std::size_t n, LaneArena<value_type>& arena)
      : Base(n, arena), jacobian_(n, arena) {}

  ROTORSWEEP_HD value_type add_dot(Context, value_type running, const value_type* a,
                                   const value_type* b) const {
    for (std::size_t k = 0; k < this->n_; ++k) running += a[k] * b[k];
    return running;
  }
  ROTORSWEEP_HD void linearize(Context system, const value_type* y, value_type t, value_type* f,
                               value_type* qdot, value_type* df_dt, value_type* dq_dy, value_type* dq_dt) {
    system.linearize(this->work_, y, t, f, qdot, jacobian_, df_dt, dq_dy, dq_dt);
  }
  /// f at y + displacement (a displaced model) or at `argument` (any other), at time t + tau.
  ROTORSWEEP_HD void evaluate_stage(Context system, const value_type* y, const value_type* argument,
                                    value_type t, value_type tau, value_type* f, value_type* qdot) {
    if constexpr (displaced)
      system.evaluate_displaced(this->work_, y, argument, t, tau, f, qdot);
    else
      this->evaluate(system, argument, t + tau, f, qdot);
  }
  ROTORSWEEP_HD void factor(Context, value_type shift) { jacobian_.factor(shift); }
  ROTORSWEEP_HD void solve(Context, value_type* u) const { jacobian_.solve(u); }
  ROTORSWEEP_HD resolved_type resolved(value_type h) const {
    if constexpr (JacobianWithInertia<typename System::Jacobian>)
      return jacobian_.positive_definite();
    else
      return h == h;
  }

 private:
  typename System::Jacobian jacobian_;
};

/// One attempted step of size h per lane (RosenbrockStages::attempt), any tableau of the list.
/// Scratch: views over caller-owned storage (kernels::counted_storage sizes it).
template <LaneModel System>
class RosenbrockStepper : public RosenbrockStages<LaneStageForm<System>> {
 public:
  using V = typename System::lane_type;

  ROTORSWEEP_HD RosenbrockStepper(const System& system, const RosenbrockTableau& table, LaneArena<V>& arena)
      : RosenbrockStages<LaneStageForm<System>>(system.dimension(), system.quadrature_count(), table, arena) {
  }
};

}  // namespace rotorsweep::kernels
