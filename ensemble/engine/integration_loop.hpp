// The integration loop of one block of lanes (docs/architecture.md "Layers"): caller-owned storage,
// a model, its integrator (adaptive, or the Langevin stepper) and the lane state; steps every lane
// in lockstep and gives its observers their hooks without knowing what they compute.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/model_concept.hpp"
#include "kernels/steppers/lane_state.hpp"

namespace rotorsweep::ensemble {

/// Advances lane_width<V> members of `Model` with `Integrator` (kernels::AdaptiveIntegrator or
/// kernels::LeimkuhlerMatthews). Each lane owns its time, step size, stopping time (the end of its
/// current period) and status.
template <kernels::LaneModel Model, class Integrator>
class IntegrationLoop {
 public:
  using model_type = Model;
  using V = typename Model::lane_type;
  using Parameters = typename Model::Parameters;
  static constexpr std::size_t width = kernels::lane_width<V>;
  /// Quadrature slots of the state: the most the model can carry (it carries quadrature_count()).
  static constexpr std::size_t quadrature_slots = Model::max_quadratures;
  static constexpr double period = Model::period;
  /// Whether the integrator draws noise (then every member also gets a noise stream).
  static constexpr bool stochastic = Integrator::stochastic;
  using Settings = typename Integrator::Settings;

  /// `model_arguments` follow the dimension and the arena into the model's constructor (the row
  /// models' carried quadratures).
  template <class... ModelArguments>
  IntegrationLoop(std::size_t dimension, const Settings& settings, const ModelArguments&... model_arguments)
      : storage_(storage_size(dimension, settings, model_arguments...)),
        arena_(storage_.data(), storage_.size()),
        model_(dimension, arena_, model_arguments...),
        integrator_(model_, settings, arena_),
        state_(dimension, quadrature_slots, arena_),
        work_(dimension, arena_) {
    for (auto& s : state_.status) s = kernels::LaneStatus::idle;
  }

  /// The lane values the loop's model, integrator, state and workspace take, counted by building
  /// them over an arena without storage.
  template <class... ModelArguments>
  static std::size_t storage_size(std::size_t dimension, const Settings& settings,
                                  const ModelArguments&... model_arguments) {
    return kernels::counted_storage<V>([&](kernels::LaneArena<V>& arena) {
      const Model model(dimension, arena, model_arguments...);
      const Integrator integrator(model, settings, arena);
      const kernels::LaneState<V> state(dimension, quadrature_slots, arena);
      const typename Model::Workspace work(dimension, arena);
    });
  }

  std::size_t dimension() const { return model_.dimension(); }
  const Model& model() const { return model_; }
  /// The model, for what a lane needs beyond its Parameters (the slider's gradient tables).
  Model& model() { return model_; }
  const kernels::LaneState<V>& state() const { return state_; }
  /// Scratch for observers that evaluate the model (row profiles).
  typename Model::Workspace& workspace() { return work_; }

  /// Puts a member into `lane`: parameters, y(0), t = 0, the first period ahead.
  void start(std::size_t lane, const Parameters& parameters, const std::vector<double>& y0) {
    for (std::size_t k = 0; k < dimension(); ++k) kernels::lane_set(state_.y[k], lane, y0[k]);
    for (std::size_t p = 0; p <= quadrature_slots; ++p) kernels::lane_set(state_.quad[p], lane, 0.0);
    kernels::lane_set(state_.t, lane, 0.0);
    kernels::lane_set(state_.h, lane, 0.0);
    kernels::lane_set(state_.t_stop, lane, period);
    kernels::lane_set(state_.steps_accepted, lane, 0.0);
    kernels::lane_set(state_.steps_rejected, lane, 0.0);
    kernels::lane_set(state_.tolerance_scale, lane, 1.0);
    state_.status[lane] = kernels::LaneStatus::ok;
    model_.set_lane(lane, parameters);
  }

  /// The parameters of `lane` without starting it: an idle lane still computes along, so it needs
  /// valid ones (the slider's substrate table) before any member has been in it.
  void set_parameters(std::size_t lane, const Parameters& parameters) { model_.set_lane(lane, parameters); }

  /// The lane stops next at t_stop (a problem whose stops are not the drive's periods: the slider's
  /// sample grid); its quadratures run on.
  void set_stop(std::size_t lane, double t_stop) { kernels::lane_set(state_.t_stop, lane, t_stop); }

  /// The member in `lane` integrates at tolerances rtol·scale, atol·scale (after start()).
  void set_tolerance_scale(std::size_t lane, double scale) {
    kernels::lane_set(state_.tolerance_scale, lane, scale);
  }

  /// The noise stream (its key) and damping g of the member in `lane` (stochastic integrators, after
  /// start(): the step also follows the model's curvature bound in the lane).
  void start_noise(std::size_t lane, std::uint64_t key, double g) {
    integrator_.start_lane(lane, key, g, model_.curvature_bound(lane));
  }
  /// The fixed step of the member in `lane` (stochastic integrators, after start_noise()).
  double noise_step(std::size_t lane) const { return integrator_.step_size(lane); }

  /// One step attempt of every running lane short of its period's end; `observers` see the state
  /// before (before_step) and the accepted lanes after (after_step). Returns the accepted lanes.
  template <class... Observers>
  kernels::lane_mask<V> step(Observers&... observers) {
    (observers.before_step(*this), ...);
    const auto accepted = integrator_.attempt(model_, state_);
    (observers.after_step(*this, accepted), ...);
    return accepted;
  }

  /// Whether `lane` holds a member that failed (its status is not ok).
  bool failed(std::size_t lane) const {
    return state_.status[lane] != kernels::LaneStatus::ok && state_.status[lane] != kernels::LaneStatus::idle;
  }
  /// The quadratures' integrands at the start of the last step attempt, in the lanes that stepped.
  const V* start_integrands() const { return integrator_.start_integrands(); }

  /// Whether any running lane has reached its stop (the end of its period, or set_stop's time).
  bool any_stop_reached() const { return kernels::lane_any(state_.running() & (state_.t >= state_.t_stop)); }
  bool stop_reached(std::size_t lane) const {
    return state_.status[lane] == kernels::LaneStatus::ok &&
           kernels::lane_get(state_.t, lane) >= kernels::lane_get(state_.t_stop, lane);
  }
  /// The integral of quadrature p over the lane's period so far.
  double quadrature(std::size_t lane, std::size_t p) const { return kernels::lane_get(state_.quad[p], lane); }

  /// Restarts the lane's quadratures and sets its next period. With `wrap`, the period starts
  /// again at t = 0 with every angle in [0, 2π) (the model is 2π-periodic in t and in each angle),
  /// so that long runs keep full precision.
  void next_period(std::size_t lane, bool wrap) {
    for (std::size_t p = 0; p <= quadrature_slots; ++p) kernels::lane_set(state_.quad[p], lane, 0.0);
    if (!wrap) {
      kernels::lane_set(state_.t_stop, lane, kernels::lane_get(state_.t, lane) + period);
      return;
    }
    kernels::lane_set(state_.t, lane, 0.0);
    kernels::lane_set(state_.t_stop, lane, period);
    for (std::size_t k = 0; k < dimension(); ++k)
      kernels::lane_set(state_.y[k], lane, kernels::wrap_2pi(kernels::lane_get(state_.y[k], lane)));
  }

  /// The lane's state component k, its status, and its step counts.
  double component(std::size_t lane, std::size_t k) const { return kernels::lane_get(state_.y[k], lane); }
  kernels::LaneStatus status(std::size_t lane) const { return state_.status[lane]; }
  double steps_accepted(std::size_t lane) const { return kernels::lane_get(state_.steps_accepted, lane); }
  double steps_rejected(std::size_t lane) const { return kernels::lane_get(state_.steps_rejected, lane); }

  /// Frees the lane (status idle: it no longer steps).
  void release(std::size_t lane) { state_.status[lane] = kernels::LaneStatus::idle; }

 private:
  kernels::lane_vector<V> storage_;
  kernels::LaneArena<V> arena_;
  Model model_;
  Integrator integrator_;
  kernels::LaneState<V> state_;
  typename Model::Workspace work_;
};

}  // namespace rotorsweep::ensemble
