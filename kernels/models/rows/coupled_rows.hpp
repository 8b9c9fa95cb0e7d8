// The row model with a coupling table over a range of rows and periodic or open rows (docs/model.md §1
// "Extended couplings", §8): right-hand side, dense symmetric Jacobian, ∂f/∂t, energy, integrands (§3).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/lane_math.hpp"
#include "kernels/linear/dense_symmetric.hpp"
#include "kernels/steppers/model_concept.hpp"
#include "kernels/models/rows/integrals.hpp"
#include "kernels/models/rows/row_quadratures.hpp"

namespace rotorsweep::kernels {

/// H = Σ_j [−a cos 2θ_j + A cos(θ_j − t)] + Σ_j Σ_{u=1..M} [b_u cos(θ_j − θ_{j+u}) − c_u cos(θ_j + θ_{j+u})]
/// and g dθ_j/dt = −∂H/∂θ_j. Periodic rows wrap j + u (2M < N, so that no pair is counted twice);
/// open rows drop the pairs that would cross an edge (M < N). The table is the same in every lane
/// (a scene's), A and g are per lane, and so is the quenched disorder of §7: A_j = A (1 + δ_j) and
/// a_j = a (1 + α_j). One sincos per row and one for the drive phase per evaluation; the pair terms
/// follow from products. It carries the quadratures of the Integrals given at construction and
/// satisfies LaneModel.
template <class V>
class CoupledRows : public CarriedRowQuadratures {
 public:
  using lane_type = V;
  using Jacobian = DenseSymmetric<V>;
  static constexpr double period = two_pi;

  /// One lane's parameters; the table (a, b[0 .. range), c[0 .. range)) and the boundary must be
  /// the same in every lane.
  struct Parameters {
    double A = 1.0;
    double g = 1.0;
    bool strict_fm = false;
    double a = 1.5;
    const double* b = nullptr;
    const double* c = nullptr;
    std::size_t range = 0;
    bool open = false;
    const double* A_rows = nullptr;           ///< δ_j: A_j = A (1 + δ_j)
    const double* anisotropy_rows = nullptr;  ///< α_j: a_j = a (1 + α_j)
  };

  /// Lane values of caller storage the model keeps: b_u and c_u for u < N, and each row's factors
  /// 1 + δ_j and 1 + α_j.
  static constexpr std::size_t storage_size(std::size_t n) { return 4 * n; }

  struct Workspace {
    static constexpr std::size_t storage_size(std::size_t n) { return 5 * n; }
    ROTORSWEEP_HD Workspace(std::size_t n, LaneArena<V>& arena)
        : sin_row(arena.take(n)),
          cos_row(arena.take(n)),
          sin_lag(arena.take(n)),
          cos_lag(arena.take(n)),
          product(arena.take(n)) {}
    V *sin_row, *cos_row;  // sin θ_j, cos θ_j
    V *sin_lag, *cos_lag;  // sin(θ_j − t), cos(θ_j − t)
    V* product;            // J·v products for the integrand gradients
  };

  ROTORSWEEP_HD CoupledRows(std::size_t rows, LaneArena<V>& arena, Integrals carried)
      : CarriedRowQuadratures(carried),
        rows_(rows),
        b_(arena.take(rows)),
        c_(arena.take(rows)),
        A_row_(arena.take(rows)),
        anisotropy_row_(arena.take(rows)) {
    if (arena.counting()) return;
    for (std::size_t j = 0; j < rows; ++j) A_row_[j] = anisotropy_row_[j] = V(1.0);
  }
  ROTORSWEEP_HD CoupledRows(std::size_t rows, LaneArena<V>& arena, Integrals carried, const Parameters& p)
      : CoupledRows(rows, arena, carried) {
    for (std::size_t l = 0; l < lane_width<V>; ++l) set_lane(l, p);
  }

  ROTORSWEEP_HD void set_lane(std::size_t lane, const Parameters& p) {
    lane_set(A_, lane, p.A);
    lane_set(g_, lane, p.g);
    lane_set(inv_g_, lane, 1.0 / p.g);
    lane_set(strict_fm_, lane, p.strict_fm ? 1.0 : 0.0);
    a_ = V(p.a);
    range_ = p.range < rows_ ? p.range : rows_ - 1;
    open_ = p.open;
    for (std::size_t u = 0; u < range_; ++u) {
      b_[u] = V(p.b[u]);
      c_[u] = V(p.c[u]);
    }
    for (std::size_t j = 0; j < rows_; ++j) {
      const double A_factor = p.A_rows ? 1.0 + p.A_rows[j] : 1.0;
      const double anisotropy_factor = p.anisotropy_rows ? 1.0 + p.anisotropy_rows[j] : 1.0;
      lane_set(A_row_[j], lane, A_factor);
      lane_set(anisotropy_row_[j], lane, anisotropy_factor);
      disordered_ = disordered_ || A_factor != 1.0 || anisotropy_factor != 1.0;
    }
  }

  /// A bound on the spectral radius of g ∂f/∂θ in `lane` (Gershgorin, over every θ and t): a row
  /// has at most two partners u apart, so max_j 4 |a_j| + |A_j| + 4 Σ_u (|b_u| + |c_u|).
  ROTORSWEEP_HD double curvature_bound(std::size_t lane) const {
    double couplings = 0.0;
    for (std::size_t u = 0; u < range_; ++u)
      couplings += std::fabs(lane_get(b_[u], 0)) + std::fabs(lane_get(c_[u], 0));
    double on_site = 0.0;
    for (std::size_t j = 0; j < rows_; ++j) {
      const double row = 4.0 * std::fabs(lane_get(a_, 0) * lane_get(anisotropy_row_[j], lane)) +
                         std::fabs(lane_get(A_, lane) * lane_get(A_row_[j], lane));
      on_site = row > on_site ? row : on_site;
    }
    return on_site + 4.0 * couplings;
  }

  ROTORSWEEP_HD std::size_t dimension() const { return rows_; }
  ROTORSWEEP_HD static constexpr StateScale scale(std::size_t) { return StateScale::absolute; }

  ROTORSWEEP_HD void evaluate(Workspace& w, const V* theta, V t, V* f, V* qdot) const {
    trigonometry(w, theta, t);
    torques(w, f);
    integrands(w, f, qdot);
    row_moment_integrands(integrals_, t, qdot);
  }

  ROTORSWEEP_HD void linearize(Workspace& w, const V* theta, V t, V* f, V* qdot, Jacobian& J, V* df_dt,
                               V* dq_dtheta, V* dq_dt) const {
    evaluate(w, theta, t, f, qdot);
    const std::size_t n = rows_;
    J.clear();
    J.set_band(range_, !open_);  // pairs at most range_ apart, and round the ring when periodic
    for (std::size_t j = 0; j < n; ++j) {
      J.entry(j, j) += on_site_curvature(w, j);
      df_dt[j] = lane_neg(inv_g_) * A_ * w.cos_lag[j];
    }
    for_each_pair(0, n, [&](std::size_t j, std::size_t k, std::size_t u) {
      const PairCurvatures pair = pair_curvatures(w, j, k, u);
      J.entry(j, j) += pair.same;
      J.entry(k, k) += pair.same;
      J.add_pair(j, k, pair.cross);
    });
    J.keep_constant_solutions(strict_fm_ != V(0.0));
    integrand_gradients(w, f, J, df_dt, dq_dtheta, dq_dt);
    row_moment_gradients(integrals_, rows_, t, qdot, dq_dtheta, dq_dt);
  }

  ROTORSWEEP_HD V energy(Workspace& w, const V* theta, V t) const {
    trigonometry(w, theta, t);
    return energy_range(w, 0, rows_);
  }

  /// Links between neighbouring rows: N periodic, N − 1 open.
  ROTORSWEEP_HD std::size_t links() const { return open_ ? rows_ - 1 : rows_; }

  /// The row profile at (θ, t): drive[j] = A sin(θ_j − t), row j's share of the drive integrand R,
  /// and link[j] = cos²((θ_j − θ_{j+1})/2) for each link, whose mean is ρ̄.
  ROTORSWEEP_HD void row_profile(Workspace& w, const V* theta, V t, V* drive, V* link) const {
    trigonometry(w, theta, t);
    profile_rows(w, drive, link, 0, rows_);
  }

  /// Whether lane `lane`'s member is symmetry protected (its stage solves keep all-equal rows equal).
  ROTORSWEEP_HD bool strict_fm(std::size_t lane) const { return lane_get(strict_fm_, lane) != 0.0; }

  using RowSums = RowRangeSums<V>;
  using IntegrandSums = IntegrandRangeSums<V>;

  // A team's evaluation (docs/architecture.md "Teams"): each rank takes its rows' trigonometry
  // (trigonometry_range), then, once every rank's is in place (a row's pairs reach other ranks' rows),
  // its rows' f, sums, J's rows and gradients. Each row's values come from the same operations in the
  // same order as the whole-row functions' above, so any split of the rows gives their f and J bit for bit.

  /// The trigonometry of rows [begin, end) at (θ, t) into the workspace. With disorder the lags
  /// carry their row's factor, (1 + δ_j) sin(θ_j − t) and (1 + δ_j) cos(θ_j − t): every term that
  /// reads them is one of A_j's, so each is A_j's term exactly (a factor 1 changes no bit).
  ROTORSWEEP_HD void trigonometry_range(Workspace& w, const V* theta, V t, std::size_t begin,
                                        std::size_t end) const {
    V sin_t, cos_t;
    lane_sincos(t, sin_t, cos_t);
    for (std::size_t j = begin; j < end; ++j) {
      lane_sincos(theta[j], w.sin_row[j], w.cos_row[j]);
      w.sin_lag[j] = w.sin_row[j] * cos_t - w.cos_row[j] * sin_t;
      w.cos_lag[j] = w.cos_row[j] * cos_t + w.sin_row[j] * sin_t;
      if (disordered_) {
        w.sin_lag[j] *= A_row_[j];
        w.cos_lag[j] *= A_row_[j];
      }
    }
  }
  /// f_j for rows [begin, end) and their sums of lags and of the cosines of the links after them, once
  /// every rank's trigonometry_range at (θ, t) is done (θ and t are read there).
  ROTORSWEEP_HD RowSums evaluate_range(const Workspace& w, const V*, V, V* f, std::size_t begin,
                                       std::size_t end) const {
    for (std::size_t j = begin; j < end; ++j) {
      f[j] = on_site_torque(w, j);
      for_each_pair_of(j, [&](std::size_t partner, std::size_t u, bool first) {
        f[j] += first ? pair_torques(w, j, partner, u).first : pair_torques(w, partner, j, u).second;
      });
      f[j] *= inv_g_;
    }
    RowSums sums;
    for (std::size_t j = begin; j < end; ++j) sums.lag += w.sin_lag[j];
    for (std::size_t j = begin; j < end && j < links(); ++j) sums.cos_link += cos_link(w, j);
    return sums;
  }
  /// The further sums over rows [begin, end) that W, S and H need (those the model carries), after
  /// the rank's evaluate_range; H's pair terms are counted at the pair's first row.
  ROTORSWEEP_HD IntegrandSums integrand_sums_range(const Workspace& w, const V* f, std::size_t begin,
                                                   std::size_t end) const {
    IntegrandSums sums;
    if (integrals_.work) sums.lag_force = row_products(begin, end, w.sin_lag, f);
    if (integrals_.stokes) sums.force_squares = row_products(begin, end, f, f);
    if (integrals_.energy) sums.energy = energy_range(w, begin, end);
    return sums;
  }
  /// The carried integrands at time t from the team's sums.
  ROTORSWEEP_HD void team_integrands(const RowSums& sums, const IntegrandSums& more, V t, V* qdot) const {
    integrands_from_team_sums(
        integrals_, A_, g_, sums, more,
        [&](const V& cos_links) { return alignment_from_link_sum(cos_links); }, t, qdot);
  }
  /// J's rows [begin, end) (every column) and ∂f/∂t there, once every rank's trigonometry_range at the
  /// point is done; `J` is the team's (entry(), set_band()).
  template <class Matrix>
  ROTORSWEEP_HD void jacobian_range(const Workspace& w, Matrix& J, V* df_dt, std::size_t begin,
                                    std::size_t end) const {
    J.set_band(range_, !open_);
    for (std::size_t j = begin; j < end; ++j) {
      for (std::size_t k = 0; k < rows_; ++k) J.entry(j, k) = V(0.0);
      J.entry(j, j) += on_site_curvature(w, j);
      df_dt[j] = lane_neg(inv_g_) * A_ * w.cos_lag[j];
      for_each_pair_of(j, [&](std::size_t partner, std::size_t u, bool first) {
        const PairCurvatures pair =
            first ? pair_curvatures(w, j, partner, u) : pair_curvatures(w, partner, j, u);
        J.entry(j, j) += pair.same;
        J.entry(j, partner) += pair.cross;
      });
    }
  }
  /// The carried integrands' gradients dq_dtheta[q·N + k] for rows k in [begin, end) at time t, and
  /// their parts of the sums behind ∂q̇/∂t in time_sums (team_time_derivatives), after the rank's
  /// jacobian_range (J x from J's rows [begin, end); `scratch` holds N values).
  template <class Matrix>
  ROTORSWEEP_HD void integrand_gradient_range(const Workspace& w, const V* f, const Matrix& J, const V* df_dt,
                                              V* scratch, V* dq_dtheta, V* time_sums, V t, std::size_t begin,
                                              std::size_t end) const {
    row_integrand_gradient_range(
        integrals_, rows_, A_, g_, w.sin_lag, [&](std::size_t k) { return w.cos_lag[k]; }, f,
        [&](const V* x, V* out) {
          for (std::size_t k = begin; k < end; ++k) {
            out[k] = V(0.0);
            out[k] += J.row_product(k, x);
          }
        },
        df_dt, scratch,
        [&](V* grad, std::size_t first, std::size_t last) { alignment_gradient_range(w, grad, first, last); },
        dq_dtheta, time_sums, begin, end);
    row_moment_gradient_range(integrals_, rows_, t, dq_dtheta, begin, end);
  }
  /// ∂q̇/∂t at time t from the team's time sums and the integrands there.
  ROTORSWEEP_HD void team_time_derivatives(const V* time_sums, V t, const V* qdot, V* dq_dt) const {
    time_derivatives_from_team_sums(integrals_, A_, g_, time_sums, t, qdot, dq_dt);
  }
  /// row_profile over rows [begin, end), their f into `f` as evaluate_range's, once every rank's
  /// trigonometry_range at (θ, t) is done: the same values per row, bit for bit.
  ROTORSWEEP_HD void row_profile_range(const Workspace& w, const V* theta, V t, V* f, V* drive, V* link,
                                       std::size_t begin, std::size_t end) const {
    evaluate_range(w, theta, t, f, begin, end);
    profile_rows(w, drive, link, begin, end);
  }

 private:
  /// Calls f(j, k, u − 1) for every coupled pair k = j + u (wrapped when periodic) whose first row j
  /// lies in [begin, end), each once, u by u and j ascending.
  template <class F>
  ROTORSWEEP_HD void for_each_pair(std::size_t begin, std::size_t end, F&& f) const {
    const std::size_t n = rows_;
    for (std::size_t u = 1; u <= range_; ++u)
      for (std::size_t j = begin; j < end; ++j) {
        if (open_ && j + u >= n) break;
        f(j, (j + u) % n, u - 1);
      }
  }
  /// Calls f(partner, u − 1, first) for every pair of row j in the order for_each_pair(0, N) visits
  /// them: (j, j + u) at j (first: j is the pair's first row), (j − u, j) at j − u, wrapped when periodic.
  template <class F>
  ROTORSWEEP_HD void for_each_pair_of(std::size_t j, F&& f) const {
    const std::size_t n = rows_;
    for (std::size_t u = 1; u <= range_; ++u) {
      const std::size_t before = (j + n - u) % n;
      const bool has_before = !open_ || j >= u, has_after = !open_ || j + u < n;
      if (has_before && before < j) f(before, u - 1, false);
      if (has_after) f((j + u) % n, u - 1, true);
      if (has_before && before > j) f(before, u - 1, false);
    }
  }

  /// What pair (j, k) coupled by b_u, c_u (at u − 1) adds to g f_j (first) and to g f_k (second).
  struct PairTorques {
    V first, second;
  };
  ROTORSWEEP_HD PairTorques pair_torques(const Workspace& w, std::size_t j, std::size_t k,
                                         std::size_t u) const {
    const V sin_difference = w.sin_row[j] * w.cos_row[k] - w.cos_row[j] * w.sin_row[k];
    const V sin_sum = w.sin_row[j] * w.cos_row[k] + w.cos_row[j] * w.sin_row[k];
    return {b_[u] * sin_difference - c_[u] * sin_sum, lane_neg(b_[u]) * sin_difference - c_[u] * sin_sum};
  }
  /// What pair (j, k) adds to ∂f_j/∂θ_j and ∂f_k/∂θ_k (same: (b cos(θj − θk) − c cos(θj + θk))/g) and
  /// ∂f_j/∂θ_k = ∂f_k/∂θ_j (cross: −(b cos(θj − θk) + c cos(θj + θk))/g).
  struct PairCurvatures {
    V same, cross;
  };
  ROTORSWEEP_HD PairCurvatures pair_curvatures(const Workspace& w, std::size_t j, std::size_t k,
                                               std::size_t u) const {
    const V cos_difference = w.cos_row[j] * w.cos_row[k] + w.sin_row[j] * w.sin_row[k];
    const V cos_sum = w.cos_row[j] * w.cos_row[k] - w.sin_row[j] * w.sin_row[k];
    return {inv_g_ * (b_[u] * cos_difference - c_[u] * cos_sum),
            lane_neg(inv_g_) * (b_[u] * cos_difference + c_[u] * cos_sum)};
  }
  /// Row j's own terms: g f_j before the pairs, and ∂f_j/∂θ_j before them.
  ROTORSWEEP_HD V on_site_torque(const Workspace& w, std::size_t j) const {
    const V sin_2theta = V(2.0) * w.sin_row[j] * w.cos_row[j];
    return V(-2.0) * anisotropy(j) * sin_2theta + A_ * w.sin_lag[j];
  }
  ROTORSWEEP_HD V on_site_curvature(const Workspace& w, std::size_t j) const {
    const V cos_2theta = w.cos_row[j] * w.cos_row[j] - w.sin_row[j] * w.sin_row[j];
    return inv_g_ * (V(-4.0) * anisotropy(j) * cos_2theta + A_ * w.cos_lag[j]);
  }
  /// a_j = a (1 + α_j), a without disorder.
  ROTORSWEEP_HD V anisotropy(std::size_t j) const { return disordered_ ? a_ * anisotropy_row_[j] : a_; }
  /// cos(θ_j − θ_{j+1}) of link j, and its sine.
  ROTORSWEEP_HD V cos_link(const Workspace& w, std::size_t j) const {
    const std::size_t k = (j + 1) % rows_;
    return w.cos_row[j] * w.cos_row[k] + w.sin_row[j] * w.sin_row[k];
  }
  ROTORSWEEP_HD V sin_link(const Workspace& w, std::size_t j) const {
    const std::size_t k = (j + 1) % rows_;
    return w.sin_row[j] * w.cos_row[k] - w.cos_row[j] * w.sin_row[k];
  }

  ROTORSWEEP_HD void trigonometry(Workspace& w, const V* theta, V t) const {
    trigonometry_range(w, theta, t, 0, rows_);
  }

  ROTORSWEEP_HD void torques(const Workspace& w, V* f) const {
    for (std::size_t j = 0; j < rows_; ++j) f[j] = on_site_torque(w, j);
    for_each_pair(0, rows_, [&](std::size_t j, std::size_t k, std::size_t u) {
      const PairTorques pair = pair_torques(w, j, k, u);
      f[j] += pair.first;
      f[k] += pair.second;
    });
    for (std::size_t j = 0; j < rows_; ++j) f[j] *= inv_g_;
  }

  /// H's terms of rows [begin, end) and of the pairs whose first row lies there: the rows' first, then
  /// the pairs u by u (over every row, the energy).
  ROTORSWEEP_HD V energy_range(const Workspace& w, std::size_t begin, std::size_t end) const {
    V h(0.0);
    for (std::size_t j = begin; j < end; ++j) {
      const V cos_2theta = w.cos_row[j] * w.cos_row[j] - w.sin_row[j] * w.sin_row[j];
      h += lane_neg(anisotropy(j)) * cos_2theta + A_ * w.cos_lag[j];
    }
    for_each_pair(begin, end, [&](std::size_t j, std::size_t k, std::size_t u) {
      const V cos_difference = w.cos_row[j] * w.cos_row[k] + w.sin_row[j] * w.sin_row[k];
      const V cos_sum = w.cos_row[j] * w.cos_row[k] - w.sin_row[j] * w.sin_row[k];
      h += b_[u] * cos_difference - c_[u] * cos_sum;
    });
    return h;
  }

  /// ρ̄ = mean over neighbouring rows (N links periodic, N − 1 open) of cos²((θ_j − θ_{j+1})/2),
  /// the ∫ρ̄ integrand, from Σ_links cos(θ_j − θ_{j+1}).
  ROTORSWEEP_HD V alignment_from_link_sum(const V& cos_links) const {
    return V(0.5) + V(0.5 / double(links())) * cos_links;
  }
  ROTORSWEEP_HD V alignment_from_trigonometry(const Workspace& w) const {
    V sum(0.0);
    for (std::size_t j = 0; j < links(); ++j) sum += cos_link(w, j);
    return alignment_from_link_sum(sum);
  }

  /// ∂ρ̄/∂θ_k for rows [first, last): −sin(θ_k − θ_{k+1}) of the link after k and +sin of the one
  /// before, over 2 × links, added in link order.
  ROTORSWEEP_HD void alignment_gradient_range(const Workspace& w, V* grad, std::size_t first,
                                              std::size_t last) const {
    const V scale(0.5 / double(links()));
    for (std::size_t k = first; k < last; ++k) {
      V sum(0.0);
      if (k >= 1) sum += scale * sin_link(w, k - 1);
      if (k < links()) sum -= scale * sin_link(w, k);
      if (k == 0 && !open_) sum += scale * sin_link(w, rows_ - 1);
      grad[k] = sum;
    }
  }

  /// The profile's values of rows [begin, end) after their trigonometry.
  ROTORSWEEP_HD void profile_rows(const Workspace& w, V* drive, V* link, std::size_t begin,
                                  std::size_t end) const {
    for (std::size_t j = begin; j < end; ++j) drive[j] = A_ * w.sin_lag[j];
    for (std::size_t j = begin; j < end && j < links(); ++j) link[j] = V(0.5) + V(0.5) * cos_link(w, j);
  }

  ROTORSWEEP_HD void integrands(const Workspace& w, const V* f, V* qdot) const {
    row_integrands(
        integrals_, rows_, A_, g_, [&] { return row_sum(rows_, w.sin_lag); }, w.sin_lag, f,
        [&] { return alignment_from_trigonometry(w); }, [&] { return energy_range(w, 0, rows_); }, qdot);
  }

  ROTORSWEEP_HD void integrand_gradients(Workspace& w, const V* f, const Jacobian& J, const V* df_dt,
                                         V* dq_dtheta, V* dq_dt) const {
    row_integrand_gradients(
        integrals_, rows_, A_, g_, w.sin_lag, [&](std::size_t k) { return w.cos_lag[k]; }, f, J, df_dt,
        w.product, [&](V* grad) { alignment_gradient_range(w, grad, 0, rows_); }, dq_dtheta, dq_dt);
  }

  std::size_t rows_;
  V *b_, *c_;  ///< b_u, c_u at u − 1, the same in every lane
  V *A_row_, *anisotropy_row_;  ///< 1 + δ_j and 1 + α_j per lane
  bool disordered_ = false;     ///< some lane has a factor other than 1 (else the uniform terms)
  V a_ = V(1.5);
  std::size_t range_ = 0;
  bool open_ = false;
  V A_ = V(1.0), g_ = V(1.0), inv_g_ = V(1.0);
  V strict_fm_ = V(0.0);
};

}  // namespace rotorsweep::kernels
