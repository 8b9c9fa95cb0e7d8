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
#include "kernels/models/model_concept.hpp"
#include "kernels/models/rows/integrals.hpp"
#include "kernels/models/rows/row_quadratures.hpp"

namespace rotorsweep::kernels {

/// H = Σ_j [−a cos 2θ_j + A cos(θ_j − t)] + Σ_j Σ_{u=1..M} [b_u cos(θ_j − θ_{j+u}) − c_u cos(θ_j + θ_{j+u})]
/// and g dθ_j/dt = −∂H/∂θ_j. Periodic rows wrap j + u (2M < N, so that no pair is counted twice);
/// open rows drop the pairs that would cross an edge (M < N). The table is the same in every lane
/// (a scene's), A and g are per lane. One sincos per row and one for the drive phase per
/// evaluation; the pair terms follow from products. It carries the quadratures of the Integrals
/// given at construction and satisfies LaneModel.
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
  };

  /// Lane values of caller storage the model keeps: b_u and c_u for u < N.
  static constexpr std::size_t storage_size(std::size_t n) { return 2 * n; }

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
      : CarriedRowQuadratures(carried), rows_(rows), b_(arena.take(rows)), c_(arena.take(rows)) {}  // zeros
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
  }

  /// A bound on the spectral radius of g ∂f/∂θ in `lane` (Gershgorin, over every θ and t): a row
  /// has at most two partners u apart, so 4 |a| + A + 4 Σ_u (|b_u| + |c_u|).
  ROTORSWEEP_HD double curvature_bound(std::size_t lane) const {
    double couplings = 0.0;
    for (std::size_t u = 0; u < range_; ++u)
      couplings += std::fabs(lane_get(b_[u], 0)) + std::fabs(lane_get(c_[u], 0));
    return 4.0 * std::fabs(lane_get(a_, 0)) + std::fabs(lane_get(A_, lane)) + 4.0 * couplings;
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
      const V cos_2theta = w.cos_row[j] * w.cos_row[j] - w.sin_row[j] * w.sin_row[j];
      J.entry(j, j) += inv_g_ * (V(-4.0) * a_ * cos_2theta + A_ * w.cos_lag[j]);
      df_dt[j] = lane_neg(inv_g_) * A_ * w.cos_lag[j];
    }
    for_each_pair([&](std::size_t j, std::size_t k, std::size_t u) {
      const V cos_difference = w.cos_row[j] * w.cos_row[k] + w.sin_row[j] * w.sin_row[k];
      const V cos_sum = w.cos_row[j] * w.cos_row[k] - w.sin_row[j] * w.sin_row[k];
      // ∂f_j/∂θ_j and ∂f_k/∂θ_k gain b cos(θj − θk) − c cos(θj + θk); ∂f_j/∂θ_k = −b cos(θj − θk) − c cos(θj
      // + θk)
      const V same = inv_g_ * (b_[u] * cos_difference - c_[u] * cos_sum);
      J.entry(j, j) += same;
      J.entry(k, k) += same;
      J.add_pair(j, k, lane_neg(inv_g_) * (b_[u] * cos_difference + c_[u] * cos_sum));
    });
    J.keep_constant_solutions(strict_fm_ != V(0.0));
    integrand_gradients(w, f, J, df_dt, dq_dtheta, dq_dt);
    row_moment_gradients(integrals_, rows_, t, qdot, dq_dtheta, dq_dt);
  }

  ROTORSWEEP_HD V energy(Workspace& w, const V* theta, V t) const {
    trigonometry(w, theta, t);
    return energy_from_trigonometry(w);
  }

  /// Links between neighbouring rows: N periodic, N − 1 open.
  ROTORSWEEP_HD std::size_t links() const { return open_ ? rows_ - 1 : rows_; }

  /// The row profile at (θ, t): drive[j] = A sin(θ_j − t), row j's share of the drive integrand R,
  /// and link[j] = cos²((θ_j − θ_{j+1})/2) for each link, whose mean is ρ̄.
  ROTORSWEEP_HD void row_profile(Workspace& w, const V* theta, V t, V* drive, V* link) const {
    trigonometry(w, theta, t);
    for (std::size_t j = 0; j < rows_; ++j) drive[j] = A_ * w.sin_lag[j];
    for (std::size_t j = 0; j < links(); ++j) {
      const std::size_t k = (j + 1) % rows_;
      link[j] = V(0.5) + V(0.5) * (w.cos_row[j] * w.cos_row[k] + w.sin_row[j] * w.sin_row[k]);
    }
  }

 private:
  /// Calls f(j, k, u − 1) for every coupled pair k = j + u (wrapped when periodic), each once.
  template <class F>
  ROTORSWEEP_HD void for_each_pair(F&& f) const {
    const std::size_t n = rows_;
    for (std::size_t u = 1; u <= range_; ++u)
      for (std::size_t j = 0; j < n; ++j) {
        if (open_ && j + u >= n) break;
        f(j, (j + u) % n, u - 1);
      }
  }

  ROTORSWEEP_HD void trigonometry(Workspace& w, const V* theta, V t) const {
    V sin_t, cos_t;
    lane_sincos(t, sin_t, cos_t);
    for (std::size_t j = 0; j < rows_; ++j) {
      lane_sincos(theta[j], w.sin_row[j], w.cos_row[j]);
      w.sin_lag[j] = w.sin_row[j] * cos_t - w.cos_row[j] * sin_t;
      w.cos_lag[j] = w.cos_row[j] * cos_t + w.sin_row[j] * sin_t;
    }
  }

  ROTORSWEEP_HD void torques(const Workspace& w, V* f) const {
    for (std::size_t j = 0; j < rows_; ++j) {
      const V sin_2theta = V(2.0) * w.sin_row[j] * w.cos_row[j];
      f[j] = V(-2.0) * a_ * sin_2theta + A_ * w.sin_lag[j];
    }
    for_each_pair([&](std::size_t j, std::size_t k, std::size_t u) {
      const V sin_difference = w.sin_row[j] * w.cos_row[k] - w.cos_row[j] * w.sin_row[k];
      const V sin_sum = w.sin_row[j] * w.cos_row[k] + w.cos_row[j] * w.sin_row[k];
      f[j] += b_[u] * sin_difference - c_[u] * sin_sum;
      f[k] += lane_neg(b_[u]) * sin_difference - c_[u] * sin_sum;
    });
    for (std::size_t j = 0; j < rows_; ++j) f[j] *= inv_g_;
  }

  ROTORSWEEP_HD V energy_from_trigonometry(const Workspace& w) const {
    V h(0.0);
    for (std::size_t j = 0; j < rows_; ++j) {
      const V cos_2theta = w.cos_row[j] * w.cos_row[j] - w.sin_row[j] * w.sin_row[j];
      h += lane_neg(a_) * cos_2theta + A_ * w.cos_lag[j];
    }
    for_each_pair([&](std::size_t j, std::size_t k, std::size_t u) {
      const V cos_difference = w.cos_row[j] * w.cos_row[k] + w.sin_row[j] * w.sin_row[k];
      const V cos_sum = w.cos_row[j] * w.cos_row[k] - w.sin_row[j] * w.sin_row[k];
      h += b_[u] * cos_difference - c_[u] * cos_sum;
    });
    return h;
  }

  /// ρ̄ = mean over neighbouring rows (N links periodic, N − 1 open) of cos²((θ_j − θ_{j+1})/2),
  /// the ∫ρ̄ integrand.
  ROTORSWEEP_HD V alignment_from_trigonometry(const Workspace& w) const {
    V sum(0.0);
    for (std::size_t j = 0; j < links(); ++j) {
      const std::size_t k = (j + 1) % rows_;
      sum += w.cos_row[j] * w.cos_row[k] + w.sin_row[j] * w.sin_row[k];
    }
    return V(0.5) + V(0.5 / double(links())) * sum;
  }

  ROTORSWEEP_HD void integrands(const Workspace& w, const V* f, V* qdot) const {
    row_integrands(
        integrals_, rows_, A_, g_, [&] { return row_sum(rows_, w.sin_lag); }, w.sin_lag, f,
        [&] { return alignment_from_trigonometry(w); }, [&] { return energy_from_trigonometry(w); }, qdot);
  }

  ROTORSWEEP_HD void integrand_gradients(Workspace& w, const V* f, const Jacobian& J, const V* df_dt,
                                         V* dq_dtheta, V* dq_dt) const {
    const std::size_t n = rows_;
    const auto alignment_gradient = [&](V* grad) {
      const V scale(0.5 / double(links()));
      for (std::size_t k = 0; k < n; ++k) grad[k] = V(0.0);
      for (std::size_t j = 0; j < links(); ++j) {
        const std::size_t k = (j + 1) % n;
        const V sin_link = w.sin_row[j] * w.cos_row[k] - w.cos_row[j] * w.sin_row[k];
        grad[j] -= scale * sin_link;
        grad[k] += scale * sin_link;
      }
    };
    row_integrand_gradients(
        integrals_, n, A_, g_, w.sin_lag, [&](std::size_t k) { return w.cos_lag[k]; }, f, J, df_dt, w.product,
        alignment_gradient, dq_dtheta, dq_dt);
  }

  std::size_t rows_;
  V *b_, *c_;  ///< b_u, c_u at u − 1, the same in every lane
  V a_ = V(1.5);
  std::size_t range_ = 0;
  bool open_ = false;
  V A_ = V(1.0), g_ = V(1.0), inv_g_ = V(1.0);
  V strict_fm_ = V(0.0);
};

}  // namespace rotorsweep::kernels
