// The row profile of a member's periods (docs/model.md §3 "Row profiles"): each row's share of the
// drive integral R_j = A_j ∫ sin(θ_j − t) dt and each link's ∫ cos²((θ_j − θ_{j+1})/2) dt.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/lane_state.hpp"

namespace rotorsweep::ensemble {

/// The per-row arrays of a row profile's integral: θ and f at a step's start, f at its end, the
/// interpolant's node and the profile there, the period's sums, and f at the nodes (not kept).
template <class V>
struct RowProfileArrays {
  ROTORSWEEP_HD RowProfileArrays(std::size_t rows, kernels::LaneArena<V>& arena)
      : theta_before(arena.take(rows)),
        f_before(arena.take(rows)),
        f_now(arena.take(rows)),
        theta_node(arena.take(rows)),
        drive_node(arena.take(rows)),
        link_node(arena.take(rows)),
        drive_sum(arena.take(rows)),
        link_sum(arena.take(rows)),
        scratch(arena.take(rows)) {}
  V *theta_before, *f_before, *f_now, *theta_node, *drive_node, *link_node, *drive_sum, *link_sum, *scratch;
};

/// Integrates a model's row profile over every accepted step of its lanes, over scratch taken from
/// an arena, on the host's lanes and on a GPU thread alike. With an adaptive integrator each step
/// [t0, t0 + h] is integrated by two-point Gauss–Legendre quadrature of the cubic Hermite
/// interpolant of θ through (θ0, f0) and (θ1, f1): fourth order, like the steppers that steer it.
/// With the Langevin stepper (`stochastic`) the profile is summed at each step's start, as that
/// stepper sums R. A lane's values depend on its own member only: f is evaluated for every lane,
/// but a lane keeps it only when the lane started or stepped.
template <class Model, bool stochastic>
class RowProfileIntegral {
 public:
  using V = typename Model::lane_type;
  using Workspace = typename Model::Workspace;
  static constexpr std::size_t nq = Model::max_quadratures;

  /// Takes its views for N = rows (none for rows = 0: switched off).
  ROTORSWEEP_HD RowProfileIntegral(std::size_t rows, kernels::LaneArena<V>& arena)
      : n_(rows), row_(rows, arena), qdot_(arena.take(rows > 0 ? nq + 1 : 0)) {
    if (arena.counting()) return;
    for (std::size_t j = 0; j < n_; ++j) row_.drive_sum[j] = row_.link_sum[j] = V(0.0);
  }

  ROTORSWEEP_HD std::size_t links() const { return links_; }

  /// A member enters `lane` at the state s: its sums restart.
  ROTORSWEEP_HD void start(const Model& model, Workspace& work, const kernels::LaneState<V>& s,
                           std::size_t lane) {
    links_ = model.links();
    for (std::size_t j = 0; j < n_; ++j) {
      kernels::lane_set(row_.drive_sum[j], lane, 0.0);
      kernels::lane_set(row_.link_sum[j], lane, 0.0);
    }
    if constexpr (!stochastic) {
      model.evaluate(work, s.y, s.t, row_.scratch, qdot_);
      for (std::size_t j = 0; j < n_; ++j)
        kernels::lane_set(row_.f_before[j], lane, kernels::lane_get(row_.scratch[j], lane));
    }
  }

  ROTORSWEEP_HD void before_step(const Model& model, Workspace& work, const kernels::LaneState<V>& s) {
    t_before_ = s.t;
    if constexpr (stochastic)
      model.row_profile(work, s.y, s.t, row_.drive_node, row_.link_node);
    else
      for (std::size_t j = 0; j < n_; ++j) row_.theta_before[j] = s.y[j];
  }

  ROTORSWEEP_HD void after_step(const Model& model, Workspace& work, const kernels::LaneState<V>& s,
                                kernels::lane_mask<V> accepted) {
    const V h = kernels::lane_select(accepted, s.t - t_before_, V(0.0));
    if constexpr (stochastic) {
      add(h, row_.drive_node, row_.link_node);
    } else {
      model.evaluate(work, s.y, s.t, row_.f_now, qdot_);
      add_node(model, work, V(0.21132486540518711775), h, s.y);  // 1/2 − √3/6
      add_node(model, work, V(0.78867513459481288225), h, s.y);  // 1/2 + √3/6
      for (std::size_t j = 0; j < n_; ++j)
        row_.f_before[j] = kernels::lane_select(accepted, row_.f_now[j], row_.f_before[j]);
    }
  }

  /// The lane's period just ended: writes its R_j (rows) then its link integrals (links) to `out`
  /// and starts the next period's sums.
  ROTORSWEEP_HD void take_period(std::size_t lane, double* out) {
    for (std::size_t j = 0; j < n_; ++j) {
      out[j] = kernels::lane_get(row_.drive_sum[j], lane);
      kernels::lane_set(row_.drive_sum[j], lane, 0.0);
    }
    for (std::size_t j = 0; j < links_; ++j) {
      out[n_ + j] = kernels::lane_get(row_.link_sum[j], lane);
      kernels::lane_set(row_.link_sum[j], lane, 0.0);
    }
  }

 private:
  /// Adds half the step times the profile at θ(t0 + s h) of the cubic Hermite interpolant.
  ROTORSWEEP_HD void add_node(const Model& model, Workspace& work, V s, V h, const V* theta_now) {
    const V r = V(1.0) - s;
    const V start = (V(1.0) + V(2.0) * s) * r * r, start_slope = s * r * r * h;
    const V end = s * s * (V(3.0) - V(2.0) * s), end_slope = kernels::lane_neg(s * s * r) * h;
    for (std::size_t j = 0; j < n_; ++j)
      row_.theta_node[j] = start * row_.theta_before[j] + start_slope * row_.f_before[j] +
                           end * theta_now[j] + end_slope * row_.f_now[j];
    model.row_profile(work, row_.theta_node, t_before_ + s * h, row_.drive_node, row_.link_node);
    add(V(0.5) * h, row_.drive_node, row_.link_node);
  }

  ROTORSWEEP_HD void add(V weight, const V* drive, const V* link) {
    for (std::size_t j = 0; j < n_; ++j) row_.drive_sum[j] += weight * drive[j];
    for (std::size_t j = 0; j < links_; ++j) row_.link_sum[j] += weight * link[j];
  }

  std::size_t n_;
  std::size_t links_ = 0;
  RowProfileArrays<V> row_;  ///< the per-row arrays
  V* qdot_;
  V t_before_ = V(0.0);
};

}  // namespace rotorsweep::ensemble
