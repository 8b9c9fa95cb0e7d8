// The nearest-neighbour row model (docs/model.md §1, paper Eq. EOMFULL; disorder §7) on a member's
// lanes with its rows in registers: f, J, ∂f/∂t and the quadratures' integrands and gradients (§3).
#pragma once

#include <cstddef>

#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/displaced_sincos.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_math.hpp"
#include "kernels/lanes/warp_row_slots.hpp"
#include "kernels/linear/warp_cyclic_tridiagonal.hpp"
#include "kernels/models/rows/integrals.hpp"
#include "kernels/models/rows/row_equations.hpp"
#include "kernels/models/rows/row_quadratures.hpp"

namespace rotorsweep::kernels {

/// NearestNeighbourRows' equations over the R register slots of each of a member's lanes
/// (WarpRowSlots): each lane computes its rows, the link after its last row from the next lane's
/// first row and the link before its first row from the previous lane (two shuffles and one), and
/// the sums over rows are warp sums (W::sum). PerRow: the rows carry disorder factors (1 + δ_j,
/// 1 + α_j, 1 + β_j), else every factor is 1 and never read. Carriable: the quadratures this
/// instantiation can carry (their gradients live in registers; a member carries any subset, chosen
/// at run time). Quadrature state is kept by kind (Quadrature order, as `all_integrals` lays it out),
/// every array index a compile-time constant. The formulas per row are NearestNeighbourRows' (the
/// same expressions); sums run in slot order, then across lanes, so the bits differ from the CPU
/// lanes' at rounding level (docs/numerics.md "The stage solve in registers").
template <class W, std::size_t R, bool PerRow, Integrals Carriable>
class WarpRows {
 public:
  using Warp = W;
  using V = typename W::value;
  using M = typename W::mask;
  using Slots = WarpRowSlots<W, R>;
  using Jacobian = WarpCyclicTridiagonal<W, R>;
  static constexpr std::size_t slots_per_lane = R;
  static constexpr bool per_row = PerRow;
  static constexpr std::size_t kinds = Integrals::max_count;
  static constexpr double period = two_pi;

  /// A member's parameters; the deviations are read at its rows (N values each, nullptr: none).
  struct Parameters {
    double A = 1.0, g = 1.0;
    bool strict_fm = false;
    const double* A_rows = nullptr;
    const double* anisotropy_rows = nullptr;
    const double* coupling_rows = nullptr;
  };

  ROTORSWEEP_HD WarpRows(const Slots& slots, Integrals carried, const Parameters& p)
      : slots_(slots), carried_(carried.completed()), A_(p.A), g_(p.g), inv_g_(1.0 / p.g), strict_fm_(p.strict_fm) {
    if constexpr (PerRow) {
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) {
        const M real = slots.real(r);
        const V j = lane_select(real, slots.row(r), V(0.0));
        A_row_[r] = factor(p.A_rows, j, real);
        anisotropy_row_[r] = factor(p.anisotropy_rows, j, real);
        coupling_row_[r] = factor(p.coupling_rows, j, real);
      }
    }
  }

  ROTORSWEEP_HD const Slots& slots() const { return slots_; }
  ROTORSWEEP_HD Integrals integrals() const { return carried_; }
  /// Whether the member carries quadrature `kind` (a compile-time false where Carriable does not).
  ROTORSWEEP_HD bool carries(std::size_t kind) const {
    return Carriable.carries(Quadrature(kind)) && carried_.carries(Quadrature(kind));
  }

  // What the error norm asks of a model (kernels/steppers/step_control.hpp), by kind.
  ROTORSWEEP_HD std::size_t dimension() const { return slots_.rows; }
  /// Every state component is an angle.
  ROTORSWEEP_HD static constexpr StateScale scale(std::size_t) { return StateScale::absolute; }
  ROTORSWEEP_HD static constexpr std::size_t quadrature_count() { return kinds; }
  ROTORSWEEP_HD bool error_controlled(std::size_t kind) const {
    return carries(kind) && row_error_controlled(all_integrals, kind);
  }
  ROTORSWEEP_HD static constexpr StateScale quadrature_scale(std::size_t kind) {
    return row_quadrature_scale(all_integrals, kind);
  }
  ROTORSWEEP_HD bool strict_fm() const { return strict_fm_; }

  /// Where a state kept by kind holds R(t) and ρ̄'s integral.
  static constexpr std::size_t drive_kind = std::size_t(Quadrature::drive);
  static constexpr std::size_t alignment_kind = std::size_t(Quadrature::alignment);
  /// The quadrature at index p of the carried set (Integrals::index) from a state kept by kind, every
  /// array index a compile-time constant (so that the state stays in registers).
  ROTORSWEEP_HD double carried_quadrature(const double (&quad)[kinds], std::size_t p) const {
    double value = 0.0;
    ROTORSWEEP_UNROLL
    for (std::size_t kind = 0; kind < kinds; ++kind) {
      const auto q = Quadrature(kind);
      if (carried_.carries(q) && carried_.index(q) == p) value = quad[kind];
    }
    return value;
  }
  ROTORSWEEP_HD double damping() const { return g_; }
  /// A bound on g·|∂f/∂θ| would be curvature_bound's; the register kernels run T = 0 only.

  /// f = dθ/dt and the integrands qdot[kind] at (θ, t).
  ROTORSWEEP_HD void evaluate(const V* theta, double t, V* f, double* qdot) const {
    Trigonometry trig;
    trig.at(theta, t);
    Rows rows;
    pass(trig, rows, f);
    integrands(trig, rows, f, t, qdot);
  }

  /// evaluate() at (θ + δ, t + τ), (θ, t) the point of the last linearize(): each sincos from the one
  /// there by angle addition (lane_sincos_displaced).
  ROTORSWEEP_HD void evaluate_displaced(const V* theta, const V* delta, double t, double tau, V* f,
                                        double* qdot) const {
    Trigonometry trig;
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < R; ++r)
      lane_sincos_displaced(theta[r], delta[r], start_.sin_row[r], start_.cos_row[r], trig.sin_row[r],
                            trig.cos_row[r]);
    lane_sincos_displaced(t, tau, start_.sin_t, start_.cos_t, trig.sin_t, trig.cos_t);
    Rows rows;
    pass(trig, rows, f);
    integrands(trig, rows, f, t + tau, qdot);
  }

  /// evaluate() plus J (into jacobian's diag and off), ∂f/∂t, the carried integrands' gradients
  /// grad[kind][slot] = ∂qdot_kind/∂θ and dq_dt[kind] = ∂qdot_kind/∂t; keeps the point for
  /// evaluate_displaced().
  ROTORSWEEP_HD void linearize(const V* theta, double t, V* f, double* qdot, Jacobian& J, V* df_dt,
                               V (&grad)[kinds][R], double* dq_dt) {
    start_.at(theta, t);
    Rows rows;
    pass(start_, rows, f);
    integrands(start_, rows, f, t, qdot);
    const V before_cos = W::from_previous(rows.coupled_cos[R - 1]);  // the link into the first row
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < R; ++r) {
      const M real = slots_.real(r);
      const V cos_2theta = start_.cos_row[r] * start_.cos_row[r] - start_.sin_row[r] * start_.sin_row[r];
      const V coupled_before = r == 0 ? before_cos : lane_select(slots_.first(r), before_cos, rows.coupled_cos[r - 1]);
      const V lag = scaled(A_row_, r, rows.cos_lag[r]);
      const V diag =
          row_stiffness(V(inv_g_), scaled(anisotropy_row_, r, cos_2theta), rows.coupled_cos[r], coupled_before,
                        V(A_) * lag);
      J.diag[r] = lane_select(real, diag, V(0.0));
      J.off[r] = lane_select(real, V(-inv_g_) * rows.coupled_cos[r], V(0.0));
      df_dt[r] = lane_select(real, V(-inv_g_) * V(A_) * lag, V(0.0));
    }
    J.keep_constant_solutions(strict_fm_);
    gradients(rows, f, J, df_dt, t, qdot, grad, dq_dt);
  }

 private:
  /// sin, cos of every slot's angle and of the drive's phase t.
  struct Trigonometry {
    V sin_row[R], cos_row[R];
    double sin_t = 0.0, cos_t = 0.0;
    ROTORSWEEP_HD void at(const V* theta, double t) {
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) lane_sincos(theta[r], sin_row[r], cos_row[r]);
      lane_sincos(t, sin_t, cos_t);
    }
  };

  /// A pass's per-slot values (0 at padding): the lags sin(θ_j − t) (weighted by the row's share of A
  /// where rows differ) and cos(θ_j − t), and the link after each row: its sine and cosine, and both
  /// weighted by the link's coupling.
  struct Rows {
    V sin_lag[R], lag[R], cos_lag[R];
    V sin_link[R], cos_link[R], coupled_sin[R], coupled_cos[R];
  };

  /// factor[j] · x where rows differ, else x.
  template <std::size_t N>
  ROTORSWEEP_HD static V scaled(const V (&factor)[N], std::size_t r, const V& x) {
    if constexpr (PerRow)
      return factor[r] * x;
    else
      return x;
  }

  /// 1 + deviation[j] at real slots (1 where there is none).
  ROTORSWEEP_HD static V factor(const double* deviations, const V& j, const M& real) {
    if (!deviations) return V(1.0);
    return lane_select(real, V(1.0) + W::load(deviations, j), V(1.0));
  }

  /// Every slot's lags, links and torque f_j from the trigonometry.
  ROTORSWEEP_HD void pass(const Trigonometry& trig, Rows& rows, V* f) const {
    const V sin_t(trig.sin_t), cos_t(trig.cos_t);
    const V next_sin = W::from_next(slots_.at_first(trig.sin_row));
    const V next_cos = W::from_next(slots_.at_first(trig.cos_row));
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < R; ++r) {
      const M real = slots_.real(r);
      const V s = trig.sin_row[r], c = trig.cos_row[r];
      const V right_sin = r + 1 < R ? trig.sin_row[r + 1 < R ? r + 1 : r] : next_sin;
      const V right_cos = r + 1 < R ? trig.cos_row[r + 1 < R ? r + 1 : r] : next_cos;
      const V sin_lag = s * cos_t - c * sin_t;
      rows.sin_lag[r] = lane_select(real, sin_lag, V(0.0));
      rows.lag[r] = lane_select(real, scaled(A_row_, r, sin_lag), V(0.0));
      rows.cos_lag[r] = lane_select(real, c * cos_t + s * sin_t, V(0.0));
      const V sin_link = s * right_cos - c * right_sin;
      const V cos_link = c * right_cos + s * right_sin;
      rows.sin_link[r] = lane_select(real, sin_link, V(0.0));
      rows.cos_link[r] = lane_select(real, cos_link, V(0.0));
      rows.coupled_sin[r] = lane_select(real, scaled(coupling_row_, r, sin_link), V(0.0));
      rows.coupled_cos[r] = lane_select(real, scaled(coupling_row_, r, cos_link), V(0.0));
    }
    const V before_sin = W::from_previous(rows.coupled_sin[R - 1]);
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < R; ++r) {
      const V s = trig.sin_row[r], c = trig.cos_row[r];
      const V link_before =
          r == 0 ? before_sin : lane_select(slots_.first(r), before_sin, rows.coupled_sin[r - 1]);
      const V sin_2theta = V(2.0) * s * c;
      const V torque = row_torque(V(inv_g_), scaled(anisotropy_row_, r, sin_2theta), rows.coupled_sin[r],
                                  link_before, V(A_) * rows.lag[r]);
      f[r] = lane_select(slots_.real(r), torque, V(0.0));
    }
  }

  /// Σ over the member's rows: each lane's slots in order (padding left out), then the lanes (W::sum).
  template <class Term>
  ROTORSWEEP_HD double row_sum(Term&& term) const {
    V sum(0.0);
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < R; ++r) sum = sum + lane_select(slots_.real(r), term(r), V(0.0));
    return W::sum(sum);
  }

  /// The integrands at time t by kind (row_quadratures.hpp's integrands_from_team_sums over all_integrals'
  /// layout; a kind not carried gets a value from zero sums, never read).
  ROTORSWEEP_HD void integrands(const Trigonometry& trig, const Rows& rows, const V* f, double t,
                                double* qdot) const {
    RowRangeSums<double> sums;
    IntegrandRangeSums<double> more;
    if (Carriable.drive && carried_.drive) sums.lag = row_sum([&](std::size_t r) { return rows.lag[r]; });
    if (Carriable.alignment && carried_.alignment)
      sums.cos_link = row_sum([&](std::size_t r) { return rows.cos_link[r]; });
    if (Carriable.work && carried_.work) more.lag_force = row_sum([&](std::size_t r) { return rows.lag[r] * f[r]; });
    if (Carriable.stokes && carried_.stokes)
      more.force_squares = row_sum([&](std::size_t r) { return f[r] * f[r]; });
    if (Carriable.energy && carried_.energy)
      more.energy = row_sum([&](std::size_t r) { return energy_term(trig, rows, r); });
    integrands_from_team_sums(
        all_integrals, A_, g_, sums, more,
        [&](double cos_link) { return 0.5 + (0.5 / double(slots_.rows)) * cos_link; }, t, qdot);
  }

  /// Row r's energy term −(3/2) a_j cos 2θ_j + b_j cos(θ_j − θ_{j+1}) + A_j cos(θ_j − t) (docs/model.md §1).
  ROTORSWEEP_HD V energy_term(const Trigonometry& trig, const Rows& rows, std::size_t r) const {
    const V s = trig.sin_row[r], c = trig.cos_row[r];
    const V cos_2theta = c * c - s * s;
    return V(-1.5) * scaled(anisotropy_row_, r, cos_2theta) + rows.coupled_cos[r] +
           V(A_) * scaled(A_row_, r, rows.cos_lag[r]);
  }

  /// (J x)_k at every slot: J's rows through diag and off, x's neighbours across lanes.
  ROTORSWEEP_HD void product(const Jacobian& J, const V* x, V* out) const {
    const V next = W::from_next(slots_.at_first(x));
    const V before = W::from_previous(J.off[R - 1] * x[R - 1]);  // the previous lane's last link times its row
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < R; ++r) {
      const V right = r + 1 < R ? x[r + 1 < R ? r + 1 : r] : next;
      const V left = r == 0 ? before : lane_select(slots_.first(r), before, J.off[r - 1] * x[r - 1]);
      out[r] = lane_select(slots_.real(r), J.diag[r] * x[r] + J.off[r] * right + left, V(0.0));
    }
  }

  /// The carried integrands' gradients and time derivatives (row_integrand_gradient_range's formulas:
  /// R, W, S, ρ̄, H, then the moments), each time sum a warp sum.
  ROTORSWEEP_HD void gradients(const Rows& rows, const V* f, const Jacobian& J, const V* df_dt, double t,
                               const double* qdot, V (&grad)[kinds][R], double* dq_dt) const {
    const auto slot = [](Quadrature q) { return std::size_t(q); };
    const V A(A_), g(g_);
    if (Carriable.drive && carried_.drive) {
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) grad[slot(Quadrature::drive)][r] = A * scaled(A_row_, r, rows.cos_lag[r]);
      dq_dt[slot(Quadrature::drive)] =
          -A_ * row_sum([&](std::size_t r) { return scaled(A_row_, r, rows.cos_lag[r]); });
    }
    if (Carriable.work && carried_.work) {
      V lag_product[R];
      product(J, rows.lag, lag_product);  // J symmetric: Jᵀ lag
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r)
        grad[slot(Quadrature::work)][r] = A * (scaled(A_row_, r, rows.cos_lag[r]) * f[r] + lag_product[r]);
      dq_dt[slot(Quadrature::work)] = A_ * row_sum([&](std::size_t r) {
        return rows.lag[r] * df_dt[r] - scaled(A_row_, r, rows.cos_lag[r]) * f[r];
      });
    }
    if (Carriable.stokes && carried_.stokes) {
      V force_product[R];
      product(J, f, force_product);
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) grad[slot(Quadrature::stokes)][r] = V(2.0) * g * force_product[r];
      dq_dt[slot(Quadrature::stokes)] = 2.0 * g_ * row_sum([&](std::size_t r) { return f[r] * df_dt[r]; });
    }
    if (Carriable.alignment && carried_.alignment) {
      const V scale(0.5 / double(slots_.rows));
      const V before = W::from_previous(rows.sin_link[R - 1]);
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) {
        const V left = r == 0 ? before : lane_select(slots_.first(r), before, rows.sin_link[r - 1]);
        grad[slot(Quadrature::alignment)][r] = lane_select(slots_.real(r), scale * (left - rows.sin_link[r]), V(0.0));
      }
      dq_dt[slot(Quadrature::alignment)] = 0.0;
    }
    if (Carriable.energy && carried_.energy) {
      ROTORSWEEP_UNROLL
      for (std::size_t r = 0; r < R; ++r) grad[slot(Quadrature::energy)][r] = lane_neg(g) * f[r];
      dq_dt[slot(Quadrature::energy)] = A_ * row_sum([&](std::size_t r) { return rows.lag[r]; });
    }
    if (Carriable.moments && carried_.moments) {
      const Quadrature bases[3] = {Quadrature::drive, Quadrature::work, Quadrature::stokes};
      ROTORSWEEP_UNROLL
      for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t base = slot(bases[i]), moment = slot(Quadrature::drive_moment) + i;
        ROTORSWEEP_UNROLL
        for (std::size_t r = 0; r < R; ++r) grad[moment][r] = V(t) * grad[base][r];
        dq_dt[moment] = qdot[base] + t * dq_dt[base];
      }
    }
  }

  Slots slots_;
  Integrals carried_;
  double A_, g_, inv_g_;
  bool strict_fm_;
  V A_row_[PerRow ? R : 1], anisotropy_row_[PerRow ? R : 1], coupling_row_[PerRow ? R : 1];
  Trigonometry start_;  ///< the last linearize()'s point
};

}  // namespace rotorsweep::kernels
