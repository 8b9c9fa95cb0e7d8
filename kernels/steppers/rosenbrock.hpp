// Lane-parallel Rosenbrock stepper (linearly implicit, transformed form, Hairer & Wanner
// Eq. IV.7.25) for an ODE with quadrature states: y' = f(y, t), q' = p(y, t) (docs/model.md §3).
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/model_concept.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"
#include "kernels/steppers/stage_combination.hpp"

namespace rotorsweep::kernels {

/// One attempted step of size h per lane. The quadrature states are part of the ODE: their
/// Jacobian rows ∂p/∂y enter the stages exactly (the augmented Jacobian is block lower
/// triangular, so its stage solve is the model's own solve plus one dot product per
/// quadrature), which keeps them at the method's full order.
///
/// The tableau is data (any RosenbrockTableau, chosen at run time): every stage forms its vectors in
/// one pass over the components with the tableau's nonzero terms in order (combine_stages), so a
/// step gives the bits of the same formulas written out term by term, and one instantiation serves
/// every linearly implicit stepper of the list.
///
/// Scratch: views over caller-owned storage (kernels::counted_storage sizes it).
template <LaneModel System>
class RosenbrockStepper {
 public:
  using V = typename System::lane_type;
  using Method = RosenbrockTableau;
  static constexpr std::size_t nq = System::max_quadratures;  ///< storage; quadratures_ are carried

  ROTORSWEEP_HD RosenbrockStepper(const System& system, const RosenbrockTableau& table, LaneArena<V>& arena)
      : table_(table),
        n_(system.dimension()),
        quadratures_(system.quadrature_count()),
        work_(n_, arena),
        jacobian_(n_, arena),
        f_(arena.take(n_)),
        df_dt_(arena.take(n_)),
        argument_(arena.take(n_)),
        stages_(arena.take(std::size_t(table.stages) * n_)),
        dq_dy_(arena.take(nq * n_ + 1)),
        qdot_(arena.take(nq + 1)),
        start_qdot_(arena.take(nq + 1)),
        dq_dt_(arena.take(nq + 1)),
        quad_stages_(arena.take(std::size_t(table.stages) * nq + 1)) {}

  ROTORSWEEP_HD const char* name() const { return table_.name; }
  ROTORSWEEP_HD int order() const { return table_.order; }
  ROTORSWEEP_HD int embedded_order() const { return table_.embedded_order; }
  /// Right-hand side evaluations per attempt: the linearisation and one per later stage.
  ROTORSWEEP_HD int evaluations() const { return table_.stages; }

  /// One step of size h from (t, y, q). Returns the lanes where the step resolves every
  /// unstable direction of J: where J has an eigenvalue λ > 1/(hγ), the stage solves damp a
  /// mode that grows like exp(λt) (an L-stable method turns a saddle into a false attractor,
  /// and the embedded estimate shares the error); such a lane must retry with a smaller h.
  ROTORSWEEP_HD lane_mask<V> attempt(const System& system, V t, V h, const V* y, const V* q, V* y_new,
                                     V* q_new, V* y_error, V* q_error) {
    system.linearize(work_, y, t, f_, start_qdot_, jacobian_, df_dt_, dq_dy_, dq_dt_);
    const StageScalars scalars{t, h, h * V(table_.gamma), V(1.0) / h};
    jacobian_.factor(V(1.0) / scalars.h_gamma);
    for (int i = 0; i < table_.stages; ++i) run_stage(system, scalars, y, i);
    combine(y, n_, stages_, n_, y_new, y_error);
    combine(q, quadratures_, quad_stages_, quadratures_, q_new, q_error);
    if constexpr (JacobianWithInertia<typename System::Jacobian>)
      return jacobian_.positive_definite();
    else
      return h == h;
  }

  /// The quadratures' integrands at the start of the last attempt (from its linearisation).
  ROTORSWEEP_HD const V* start_integrands() const { return start_qdot_; }

 private:
  static constexpr int max_terms = RosenbrockTableau::max_stages;
  using Terms = StageTerms<V, max_terms>;

  struct StageScalars {
    V t, h, h_gamma, inv_h;
  };

  /// Stage i: evaluate f at y + Σ a_ij U_j, form its right-hand side, solve for U_i. A model that
  /// EvaluatesDisplaced gets the displacement Σ a_ij U_j from the step's start instead.
  ROTORSWEEP_HD void run_stage(const System& system, const StageScalars& s, const V* y, int i) {
    const std::size_t n = n_;
    if (i > 0) {
      constexpr bool displaced = EvaluatesDisplaced<System>;
      Terms arguments;
      for (int j = 0; j < i; ++j)
        if (table_.a[i][j] != 0.0) arguments.add(V(table_.a[i][j]), stage(j));
      combine_stages(
          arguments, [&](std::size_t k) { return displaced ? V(0.0) : y[k]; }, argument_, 0, n);
      const V alpha(table_.alpha[i]);
      if constexpr (displaced)
        system.evaluate_displaced(work_, y, argument_, s.t, alpha * s.h, f_, qdot_);
      else
        system.evaluate(work_, argument_, s.t + alpha * s.h, f_, qdot_);
    }
    const V time_weight = V(table_.gamma_sum[i]) * s.h;
    Terms earlier;  // c_ij / h U_j for every j < i (a zero weight adds a zero)
    for (int j = 0; j < i; ++j) earlier.add(V(table_.c[i][j]) * s.inv_h, stage(j));
    V* u = stage(i);
    combine_stages(
        earlier, [&](std::size_t k) { return f_[k] + time_weight * df_dt_[k]; }, u, 0, n);
    jacobian_.solve(u);

    const std::size_t carried = quadratures_;
    for (std::size_t p = 0; p < carried; ++p) {
      const V* grad = dq_dy_ + p * n;
      V sum = (i == 0 ? start_qdot_ : qdot_)[p] + time_weight * dq_dt_[p];
      for (std::size_t k = 0; k < n; ++k) sum += grad[k] * u[k];
      for (int j = 0; j < i; ++j) sum += earlier.weight[j] * quad_stages_[std::size_t(j) * carried + p];
      quad_stages_[std::size_t(i) * carried + p] = s.h_gamma * sum;
    }
  }

  ROTORSWEEP_HD V* stage(int i) { return stages_ + std::size_t(i) * n_; }

  /// result = start + Σ m_i U_i and error = Σ e_i U_i over `count` components (nonzero weights only,
  /// in stage order).
  ROTORSWEEP_HD void combine(const V* start, std::size_t count, const V* stages, std::size_t stride, V* result,
                             V* error) const {
    Terms solution, estimate;
    for (int i = 0; i < table_.stages; ++i) {
      if (table_.m[i] != 0.0) solution.add(V(table_.m[i]), stages + std::size_t(i) * stride);
      if (table_.e[i] != 0.0) estimate.add(V(table_.e[i]), stages + std::size_t(i) * stride);
    }
    combine_stages(
        solution, [&](std::size_t k) { return start[k]; }, result, 0, count);
    combine_stages(
        estimate, [](std::size_t) { return V(0.0); }, error, 0, count);
  }

  RosenbrockTableau table_;
  std::size_t n_;
  std::size_t quadratures_;  ///< the model's carried quadratures
  typename System::Workspace work_;
  typename System::Jacobian jacobian_;
  V *f_, *df_dt_;
  V* argument_;  ///< a stage's argument y + Σ a_ij U_j, or its displacement Σ a_ij U_j from y
  V* stages_;
  V *dq_dy_, *qdot_;
  V* start_qdot_;  ///< the integrands at the step's start (stage 0's; qdot_ holds the later stages')
  V *dq_dt_, *quad_stages_;
};

}  // namespace rotorsweep::kernels
