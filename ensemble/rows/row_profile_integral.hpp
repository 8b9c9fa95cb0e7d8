// The row profile of a member's periods (docs/model.md §3 "Row profiles"): each row's share of the
// drive integral R_j = A_j ∫ sin(θ_j − t) dt and each link's ∫ cos²((θ_j − θ_{j+1})/2) dt.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/lane_state.hpp"

namespace rotorsweep::ensemble {

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
      : n_(rows),
        theta_before_(arena.take(rows)),
        f_before_(arena.take(rows)),
        f_now_(arena.take(rows)),
        theta_node_(arena.take(rows)),
        drive_node_(arena.take(rows)),
        link_node_(arena.take(rows)),
        drive_sum_(arena.take(rows)),
        link_sum_(arena.take(rows)),
        scratch_(arena.take(rows)),
        qdot_(arena.take(rows > 0 ? nq + 1 : 0)) {
    if (arena.counting()) return;
    for (std::size_t j = 0; j < n_; ++j) drive_sum_[j] = link_sum_[j] = V(0.0);
  }

  ROTORSWEEP_HD std::size_t links() const { return links_; }

  /// A member enters `lane` at the state s: its sums restart.
  ROTORSWEEP_HD void start(const Model& model, Workspace& work, const kernels::LaneState<V>& s,
                           std::size_t lane) {
    links_ = model.links();
    for (std::size_t j = 0; j < n_; ++j) {
      kernels::lane_set(drive_sum_[j], lane, 0.0);
      kernels::lane_set(link_sum_[j], lane, 0.0);
    }
    if constexpr (!stochastic) {
      model.evaluate(work, s.y, s.t, scratch_, qdot_);
      for (std::size_t j = 0; j < n_; ++j)
        kernels::lane_set(f_before_[j], lane, kernels::lane_get(scratch_[j], lane));
    }
  }

  ROTORSWEEP_HD void before_step(const Model& model, Workspace& work, const kernels::LaneState<V>& s) {
    t_before_ = s.t;
    if constexpr (stochastic)
      model.row_profile(work, s.y, s.t, drive_node_, link_node_);
    else
      for (std::size_t j = 0; j < n_; ++j) theta_before_[j] = s.y[j];
  }

  ROTORSWEEP_HD void after_step(const Model& model, Workspace& work, const kernels::LaneState<V>& s,
                                kernels::lane_mask<V> accepted) {
    const V h = kernels::lane_select(accepted, s.t - t_before_, V(0.0));
    if constexpr (stochastic) {
      add(h, drive_node_, link_node_);
    } else {
      model.evaluate(work, s.y, s.t, f_now_, qdot_);
      add_node(model, work, V(0.21132486540518711775), h, s.y);  // 1/2 − √3/6
      add_node(model, work, V(0.78867513459481288225), h, s.y);  // 1/2 + √3/6
      for (std::size_t j = 0; j < n_; ++j)
        f_before_[j] = kernels::lane_select(accepted, f_now_[j], f_before_[j]);
    }
  }

  /// The lane's period just ended: writes its R_j (rows) then its link integrals (links) to `out`
  /// and starts the next period's sums.
  ROTORSWEEP_HD void take_period(std::size_t lane, double* out) {
    for (std::size_t j = 0; j < n_; ++j) {
      out[j] = kernels::lane_get(drive_sum_[j], lane);
      kernels::lane_set(drive_sum_[j], lane, 0.0);
    }
    for (std::size_t j = 0; j < links_; ++j) {
      out[n_ + j] = kernels::lane_get(link_sum_[j], lane);
      kernels::lane_set(link_sum_[j], lane, 0.0);
    }
  }

 private:
  /// Adds half the step times the profile at θ(t0 + s h) of the cubic Hermite interpolant.
  ROTORSWEEP_HD void add_node(const Model& model, Workspace& work, V s, V h, const V* theta_now) {
    const V r = V(1.0) - s;
    const V start = (V(1.0) + V(2.0) * s) * r * r, start_slope = s * r * r * h;
    const V end = s * s * (V(3.0) - V(2.0) * s), end_slope = kernels::lane_neg(s * s * r) * h;
    for (std::size_t j = 0; j < n_; ++j)
      theta_node_[j] =
          start * theta_before_[j] + start_slope * f_before_[j] + end * theta_now[j] + end_slope * f_now_[j];
    model.row_profile(work, theta_node_, t_before_ + s * h, drive_node_, link_node_);
    add(V(0.5) * h, drive_node_, link_node_);
  }

  ROTORSWEEP_HD void add(V weight, const V* drive, const V* link) {
    for (std::size_t j = 0; j < n_; ++j) drive_sum_[j] += weight * drive[j];
    for (std::size_t j = 0; j < links_; ++j) link_sum_[j] += weight * link[j];
  }

  std::size_t n_;
  std::size_t links_ = 0;
  V *theta_before_, *f_before_, *f_now_, *theta_node_, *drive_node_, *link_node_, *drive_sum_, *link_sum_;
  V *scratch_, *qdot_;
  V t_before_ = V(0.0);
};

}  // namespace rotorsweep::ensemble
