// The nearest-neighbour periodic row model (docs/model.md §1, paper Eq. EOMFULL) with optional
// per-row disorder (§7): right-hand side, cyclic tridiagonal Jacobian, ∂f/∂t, energy, integrands (§3).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/displaced_sincos.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/lane_math.hpp"
#include "kernels/linear/cyclic_tridiagonal.hpp"
#include "kernels/models/rows/integrals.hpp"
#include "kernels/models/rows/row_equations.hpp"
#include "kernels/models/rows/row_quadratures.hpp"
#include "kernels/steppers/model_concept.hpp"

namespace rotorsweep::kernels {

/// g dθ_j/dt = -3 a_j sin 2θ_j + b_j sin(θ_j - θ_{j+1}) + b_{j-1} sin(θ_j - θ_{j-1}) + A_j sin(θ_j - t),
/// rows periodic (θ_N ≡ θ_0), N >= 2, with A_j = A (1 + δ_j), a_j = 1 + α_j, b_j = 1 + β_j
/// (b_j couples rows j and j+1). A, g and the deviations are per lane; all deviations zero is the
/// uniform model with the same bits (a factor 1 multiplies exactly). Every evaluation takes one
/// sincos per row and one for the drive phase; all other trigonometry follows from sums
/// and products of those. A Rosenbrock stage, close to the step's start, gets its sincos from
/// those of the start by angle addition (evaluate_displaced).
///
/// It carries the quadratures of the Integrals given at construction (a scene's observables,
/// chosen at run time). Scratch lives in a Workspace, the per-row factors in storage_size(N) lane
/// values of caller-owned storage. It satisfies LaneModel (kernels/steppers/model_concept.hpp).
template <class V>
class NearestNeighbourRows : public CarriedRowQuadratures {
 public:
  using lane_type = V;
  using Jacobian = CyclicTridiagonal<V>;
  static constexpr double period = two_pi;  ///< the drive period

  /// One lane's parameters. `strict_fm` marks a member that starts exactly in the strict-FM set
  /// (all rows equal): its stage solves keep all-equal rows exactly equal (CyclicTridiagonal),
  /// so that the symmetry-protected state stays strict FM in floating point.
  /// The per-row relative deviations δ_j, α_j, β_j are read from N values each; nullptr is zero.
  struct Parameters {
    double A = 1.0;
    double g = 1.0;
    bool strict_fm = false;
    const double* A_rows = nullptr;           ///< δ_j: A_j = A (1 + δ_j)
    const double* anisotropy_rows = nullptr;  ///< α_j: anisotropy 3/2 (1 + α_j)
    const double* coupling_rows = nullptr;    ///< β_j: coupling of rows j, j+1 is 1 + β_j
  };

  /// Lane values of caller storage the model keeps (its per-row factors).
  static constexpr std::size_t storage_size(std::size_t n) { return 3 * n; }

  struct Workspace {
    static constexpr std::size_t storage_size(std::size_t n) { return 10 * n; }
    ROTORSWEEP_HD Workspace(std::size_t n, LaneArena<V>& arena)
        : sin_row(arena.take(n)),
          cos_row(arena.take(n)),
          sin_lag(arena.take(n)),
          cos_lag(arena.take(n)),
          sin_link(arena.take(n)),
          cos_link(arena.take(n)),
          product(arena.take(n)),
          weighted_lag(arena.take(n)),
          start_sin_row(arena.take(n)),
          start_cos_row(arena.take(n)) {}
    V *sin_row, *cos_row;                          // sin θ_j, cos θ_j
    V *sin_lag, *cos_lag;                          // sin(θ_j - t), cos(θ_j - t)
    V *sin_link, *cos_link;                        // sin(θ_j - θ_{j+1}), cos(θ_j - θ_{j+1})
    V* product;                                    // J·v products for the integrand gradients
    V* weighted_lag;                               // (1 + δ_j) sin(θ_j - t)
    V *start_sin_row, *start_cos_row;              // sin θ_j, cos θ_j at the last linearize()
    V sin_t = V(0.0), cos_t = V(0.0);              // sin t, cos t
    V start_sin_t = V(0.0), start_cos_t = V(0.0);  // at the last linearize()
  };

  /// A uniform model (every factor 1) carrying `carried` over storage_size(rows) values of `arena`.
  ROTORSWEEP_HD NearestNeighbourRows(std::size_t rows, LaneArena<V>& arena, Integrals carried)
      : CarriedRowQuadratures(carried),
        rows_(rows),
        reads_rows_(integrals_.work || integrals_.energy),
        A_row_(arena.take(rows)),
        anisotropy_row_(arena.take(rows)),
        coupling_row_(arena.take(rows)) {
    if (arena.counting()) return;
    for (std::size_t j = 0; j < rows; ++j) A_row_[j] = anisotropy_row_[j] = coupling_row_[j] = V(1.0);
  }
  ROTORSWEEP_HD NearestNeighbourRows(std::size_t rows, LaneArena<V>& arena, Integrals carried,
                                     const Parameters& p)
      : NearestNeighbourRows(rows, arena, carried) {
    for (std::size_t l = 0; l < lane_width<V>; ++l) set_lane(l, p);
  }
  /// A and g per lane, uniform rows, no lane symmetry protected.
  ROTORSWEEP_HD NearestNeighbourRows(std::size_t rows, LaneArena<V>& arena, Integrals carried, V A, V g)
      : NearestNeighbourRows(rows, arena, carried) {
    A_ = A;
    g_ = g;
    inv_g_ = V(1.0) / g;
  }

  /// Gives one lane new parameters (a lane block refilled with another member).
  ROTORSWEEP_HD void set_lane(std::size_t lane, const Parameters& p) {
    lane_set(A_, lane, p.A);
    lane_set(g_, lane, p.g);
    lane_set(inv_g_, lane, 1.0 / p.g);
    lane_set(strict_fm_, lane, p.strict_fm ? 1.0 : 0.0);
    for (std::size_t j = 0; j < rows_; ++j) {
      const double factors[3] = {p.A_rows ? 1.0 + p.A_rows[j] : 1.0,
                                 p.anisotropy_rows ? 1.0 + p.anisotropy_rows[j] : 1.0,
                                 p.coupling_rows ? 1.0 + p.coupling_rows[j] : 1.0};
      lane_set(A_row_[j], lane, factors[0]);
      lane_set(anisotropy_row_[j], lane, factors[1]);
      lane_set(coupling_row_[j], lane, factors[2]);
      disordered_ = disordered_ || factors[0] != 1.0 || factors[1] != 1.0 || factors[2] != 1.0;
    }
  }

  /// A bound on the spectral radius of g ∂f/∂θ in `lane` (Gershgorin, over every θ and t):
  /// max_j 6 (1 + α_j) + 2 (1 + β_j) + 2 (1 + β_{j−1}) + A (1 + δ_j), 10 + A without disorder.
  ROTORSWEEP_HD double curvature_bound(std::size_t lane) const {
    double bound = 0.0;
    for (std::size_t j = 0; j < rows_; ++j) {
      const std::size_t jm = (j == 0) ? rows_ - 1 : j - 1;
      const double row = 6.0 * std::fabs(lane_get(anisotropy_row_[j], lane)) +
                         2.0 * std::fabs(lane_get(coupling_row_[j], lane)) +
                         2.0 * std::fabs(lane_get(coupling_row_[jm], lane)) +
                         std::fabs(lane_get(A_, lane) * lane_get(A_row_[j], lane));
      bound = row > bound ? row : bound;
    }
    return bound;
  }

  ROTORSWEEP_HD std::size_t dimension() const { return rows_; }
  /// Every state component is an angle: its error is measured absolutely.
  ROTORSWEEP_HD static constexpr StateScale scale(std::size_t) { return StateScale::absolute; }

  /// f = dθ/dt and the quadrature integrands qdot at (θ, t).
  ROTORSWEEP_HD void evaluate(Workspace& w, const V* theta, V t, V* f, V* qdot) const {
    if (disordered_)
      evaluate_rows<true>(w, theta, t, f, qdot, reads_rows_);
    else
      evaluate_rows<false>(w, theta, t, f, qdot, reads_rows_);
  }

  /// evaluate() at (θ + δ, t + τ), where (θ, t) is the point of the last linearize() on `w`: each
  /// sincos comes from the one at (θ, t) by angle addition (kernels/lanes/displaced_sincos.hpp).
  ROTORSWEEP_HD void evaluate_displaced(Workspace& w, const V* theta, const V* delta, V t, V tau, V* f,
                                        V* qdot) const {
    if (disordered_)
      evaluate_displaced_rows<true>(w, theta, delta, t, tau, f, qdot);
    else
      evaluate_displaced_rows<false>(w, theta, delta, t, tau, f, qdot);
  }

  /// evaluate() plus the Jacobian J = ∂f/∂θ, ∂f/∂t, and the gradients of the integrands
  /// (dq_dtheta[q·N + k] = ∂qdot_q/∂θ_k, dq_dt[q] = ∂qdot_q/∂t) at the same point.
  ROTORSWEEP_HD void linearize(Workspace& w, const V* theta, V t, V* f, V* qdot, Jacobian& J, V* df_dt,
                               V* dq_dtheta, V* dq_dt) const {
    if (disordered_)
      linearize_rows<true>(w, theta, t, f, qdot, J, df_dt, dq_dtheta, dq_dt);
    else
      linearize_rows<false>(w, theta, t, f, qdot, J, df_dt, dq_dtheta, dq_dt);
  }

  /// H(θ; A, t) of docs/model.md §1.
  ROTORSWEEP_HD V energy(Workspace& w, const V* theta, V t) const {
    if (disordered_) {
      trigonometry<true>(w, theta, t);
      return energy_from_trigonometry<true>(w);
    }
    trigonometry<false>(w, theta, t);
    return energy_from_trigonometry<false>(w);
  }

  /// The N links of the ring.
  ROTORSWEEP_HD std::size_t links() const { return rows_; }

  using RowSums = RowRangeSums<V>;
  using IntegrandSums = IntegrandRangeSums<V>;

  // A team's evaluation (docs/architecture.md "Teams"): each rank passes over its rows [begin, end),
  // the team adds the ranks' sums, and the integrands and the Jacobian follow.

  /// f_j for rows [begin, end) at (θ, t), their trigonometry into the workspace (rows begin − 1 and
  /// end are read, not written), and their sums of lags and of the cosines of links begin … end − 1.
  /// One rank over every row gives evaluate()'s f and sums, bit for bit.
  ROTORSWEEP_HD RowSums evaluate_range(Workspace& w, const V* theta, V t, V* f, std::size_t begin,
                                       std::size_t end) const {
    return disordered_ ? range_pass<true>(w, theta, t, f, begin, end)
                       : range_pass<false>(w, theta, t, f, begin, end);
  }
  /// The further sums over rows [begin, end) that W, S and H need (those the model carries), after
  /// the rank's evaluate_range.
  ROTORSWEEP_HD IntegrandSums integrand_sums_range(const Workspace& w, const V* f, std::size_t begin,
                                                   std::size_t end) const {
    IntegrandSums sums;
    if (integrals_.work)
      sums.lag_force =
          row_products(begin, end, disordered_ ? weighted_lag<true>(w) : weighted_lag<false>(w), f);
    if (integrals_.stokes) sums.force_squares = row_products(begin, end, f, f);
    if (integrals_.energy)
      sums.energy = disordered_ ? energy_range<true>(w, begin, end) : energy_range<false>(w, begin, end);
    return sums;
  }
  /// The carried integrands at time t from the team's sums.
  ROTORSWEEP_HD void team_integrands(const RowSums& sums, const IntegrandSums& more, V t, V* qdot) const {
    integrands_from_team_sums(
        integrals_, A_, g_, sums, more, [&](const V& cos_link) { return alignment_from_link_sum(cos_link); },
        t, qdot);
  }
  /// J's diagonal, the links after rows [begin, end) and ∂f/∂t there, once every rank's
  /// evaluate_range at the point is done (row begin reads link begin − 1).
  ROTORSWEEP_HD void jacobian_range(const Workspace& w, V* diag, V* off, V* df_dt, std::size_t begin,
                                    std::size_t end) const {
    for (std::size_t j = begin; j < end; ++j) {
      const JacobianRow row = disordered_ ? jacobian_row<true>(w, j) : jacobian_row<false>(w, j);
      diag[j] = row.diag;
      off[j] = row.off;
      df_dt[j] = row.df_dt;
    }
  }
  /// The carried integrands' gradients dq_dtheta[q·N + k] for rows k in [begin, end) at time t, and
  /// their parts of the sums behind ∂q̇/∂t in time_sums (team_time_derivatives), once every rank's
  /// jacobian_range at the point is done (J's rows through diag and off; `scratch` holds N values).
  ROTORSWEEP_HD void integrand_gradient_range(const Workspace& w, const V* f, const V* diag, const V* off,
                                              const V* df_dt, V* scratch, V* dq_dtheta, V* time_sums, V t,
                                              std::size_t begin, std::size_t end) const {
    if (disordered_)
      gradient_range<true>(w, f, diag, off, df_dt, scratch, dq_dtheta, time_sums, begin, end);
    else
      gradient_range<false>(w, f, diag, off, df_dt, scratch, dq_dtheta, time_sums, begin, end);
    row_moment_gradient_range(integrals_, rows_, t, dq_dtheta, begin, end);
  }
  /// ∂q̇/∂t at time t from the team's time sums and the integrands there.
  ROTORSWEEP_HD void team_time_derivatives(const V* time_sums, V t, const V* qdot, V* dq_dt) const {
    time_derivatives_from_team_sums(integrals_, A_, g_, time_sums, t, qdot, dq_dt);
  }
  /// Whether lane `lane`'s member is symmetry protected (its stage solves keep all-equal rows equal).
  ROTORSWEEP_HD bool strict_fm(std::size_t lane) const { return lane_get(strict_fm_, lane) != 0.0; }

  /// The row profile at (θ, t): drive[j] = A (1 + δ_j) sin(θ_j - t), row j's share of the drive
  /// integrand R, and link[j] = cos²((θ_j - θ_{j+1})/2), whose mean over the links is ρ̄.
  ROTORSWEEP_HD void row_profile(Workspace& w, const V* theta, V t, V* drive, V* link) const {
    trigonometry<false>(w, theta, t);
    for (std::size_t j = 0; j < rows_; ++j) {
      drive[j] = A_ * (A_row_[j] * w.sin_lag[j]);
      link[j] = V(0.5) + V(0.5) * w.cos_link[j];
    }
  }
  /// row_profile over rows [begin, end) (a team rank's), their f into `f` as evaluate_range's: the
  /// same values per row, bit for bit.
  ROTORSWEEP_HD void row_profile_range(Workspace& w, const V* theta, V t, V* f, V* drive, V* link,
                                       std::size_t begin, std::size_t end) const {
    evaluate_range(w, theta, t, f, begin, end);
    for (std::size_t j = begin; j < end; ++j) {
      drive[j] = A_ * (A_row_[j] * w.sin_lag[j]);
      link[j] = V(0.5) + V(0.5) * w.cos_link[j];
    }
  }

 private:
  // Every loop below is written once for both cases: per_row = false is the uniform model (the
  // factors are not read), per_row = true multiplies each term by its row's factor.

  /// factor[j] · x with per-row factors, else x.
  template <bool per_row>
  ROTORSWEEP_HD static V scaled(const V* factor, std::size_t j, const V& x) {
    if constexpr (per_row)
      return factor[j] * x;
    else
      return x;
  }

  /// (1 + δ_j) sin(θ_j - t) after trigonometry<per_row>().
  template <bool per_row>
  ROTORSWEEP_HD static const V* weighted_lag(const Workspace& w) {
    if constexpr (per_row)
      return w.weighted_lag;
    else
      return w.sin_lag;
  }

  /// The pass over the rows (rows_pass) for what is needed, then the integrands: with `store`
  /// (the Jacobian, or W and H, read every row's trigonometry from the workspace) everything is
  /// stored; else the links' cosines are summed only for ρ̄. One branch per evaluation picks the
  /// pass compiled for that case, so the per-row loop carries no test.
  template <bool per_row, class RowSincos>
  ROTORSWEEP_HD void pass_and_integrands(Workspace& w, RowSincos&& row_sincos, V* f, V* qdot,
                                         bool store) const {
    RowSums sums;
    if (store)
      sums = rows_pass<per_row, true, true>(w, row_sincos, f);
    else if (integrals_.alignment)
      sums = rows_pass<per_row, false, true>(w, row_sincos, f);
    else
      sums = rows_pass<per_row, false, false>(w, row_sincos, f);
    integrands<per_row>(w, sums, f, qdot);
  }

  /// A row's sine and cosine for rows_pass: at θ_j, or at θ_j + δ_j from the linearisation point's.
  /// Functions that are always inlined into the pass (a call per row would spill its lane registers).
  struct RowSincosAt {
    const V* theta;
    ROTORSWEEP_HD ROTORSWEEP_INLINE void operator()(std::size_t j, V& s, V& c) const {
      lane_sincos(theta[j], s, c);
    }
  };
  struct RowSincosDisplaced {
    const V *theta, *delta, *start_sin, *start_cos;
    ROTORSWEEP_HD ROTORSWEEP_INLINE void operator()(std::size_t j, V& s, V& c) const {
      lane_sincos_displaced(theta[j], delta[j], start_sin[j], start_cos[j], s, c);
    }
  };

  template <bool per_row>
  ROTORSWEEP_HD void evaluate_rows(Workspace& w, const V* theta, V t, V* f, V* qdot, bool store) const {
    lane_sincos(t, w.sin_t, w.cos_t);
    pass_and_integrands<per_row>(w, RowSincosAt{theta}, f, qdot, store);
    row_moment_integrands(integrals_, t, qdot);
  }

  template <bool per_row>
  ROTORSWEEP_HD void evaluate_displaced_rows(Workspace& w, const V* theta, const V* delta, V t, V tau, V* f,
                                             V* qdot) const {
    lane_sincos_displaced(t, tau, w.start_sin_t, w.start_cos_t, w.sin_t, w.cos_t);
    pass_and_integrands<per_row>(w, RowSincosDisplaced{theta, delta, w.start_sin_row, w.start_cos_row}, f,
                                 qdot, reads_rows_);
    row_moment_integrands(integrals_, t + tau, qdot);
  }

  template <bool per_row>
  ROTORSWEEP_HD void linearize_rows(Workspace& w, const V* theta, V t, V* f, V* qdot, Jacobian& J, V* df_dt,
                                    V* dq_dtheta, V* dq_dt) const {
    evaluate_rows<per_row>(w, theta, t, f, qdot, true);
    const std::size_t n = rows_;
    for (std::size_t j = 0; j < n; ++j) {
      const JacobianRow row = jacobian_row<per_row>(w, j);
      J.diag(j) = row.diag;
      J.off(j) = row.off;
      df_dt[j] = row.df_dt;
    }
    J.keep_constant_solutions(strict_fm_ != V(0.0));
    integrand_gradients<per_row>(w, f, J, df_dt, dq_dtheta, dq_dt);
    row_moment_gradients(integrals_, n, t, qdot, dq_dtheta, dq_dt);
    for (std::size_t j = 0; j < n; ++j) {  // the start of evaluate_displaced()
      w.start_sin_row[j] = w.sin_row[j];
      w.start_cos_row[j] = w.cos_row[j];
    }
    w.start_sin_t = w.sin_t;
    w.start_cos_t = w.cos_t;
  }

  /// Row j's diagonal entry of J, the entry of link j, and ∂f_j/∂t, from the stored trigonometry.
  struct JacobianRow {
    V diag, off, df_dt;
  };
  template <bool per_row>
  ROTORSWEEP_HD JacobianRow jacobian_row(const Workspace& w, std::size_t j) const {
    const std::size_t jm = (j == 0) ? rows_ - 1 : j - 1;
    const V cos_2theta = w.cos_row[j] * w.cos_row[j] - w.sin_row[j] * w.sin_row[j];
    const V coupled = scaled<per_row>(coupling_row_, j, w.cos_link[j]);
    const V lag = scaled<per_row>(A_row_, j, w.cos_lag[j]);
    return {row_stiffness(inv_g_, scaled<per_row>(anisotropy_row_, j, cos_2theta), coupled,
                          scaled<per_row>(coupling_row_, jm, w.cos_link[jm]), A_ * lag),
            lane_neg(inv_g_) * coupled, lane_neg(inv_g_) * A_ * lag};
  }

  /// integrand_gradient_range over one rank's rows, J x from J's rows and x's neighbours.
  template <bool per_row>
  ROTORSWEEP_HD void gradient_range(const Workspace& w, const V* f, const V* diag, const V* off,
                                    const V* df_dt, V* scratch, V* dq_dtheta, V* time_sums, std::size_t begin,
                                    std::size_t end) const {
    const std::size_t n = rows_;
    row_integrand_gradient_range(
        integrals_, n, A_, g_, weighted_lag<per_row>(w),
        [&](std::size_t k) { return scaled<per_row>(A_row_, k, w.cos_lag[k]); }, f,
        [&](const V* x, V* out) {
          for (std::size_t k = begin; k < end; ++k) {
            const std::size_t km = (k == 0) ? n - 1 : k - 1, k1 = (k + 1 == n) ? 0 : k + 1;
            out[k] = diag[k] * x[k] + off[k] * x[k1] + off[km] * x[km];
          }
        },
        df_dt, scratch,
        [&](V* grad, std::size_t first, std::size_t last) { alignment_gradient_range(w, grad, first, last); },
        dq_dtheta, time_sums, begin, end);
  }

  /// ∂ρ̄/∂θ_k = (1/2N) (sin(θ_{k−1} − θ_k) − sin(θ_k − θ_{k+1})) for rows [first, last).
  ROTORSWEEP_HD void alignment_gradient_range(const Workspace& w, V* grad, std::size_t first,
                                              std::size_t last) const {
    const V scale(0.5 / double(rows_));
    for (std::size_t k = first; k < last; ++k) {
      const std::size_t km = (k == 0) ? rows_ - 1 : k - 1;
      grad[k] = scale * (w.sin_link[km] - w.sin_link[k]);
    }
  }

  /// evaluate_range's pass: rows [begin, end) in row order, their neighbours read but not stored.
  template <bool per_row>
  ROTORSWEEP_HD RowSums range_pass(Workspace& w, const V* theta, V t, V* f, std::size_t begin,
                                   std::size_t end) const {
    const std::size_t n = rows_;
    V sin_t(0.0), cos_t(0.0);
    lane_sincos(t, sin_t, cos_t);
    const auto row = [&]<bool store>(std::size_t j) {
      V s(0.0), c(0.0);
      lane_sincos(theta[j], s, c);
      return row_values<per_row, store>(w, j, s, c, sin_t, cos_t);
    };
    const std::size_t before = (begin + n - 1) % n;
    const Row previous = row.template operator()<false>(before);
    Row current = row.template operator()<true>(begin);
    V link_before = link_values<per_row, false, false>(w, before, previous, current).sin;
    RowSums sums;
    for (std::size_t j = begin; j < end; ++j) {
      sums.lag += current.lag;
      const std::size_t j1 = (j + 1) % n;
      const Row next = j + 1 < end ? row.template operator()<true>(j1) : row.template operator()<false>(j1);
      const Link after = link_values<per_row, true, true>(w, j, current, next);
      sums.cos_link += after.cos;
      f[j] = torque<per_row>(j, current, after.sin, link_before, inv_g_, A_);
      link_before = after.sin;
      current = next;
    }
    return sums;
  }

  /// The whole trigonometry in the workspace, for the energy and the row profile; the torques
  /// go to the scratch w.product.
  template <bool per_row>
  ROTORSWEEP_HD void trigonometry(Workspace& w, const V* theta, V t) const {
    lane_sincos(t, w.sin_t, w.cos_t);
    rows_pass<per_row, true, true>(
        w, [&](std::size_t j, V& s, V& c) { lane_sincos(theta[j], s, c); }, w.product);
  }

  /// A row's sincos and its lag sin(θ_j − t), weighted by the row's share of A.
  struct Row {
    V sin, cos, lag;
  };
  /// A link's sine, weighted by the coupling, and its cosine where computed.
  struct Link {
    V sin, cos;
  };

  /// Row j from its sincos (s, c) and the drive's (sin_t, cos_t); with `store`, its trigonometry goes to
  /// the workspace.
  template <bool per_row, bool store>
  ROTORSWEEP_HD Row row_values(Workspace& w, std::size_t j, V s, V c, V sin_t, V cos_t) const {
    Row r{s, c, V(0.0)};
    const V sin_lag = r.sin * cos_t - r.cos * sin_t;
    r.lag = scaled<per_row>(A_row_, j, sin_lag);
    if constexpr (store) {
      w.sin_row[j] = r.sin;
      w.cos_row[j] = r.cos;
      w.sin_lag[j] = sin_lag;
      w.cos_lag[j] = r.cos * cos_t + r.sin * sin_t;
      if constexpr (per_row) w.weighted_lag[j] = r.lag;
    }
    return r;
  }

  /// Link j between rows j and j + 1 (a and b); with `cosines` its cosine, with `store` both to the
  /// workspace.
  template <bool per_row, bool store, bool cosines>
  ROTORSWEEP_HD Link link_values(Workspace& w, std::size_t j, const Row& a, const Row& b) const {
    Link l{a.sin * b.cos - a.cos * b.sin, V(0.0)};
    if constexpr (cosines) l.cos = a.cos * b.cos + a.sin * b.sin;
    if constexpr (store) {
      w.sin_link[j] = l.sin;
      w.cos_link[j] = l.cos;
    }
    l.sin = scaled<per_row>(coupling_row_, j, l.sin);
    return l;
  }

  /// The torque f_j of row r between its (weighted) link sines after and before it.
  template <bool per_row>
  ROTORSWEEP_HD V torque(std::size_t j, const Row& r, const V& link_after, const V& link_before,
                         const V& inv_g, const V& A) const {
    const V sin_2theta = V(2.0) * r.sin * r.cos;
    return row_torque(inv_g, scaled<per_row>(anisotropy_row_, j, sin_2theta), link_after, link_before,
                      A * r.lag);
  }

  /// One pass over the rows from w.sin_t, w.cos_t and each row's sincos, which row_sincos(j, s, c)
  /// returns in s, c: each row's lag, its link to the row before, and the torque f_j as soon as
  /// both links of row j are known, every value used while in registers. Row N-1 comes first, so
  /// that the torques come out in row order and the stage solve, which reads them in that order,
  /// can start before the pass ends; the sums are taken in row order all the same. With `store`,
  /// the sines, cosines, lags and links go to the workspace (the Jacobian, the energy and the
  /// integrands W, H read them); with `cosines`, the links' cosines are computed (and summed).
  template <bool per_row, bool store, bool cosines, class RowSincos>
  ROTORSWEEP_HD RowSums rows_pass(Workspace& w, RowSincos&& row_sincos, V* f) const {
    const std::size_t n = rows_;
    const V sin_t = w.sin_t, cos_t = w.cos_t;
    const V inv_g = inv_g_, A = A_;  // f could alias the members: keep them in registers
    const auto row = [&](std::size_t j) {
      V s(0.0), c(0.0);
      row_sincos(j, s, c);
      return row_values<per_row, store>(w, j, s, c, sin_t, cos_t);
    };

    RowSums sums;
    const Row last = row(n - 1), first = row(0);
    const Link closing = link_values<per_row, store, cosines>(w, n - 1, last, first);
    sums.lag += first.lag;
    Row previous = first;
    V link_before = closing.sin;
    const auto next = [&](std::size_t j, const Row& current) {  // row j, after row j - 1
      sums.lag += current.lag;
      const Link after = link_values<per_row, store, cosines>(w, j - 1, previous, current);
      if constexpr (cosines) sums.cos_link += after.cos;
      f[j - 1] = torque<per_row>(j - 1, previous, after.sin, link_before, inv_g, A);
      link_before = after.sin;
      previous = current;
    };
    for (std::size_t j = 1; j + 1 < n; ++j) next(j, row(j));
    next(n - 1, last);
    if constexpr (cosines) sums.cos_link += closing.cos;
    f[n - 1] = torque<per_row>(n - 1, last, closing.sin, link_before, inv_g, A);
    return sums;
  }

  template <bool per_row>
  ROTORSWEEP_HD V energy_from_trigonometry(const Workspace& w) const {
    return energy_range<per_row>(w, 0, rows_);
  }

  /// The energy terms of rows [begin, end), summed in row order.
  template <bool per_row>
  ROTORSWEEP_HD V energy_range(const Workspace& w, std::size_t begin, std::size_t end) const {
    V h(0.0);
    for (std::size_t j = begin; j < end; ++j) {
      const V cos_2theta = w.cos_row[j] * w.cos_row[j] - w.sin_row[j] * w.sin_row[j];
      h += V(-1.5) * scaled<per_row>(anisotropy_row_, j, cos_2theta) +
           scaled<per_row>(coupling_row_, j, w.cos_link[j]) + A_ * scaled<per_row>(A_row_, j, w.cos_lag[j]);
    }
    return h;
  }

  /// ρ̄ = (1/N) Σ cos²((θ_j − θ_{j+1})/2) = 1/2 + (1/2N) Σ cos(θ_j − θ_{j+1}), the ∫ρ̄ integrand,
  /// from the sum of the links' cosines.
  ROTORSWEEP_HD V alignment_from_link_sum(const V& cos_link_sum) const {
    return V(0.5) + V(0.5 / double(rows_)) * cos_link_sum;
  }

  template <bool per_row>
  ROTORSWEEP_HD void integrands(const Workspace& w, const RowSums& sums, const V* f, V* qdot) const {
    row_integrands(
        integrals_, rows_, A_, g_, [&] { return sums.lag; }, weighted_lag<per_row>(w), f,
        [&] { return alignment_from_link_sum(sums.cos_link); },
        [&] { return energy_from_trigonometry<per_row>(w); }, qdot);
  }

  template <bool per_row>
  ROTORSWEEP_HD void integrand_gradients(Workspace& w, const V* f, const Jacobian& J, const V* df_dt,
                                         V* dq_dtheta, V* dq_dt) const {
    const std::size_t n = rows_;
    const auto cos_lag = [&](std::size_t k) { return scaled<per_row>(A_row_, k, w.cos_lag[k]); };
    const auto alignment_gradient = [&](V* grad) { alignment_gradient_range(w, grad, 0, n); };
    row_integrand_gradients(integrals_, n, A_, g_, weighted_lag<per_row>(w), cos_lag, f, J, df_dt, w.product,
                            alignment_gradient, dq_dtheta, dq_dt);
  }

  std::size_t rows_;
  bool reads_rows_;  ///< W or H carried: their integrands read every row's trigonometry
  V *A_row_, *anisotropy_row_, *coupling_row_;  ///< 1 + δ_j, 1 + α_j, 1 + β_j per lane
  bool disordered_ = false;  ///< some lane has a factor other than 1: the per-row loops run
  V A_ = V(1.0), g_ = V(1.0), inv_g_ = V(1.0);
  V strict_fm_ = V(0.0);  ///< 1 in lanes whose member is symmetry protected
};

}  // namespace rotorsweep::kernels
