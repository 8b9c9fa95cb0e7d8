// The step reducers bound to an integration loop's hooks (docs/architecture.md "Observables"): each
// sees a lane start, every step, and a period's end, where it writes its channels.
#pragma once

#include <cstddef>

#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/step_reducers.hpp"
#include "kernels/lanes/lane.hpp"

namespace rotorsweep::ensemble {

/// Extremes of ρ̄ at the points where the period's steps start (channels alignment_min,
/// alignment_max): ρ̄ is the integrand of the ∫ρ̄ quadrature (at `index` among the model's), which
/// every attempt evaluates at its start, so the extremes cost no trigonometry of their own.
/// Switched off (a model that does not carry ∫ρ̄), it costs one branch per step.
template <class Loop>
class AlignmentObserver {
 public:
  using V = typename Loop::V;
  AlignmentObserver(bool enabled, std::size_t index) : enabled_(enabled), index_(index) {}

  void start(Loop&, std::size_t lane) {
    if (enabled_) extrema_.start_lane(lane);
  }
  void before_step(Loop& loop) {
    if (enabled_) stepping_ = loop.state().stepping();
  }
  void after_step(Loop& loop, kernels::lane_mask<V>) {
    if (enabled_) extrema_.accumulate(stepping_, loop.start_integrands()[index_]);
  }
  void end_period(std::size_t lane, PeriodRecord& record) {
    if (enabled_) extrema_.end_period(lane, record);
  }

 private:
  AlignmentExtrema<V> extrema_;
  kernels::lane_mask<V> stepping_{};
  bool enabled_;
  std::size_t index_;
};

/// Slip events (channel slips; with `energies` each slip's energy, channels slip_energies); switched
/// off, it costs one branch per step.
template <class Loop>
class SlipObserver {
 public:
  using V = typename Loop::V;
  SlipObserver(std::size_t dimension, double slip_rate, bool enabled, bool energies)
      : slips_(slip_rate, energies), theta_before_(enabled ? dimension : 0), enabled_(enabled) {}

  void start(Loop&, std::size_t lane) { slips_.start_lane(lane); }
  /// The lane's own threshold (at T > 0 it is raised above the noise, see LaneScheduler).
  void set_rate(std::size_t lane, double slip_rate) { slips_.set_rate(lane, slip_rate); }
  /// The lane's member's g, which turns its slips' speeds into energies.
  void set_damping(std::size_t lane, double g) { slips_.set_damping(lane, g); }
  void before_step(Loop& loop) {
    if (!enabled_) return;
    for (std::size_t j = 0; j < theta_before_.size(); ++j) theta_before_[j] = loop.state().y[j];
    t_before_ = loop.state().t;
  }
  void after_step(Loop& loop, kernels::lane_mask<V> accepted) {
    if (enabled_)
      slips_.accumulate(accepted, theta_before_.size(), theta_before_.data(), loop.state().y,
                        loop.state().t - t_before_);
  }
  void end_period(std::size_t lane, PeriodRecord& record) {
    if (enabled_) slips_.end_period(lane, record);
  }

 private:
  SlipCounter<V> slips_;
  kernels::lane_vector<V> theta_before_;
  V t_before_ = V(0.0);
  bool enabled_;
};

/// The swing of the dissipation integral R (at `index` among the model's quadratures; channel
/// dissipation_error) at the member's tolerances; error_rtol is rtol times the stepper's
/// swing_error_factor. Switched off (no R, or a stochastic integrator), it costs one branch per step.
template <class Loop>
class DissipationErrorObserver {
 public:
  using V = typename Loop::V;
  DissipationErrorObserver(bool enabled, std::size_t index, double error_rtol, double atol)
      : enabled_(enabled), index_(index), error_rtol_(error_rtol), atol_(atol) {}

  void start(Loop&, std::size_t lane) {
    if (enabled_) swing_.start_lane(lane);
  }
  void before_step(Loop&) {}
  void after_step(Loop& loop, kernels::lane_mask<V> accepted) {
    if (enabled_) swing_.accumulate(accepted, loop.state().quad[index_]);
  }
  void end_period(std::size_t lane, PeriodRecord& record) {
    if (enabled_) swing_.end_period(lane, error_rtol_, atol_, record);
  }

 private:
  DissipationSwing<V> swing_;
  bool enabled_;
  std::size_t index_;
  double error_rtol_, atol_;
};

}  // namespace rotorsweep::ensemble
