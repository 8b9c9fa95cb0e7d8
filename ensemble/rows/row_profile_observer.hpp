// The row profile of a member's periods (docs/model.md §3 "Row profiles"): each row's share of the
// drive integral R_j = A_j ∫ sin(θ_j − t) dt and each link's ∫ cos²((θ_j − θ_{j+1})/2) dt.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/models/model_concept.hpp"

namespace rotorsweep::ensemble {

/// Integrates the model's row profile over every accepted step. With an adaptive integrator each
/// step [t0, t0 + h] is integrated by two-point Gauss–Legendre quadrature of the cubic Hermite
/// interpolant of θ through (θ0, f0) and (θ1, f1): fourth order, like the steppers that steer it.
/// With the Langevin stepper the profile is summed at each step's start, as that stepper sums R.
/// A lane's values depend on its own member only: f is evaluated for every lane, but a lane keeps
/// it only when the lane started or stepped. Switched off (or for a model without row profiles) it
/// costs one branch per step.
template <class Loop>
class RowProfileObserver {
 public:
  using V = typename Loop::V;
  using Model = typename Loop::model_type;
  static constexpr bool reports = kernels::ReportsRowProfile<Model>;

  RowProfileObserver(std::size_t dimension, bool enabled)
      : n_(dimension),
        enabled_(enabled && reports),
        storage_(enabled_ ? 9 * dimension + Loop::quadrature_slots + 1 : 0) {
    if (!enabled_) return;
    kernels::LaneArena<V> arena(storage_.data(), storage_.size());
    for (V** view : {&theta_before_, &f_before_, &f_now_, &theta_node_, &drive_node_, &link_node_,
                     &drive_sum_, &link_sum_, &scratch_})
      *view = arena.take(n_);
    qdot_ = arena.take(Loop::quadrature_slots + 1);
    for (std::size_t j = 0; j < n_; ++j) drive_sum_[j] = link_sum_[j] = V(0.0);
  }

  bool enabled() const { return enabled_; }
  std::size_t links() const { return links_; }

  void start(Loop& loop, std::size_t lane) {
    if constexpr (reports) {
      if (!enabled_) return;
      links_ = loop.model().links();
      for (std::size_t j = 0; j < n_; ++j) {
        kernels::lane_set(drive_sum_[j], lane, 0.0);
        kernels::lane_set(link_sum_[j], lane, 0.0);
      }
      if constexpr (!Loop::stochastic) {
        loop.model().evaluate(loop.workspace(), loop.state().y, loop.state().t, scratch_, qdot_);
        for (std::size_t j = 0; j < n_; ++j)
          kernels::lane_set(f_before_[j], lane, kernels::lane_get(scratch_[j], lane));
      }
    }
  }

  void before_step(Loop& loop) {
    if constexpr (reports) {
      if (!enabled_) return;
      const auto& s = loop.state();
      t_before_ = s.t;
      if constexpr (Loop::stochastic)
        loop.model().row_profile(loop.workspace(), s.y, s.t, drive_node_, link_node_);
      else
        for (std::size_t j = 0; j < n_; ++j) theta_before_[j] = s.y[j];
    }
  }

  void after_step(Loop& loop, kernels::lane_mask<V> accepted) {
    if constexpr (reports) {
      if (!enabled_) return;
      const auto& s = loop.state();
      const V h = kernels::lane_select(accepted, s.t - t_before_, V(0.0));
      if constexpr (Loop::stochastic) {
        add(h, drive_node_, link_node_);
      } else {
        loop.model().evaluate(loop.workspace(), s.y, s.t, f_now_, qdot_);
        for (const double node : gauss_nodes) {
          hermite(V(node), h, s.y);
          loop.model().row_profile(loop.workspace(), theta_node_, t_before_ + V(node) * h, drive_node_,
                                   link_node_);
          add(V(0.5) * h, drive_node_, link_node_);
        }
        for (std::size_t j = 0; j < n_; ++j)
          f_before_[j] = kernels::lane_select(accepted, f_now_[j], f_before_[j]);
      }
    }
  }

  /// The lane's period just ended: its R_j (rows) then its link integrals (links), and a fresh start.
  std::vector<double> take_period(std::size_t lane) {
    std::vector<double> values(n_ + links_);
    for (std::size_t j = 0; j < n_; ++j) {
      values[j] = kernels::lane_get(drive_sum_[j], lane);
      kernels::lane_set(drive_sum_[j], lane, 0.0);
    }
    for (std::size_t j = 0; j < links_; ++j) {
      values[n_ + j] = kernels::lane_get(link_sum_[j], lane);
      kernels::lane_set(link_sum_[j], lane, 0.0);
    }
    return values;
  }

 private:
  static constexpr double gauss_nodes[2] = {0.21132486540518711775, 0.78867513459481288225};  // 1/2 ∓ √3/6

  /// θ(t0 + s h) of the cubic Hermite interpolant, into theta_node_.
  void hermite(V s, V h, const V* theta_now) {
    const V r = V(1.0) - s;
    const V start = (V(1.0) + V(2.0) * s) * r * r, start_slope = s * r * r * h;
    const V end = s * s * (V(3.0) - V(2.0) * s), end_slope = kernels::lane_neg(s * s * r) * h;
    for (std::size_t j = 0; j < n_; ++j)
      theta_node_[j] =
          start * theta_before_[j] + start_slope * f_before_[j] + end * theta_now[j] + end_slope * f_now_[j];
  }

  void add(V weight, const V* drive, const V* link) {
    for (std::size_t j = 0; j < n_; ++j) drive_sum_[j] += weight * drive[j];
    for (std::size_t j = 0; j < links_; ++j) link_sum_[j] += weight * link[j];
  }

  std::size_t n_;
  std::size_t links_ = 0;
  bool enabled_;
  kernels::lane_vector<V> storage_;
  V *theta_before_ = nullptr, *f_before_ = nullptr, *f_now_ = nullptr, *theta_node_ = nullptr;
  V *drive_node_ = nullptr, *link_node_ = nullptr, *drive_sum_ = nullptr, *link_sum_ = nullptr;
  V *scratch_ = nullptr, *qdot_ = nullptr;
  V t_before_ = V(0.0);
};

}  // namespace rotorsweep::ensemble
