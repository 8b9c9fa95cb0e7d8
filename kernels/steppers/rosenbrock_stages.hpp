// The stages of one Rosenbrock step (linearly implicit, transformed form, Hairer & Wanner Eq. IV.7.25),
// written once for every way a member's vectors are held: lanes (RosenbrockStepper), a team (TeamRosenbrock).
#pragma once

#include <cstddef>
#include <type_traits>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"
#include "kernels/steppers/stage_combination.hpp"

namespace rotorsweep::kernels {

/// One attempted step of size h of an ODE with quadrature states, y' = f(y, t), q' = p(y, t)
/// (docs/model.md §3). The quadratures are part of the ODE: their Jacobian rows ∂p/∂y enter the stages
/// exactly (the augmented Jacobian is block lower triangular, so its stage solve is the model's own solve
/// plus one dot product per quadrature), which keeps them at the method's full order.
///
/// The tableau is data (any RosenbrockTableau, chosen at run time): every stage forms its vectors in one
/// pass over the components with the tableau's nonzero terms in order (combine_stages), so a step gives
/// the bits of the same formulas written out term by term, and one instantiation serves every linearly
/// implicit stepper of the list.
///
/// Form says how the member's vectors are held and what its model is asked (LaneStageForm, TeamStageForm):
///   value_type, resolved_type  a component's type (a lane block or double) and the step's verdict
///   Context                    what each call gets (the model; a team and its model)
///   max_quadratures            the most quadratures the model carries
///   displaced                  whether stages evaluate at a displacement from the linearisation point
///   copies_table               whether the tableau is copied (else read where the caller keeps it)
///   rows(c, part)              part(begin, end) over the components, once per holder of a block of them
///   add_dot(c, sum, a, b)      sum + a·b over every component (the form's order of addition)
///   linearize, evaluate_stage  the model's f, integrands, J, ∂f/∂t, ∂p/∂y, ∂p/∂t; f at a stage
///   evaluate                   f and the integrands at (y, t) (only where a driver asks: evaluate())
///   factor(c, shift), solve(c, u), resolved(h)   the stage matrix shift·I − J and its verdict
template <class Form>
class RosenbrockStages {
 public:
  using V = typename Form::value_type;
  using Context = typename Form::Context;
  using Method = RosenbrockTableau;
  static constexpr int max_stages = RosenbrockTableau::max_stages;
  static constexpr std::size_t nq = Form::max_quadratures;  ///< storage; carried_ are stepped

  template <class... FormShape>
  ROTORSWEEP_HD RosenbrockStages(std::size_t n, std::size_t carried, const RosenbrockTableau& table,
                                 LaneArena<V>& arena, FormShape... shape)
      : table_(hold(table)),
        n_(n),
        carried_(carried),
        form_(n, arena, shape...),
        f_(arena.take(n)),
        df_dt_(arena.take(n)),
        argument_(arena.take(n)),
        stages_(arena.take(std::size_t(table.stages) * n)),
        dq_dy_(arena.take(carried * n + 1)) {}

  ROTORSWEEP_HD const char* name() const { return table().name; }
  ROTORSWEEP_HD int order() const { return table().order; }
  ROTORSWEEP_HD int embedded_order() const { return table().embedded_order; }
  /// Right-hand side evaluations per attempt: the linearisation and one per later stage.
  ROTORSWEEP_HD int evaluations() const { return table().stages; }
  ROTORSWEEP_HD std::size_t quadrature_count() const { return carried_; }

  /// One step of size h from (t, y, q) into y_new, q_new and the error estimates. Returns where the step
  /// resolves every unstable direction of J: where J has an eigenvalue λ > 1/(hγ), the stage solves damp a
  /// mode that grows like exp(λt) (an L-stable method turns a saddle into a false attractor, and the
  /// embedded estimate shares the error); there the member must retry with a smaller h.
  ROTORSWEEP_HD typename Form::resolved_type attempt(Context c, V t, V h, const V* y, const V* q, V* y_new,
                                                     V* q_new, V* y_error, V* q_error) {
    form_.linearize(c, y, t, f_, start_qdot_, df_dt_, dq_dy_, dq_dt_);
    const Step step{t, h, h * V(table().gamma), V(1.0) / h};
    form_.factor(c, V(1.0) / step.h_gamma);
    for (int i = 0; i < table().stages; ++i) run_stage(c, step, y, i);
    combine(c, y, q, y_new, q_new, y_error, q_error);
    return form_.resolved(h);
  }

  /// The quadratures' integrands at the start of the last attempt (from its linearisation).
  ROTORSWEEP_HD const V* start_integrands() const { return start_qdot_; }

  /// f at (y, t), with the quadratures' integrands into qdot (a first step's rate).
  ROTORSWEEP_HD void evaluate(Context c, const V* y, V t, V* qdot) { form_.evaluate(c, y, t, f_, qdot); }
  /// f of the last evaluation.
  ROTORSWEEP_HD const V* rate() const { return f_; }

 private:
  using Terms = StageTerms<V, max_stages>;
  using Table = std::conditional_t<Form::copies_table, RosenbrockTableau, const RosenbrockTableau*>;
  struct Step {
    V t, h, h_gamma, inv_h;
  };

  ROTORSWEEP_HD static Table hold(const RosenbrockTableau& table) {
    if constexpr (Form::copies_table)
      return table;
    else
      return &table;
  }
  ROTORSWEEP_HD const RosenbrockTableau& table() const {
    if constexpr (Form::copies_table)
      return table_;
    else
      return *table_;
  }

  /// Stage i: f at y + Σ a_ij U_j (a displaced form: at the displacement Σ a_ij U_j from y), its right-hand
  /// side, the solve for U_i, and the quadratures' stage values.
  ROTORSWEEP_HD void run_stage(Context c, const Step& s, const V* y, int i) {
    const RosenbrockTableau& tab = table();
    if (i > 0) {
      Terms arguments;
      for (int j = 0; j < i; ++j)
        if (tab.a[i][j] != 0.0) arguments.add(V(tab.a[i][j]), stage(j));
      form_.rows(c, [&](std::size_t begin, std::size_t end) {
        combine_stages(
            arguments, [&](std::size_t k) { return Form::displaced ? V(0.0) : y[k]; }, argument_, begin, end);
      });
      form_.evaluate_stage(c, y, argument_, s.t, V(tab.alpha[i]) * s.h, f_, qdot_);
    }
    const V time_weight = V(tab.gamma_sum[i]) * s.h;
    Terms earlier;  // c_ij / h U_j for every j < i (a zero weight adds a zero)
    for (int j = 0; j < i; ++j) earlier.add(V(tab.c[i][j]) * s.inv_h, stage(j));
    V* u = stage(i);
    form_.rows(c, [&](std::size_t begin, std::size_t end) {
      combine_stages(
          earlier, [&](std::size_t k) { return f_[k] + time_weight * df_dt_[k]; }, u, begin, end);
    });
    form_.solve(c, u);

    const V* integrands = i == 0 ? start_qdot_ : qdot_;
    for (std::size_t p = 0; p < carried_; ++p) {
      V sum = form_.add_dot(c, integrands[p] + time_weight * dq_dt_[p], dq_dy_ + p * n_, u);
      for (int j = 0; j < i; ++j) sum += earlier.weight[j] * quad_stage(j)[p];
      quad_stage(i)[p] = s.h_gamma * sum;
    }
  }

  ROTORSWEEP_HD V* stage(int i) const { return stages_ + std::size_t(i) * n_; }
  ROTORSWEEP_HD V* quad_stage(int i) { return quad_stages_ + std::size_t(i) * nq; }

  /// y_new = y + Σ m_i U_i and y_error = Σ e_i U_i (nonzero weights only, in stage order); the
  /// quadratures' alike.
  ROTORSWEEP_HD void combine(Context c, const V* y, const V* q, V* y_new, V* q_new, V* y_error, V* q_error) {
    Terms solution, estimate, quad_solution, quad_estimate;
    for (int i = 0; i < table().stages; ++i) {
      const double m = table().m[i], e = table().e[i];
      if (m != 0.0) solution.add(V(m), stage(i)), quad_solution.add(V(m), quad_stage(i));
      if (e != 0.0) estimate.add(V(e), stage(i)), quad_estimate.add(V(e), quad_stage(i));
    }
    form_.rows(c, [&](std::size_t begin, std::size_t end) {
      combine_stages(
          solution, [&](std::size_t k) { return y[k]; }, y_new, begin, end);
      combine_stages(
          estimate, [](std::size_t) { return V(0.0); }, y_error, begin, end);
    });
    combine_stages(
        quad_solution, [&](std::size_t p) { return q[p]; }, q_new, 0, carried_);
    combine_stages(
        quad_estimate, [](std::size_t) { return V(0.0); }, q_error, 0, carried_);
  }

  Table table_;
  std::size_t n_;
  std::size_t carried_;  ///< the model's carried quadratures
  Form form_;
  V *f_, *df_dt_;
  V* argument_;  ///< a stage's argument y + Σ a_ij U_j, or its displacement Σ a_ij U_j from y
  V* stages_;
  V* dq_dy_;  ///< ∂p_p/∂y_k at [p·n + k]
  // per member, whatever holds its vectors (on a team each rank keeps its own copy)
  V start_qdot_[nq + 1] = {}, qdot_[nq + 1] = {},
                     dq_dt_[nq + 1] = {};    ///< integrands at the start, a stage; ∂p/∂t
  V quad_stages_[max_stages * nq + 1] = {};  ///< the quadratures' stage values, nq per stage
};

}  // namespace rotorsweep::kernels
