// One block of SIMD lanes working through members (architecture.md data flow): fill idle
// lanes from the plan, step all lanes in lockstep, close periods, retire and refill lanes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <vector>

#include "ensemble/member_plan.hpp"
#include "ensemble/member_result.hpp"
#include "ensemble/member_summary.hpp"
#include "ensemble/scene.hpp"
#include "ensemble/step_reducers.hpp"
#include "kernels/adaptive_integrator.hpp"
#include "kernels/integrals.hpp"
#include "kernels/lane_state.hpp"
#include "kernels/period_driver.hpp"

namespace rotorsweep::ensemble {

/// Runs members through lane_width<V> lanes of `Model` (a row model with quadratures Q)
/// advanced by `Stepper`. Each lane owns its member, time, step size and status; a member
/// that finishes or fails retires at once and (with scene.refill) its lane takes the next.
template <class Model, class Stepper>
class LaneBlock {
 public:
  using V = typename Model::lane_type;
  static constexpr kernels::Integrals Q = Model::integrals;
  static constexpr std::size_t width = kernels::lane_width<V>;

  explicit LaneBlock(const Scene& scene)
      : scene_(scene),
        model_(scene.rows, V(1.0), V(1.0)),
        integrator_(model_, {scene.rtol, scene.atol}, {.h_max = scene.h_max, .max_steps = scene.max_steps}),
        state_(scene.rows, Q.count()),
        work_(model_.make_workspace()),
        theta_before_(scene.rows),
        slips_(scene.slip_rate),
        lanes_(width) {
    state_.status.fill(kernels::LaneStatus::idle);
  }

  /// Takes members from next_member() (a std::optional<Member>; empty when the plan is
  /// exhausted) until none is left and every lane has retired; hands each result to retire().
  template <class NextMember, class Retire>
  void run(NextMember&& next_member, Retire&& retire) {
    for (;;) {
      if (scene_.refill || occupied_ == 0) fill_idle_lanes(next_member);
      if (occupied_ == 0) return;
      step();
      const bool period_ends = kernels::lane_any(state_.running() & (state_.t >= state_.t_stop));
      for (std::size_t l = 0; l < width; ++l) {
        if (!lanes_[l].occupied) continue;
        if (state_.status[l] != kernels::LaneStatus::ok)
          retire(finish(l, false));
        else if (period_ends && kernels::lane_get(state_.t, l) >= kernels::lane_get(state_.t_stop, l))
          close_period(l, retire);
      }
    }
  }

  double lane_steps_busy() const { return busy_; }    ///< Σ over attempts of lanes holding a member
  double lane_steps_total() const { return total_; }  ///< Σ over attempts of all lanes

 private:
  struct Lane {
    bool occupied = false;
    Member member;
    std::vector<PeriodRecord> history;
  };

  template <class NextMember>
  void fill_idle_lanes(NextMember& next_member) {
    std::array<bool, width> fresh{};
    bool any_fresh = false;
    for (std::size_t l = 0; l < width && occupied_ < width && !plan_exhausted_; ++l) {
      if (lanes_[l].occupied) continue;
      const std::optional<Member> member = next_member();
      plan_exhausted_ = !member;
      if (plan_exhausted_) break;
      start(l, *member);
      fresh[l] = any_fresh = true;
    }
    if constexpr (Q.alignment) {
      if (!any_fresh) return;
      const V rho = model_.alignment(work_, state_.theta.data(), state_.t);
      for (std::size_t l = 0; l < width; ++l)
        if (fresh[l]) extrema_.start_lane(l, kernels::lane_get(rho, l));
    }
  }

  void start(std::size_t l, const Member& member) {
    const std::vector<double> theta = member_initial_angles(scene_, member);
    for (std::size_t j = 0; j < scene_.rows; ++j) kernels::lane_set(state_.theta[j], l, theta[j]);
    for (auto& q : state_.quad) kernels::lane_set(q, l, 0.0);
    kernels::lane_set(state_.t, l, 0.0);
    kernels::lane_set(state_.h, l, 0.0);
    kernels::lane_set(state_.t_stop, l, kernels::drive_period);
    kernels::lane_set(state_.steps_accepted, l, 0.0);
    kernels::lane_set(state_.steps_rejected, l, 0.0);
    state_.status[l] = kernels::LaneStatus::ok;
    const bool strict_fm = std::all_of(theta.begin(), theta.end(), [&](double x) { return x == theta[0]; });
    model_.set_lane_parameters(l, member.A, member.g, strict_fm);
    slips_.start_lane(l);
    lanes_[l].occupied = true;
    lanes_[l].member = member;
    lanes_[l].history.clear();
    ++occupied_;
  }

  void step() {
    if (scene_.slips) {
      for (std::size_t j = 0; j < scene_.rows; ++j) theta_before_[j] = state_.theta[j];
      t_before_ = state_.t;
    }
    const auto accepted = integrator_.attempt(model_, state_);
    busy_ += double(occupied_);
    total_ += double(width);
    if constexpr (Q.alignment)
      extrema_.accumulate(accepted, model_.alignment(work_, state_.theta.data(), state_.t));
    if (scene_.slips)
      slips_.accumulate(accepted, scene_.rows, theta_before_.data(), state_.theta.data(),
                        state_.t - t_before_);
  }

  template <class Retire>
  void close_period(std::size_t l, Retire& retire) {
    constexpr double period = kernels::drive_period;
    PeriodRecord record;
    if constexpr (Q.drive) record.dissipation = kernels::lane_get(state_.quad[Q.drive_index()], l);
    if constexpr (Q.work) record.work = kernels::lane_get(state_.quad[Q.work_index()], l);
    if constexpr (Q.stokes) record.stokes = kernels::lane_get(state_.quad[Q.stokes_index()], l);
    if constexpr (Q.alignment) {
      record.alignment_mean = kernels::lane_get(state_.quad[Q.alignment_index()], l) / period;
      extrema_.end_period(l, record);
    }
    if constexpr (Q.energy) record.energy_mean = kernels::lane_get(state_.quad[Q.energy_index()], l) / period;
    if (scene_.slips) slips_.end_period(l, record);
    for (auto& q : state_.quad) kernels::lane_set(q, l, 0.0);

    auto& history = lanes_[l].history;
    history.push_back(record);
    const int periods = int(history.size());
    const bool long_enough = periods >= scene_.relax_periods + scene_.average_periods;
    bool settled = long_enough;
    if (scene_.steady_tol > 0) settled = long_enough && periods_agree(history, scene_.steady_tol);
    if (settled || (scene_.steady_tol > 0 && periods >= scene_.max_periods)) {
      retire(finish(l, settled));
      return;
    }
    if (scene_.wrap_angles)
      restart_period_wrapped(l);
    else
      kernels::lane_set(state_.t_stop, l, kernels::lane_get(state_.t, l) + period);
  }

  // numerics.wrap_angles: the next period starts at t = 0 with every θ_j in [0, 2π) (the model
  // is 2π-periodic in t and in each θ_j), so long runs keep full precision in sincos.
  void restart_period_wrapped(std::size_t l) {
    constexpr double turn = kernels::drive_period;
    kernels::lane_set(state_.t, l, 0.0);
    kernels::lane_set(state_.t_stop, l, turn);
    for (auto& row : state_.theta) {
      const double theta = kernels::lane_get(row, l);
      kernels::lane_set(row, l, theta - turn * std::floor(theta / turn));
    }
  }

  MemberResult finish(std::size_t l, bool settled) {
    Lane& lane = lanes_[l];
    MemberResult result;
    result.index = lane.member.index;
    result.status = state_.status[l];
    result.settled = settled;
    result.periods_run = int(lane.history.size());
    result.steps_accepted = kernels::lane_get(state_.steps_accepted, l);
    result.steps_rejected = kernels::lane_get(state_.steps_rejected, l);
    result.theta_final.resize(scene_.rows);
    constexpr double turn = 2.0 * std::numbers::pi;
    for (std::size_t j = 0; j < scene_.rows; ++j) {
      const double theta = kernels::lane_get(state_.theta[j], l);
      result.theta_final[j] = theta - turn * std::floor(theta / turn);
    }
    const bool ok = result.status == kernels::LaneStatus::ok;
    summarize(ok ? lane.history : std::vector<PeriodRecord>{}, scene_.average_periods,
              scene_.classifies_regimes(), result);
    if (scene_.period_series) result.periods = std::move(lane.history);
    lane.occupied = false;
    lane.history.clear();
    state_.status[l] = kernels::LaneStatus::idle;
    --occupied_;
    return result;
  }

  const Scene& scene_;
  Model model_;
  kernels::AdaptiveIntegrator<Model, Stepper> integrator_;
  kernels::LaneState<V> state_;
  typename Model::Workspace work_;
  kernels::lane_vector<V> theta_before_;
  V t_before_ = V(0.0);
  AlignmentExtrema<V> extrema_;
  SlipCounter<V> slips_;
  std::vector<Lane> lanes_;
  std::size_t occupied_ = 0;
  bool plan_exhausted_ = false;
  double busy_ = 0, total_ = 0;
};

}  // namespace rotorsweep::ensemble
