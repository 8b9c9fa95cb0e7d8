// Test support: caller-owned storage for kernel objects (kernels never allocate), one fresh
// chunk per object, kept until the test program ends.
#pragma once

#include <cstddef>
#include <deque>
#include <utility>

#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/lane_state.hpp"

namespace rotorsweep::testing {

/// An arena over a fresh chunk of `size` lane values.
template <class V>
kernels::LaneArena<V> scratch(std::size_t size) {
  static std::deque<kernels::lane_vector<V>> chunks;
  chunks.emplace_back(size);
  return {chunks.back().data(), size};
}

/// A kernel object T(args..., arena) over a fresh chunk of exactly what its constructor takes,
/// counted over an arena without storage (steppers, integrators, lane states).
template <class T, class V, class... Args>
T built(const Args&... args) {
  auto arena = scratch<V>(
      kernels::counted_storage<V>([&](kernels::LaneArena<V>& counter) { const T t(args..., counter); }));
  return T(args..., arena);
}

/// A model over a fresh chunk of its own storage; `args` follow the row count (A and g, or Parameters).
template <class Model, class... Args>
Model model(std::size_t n, Args&&... args) {
  auto arena = scratch<typename Model::lane_type>(Model::storage_size(n));
  return Model(n, arena, std::forward<Args>(args)...);
}

template <class Model>
typename Model::Workspace workspace(const Model& model) {
  auto arena = scratch<typename Model::lane_type>(Model::Workspace::storage_size(model.dimension()));
  return typename Model::Workspace(model.dimension(), arena);
}

template <class Jacobian>
Jacobian jacobian(std::size_t n) {
  auto arena = scratch<typename Jacobian::lane_type>(Jacobian::storage_size(n));
  return Jacobian(n, arena);
}

/// An adaptive integrator of `model` with `method` (its stepper's tableau).
template <class Integrator, class Model>
Integrator integrator(const Model& model, const typename Integrator::Method& method, kernels::Tolerances tolerances,
                      kernels::StepLimits limits = {}) {
  return built<Integrator, typename Model::lane_type>(model, method, tolerances, limits);
}

template <class V>
kernels::LaneState<V> lane_state(std::size_t dimension, std::size_t quadratures) {
  return built<kernels::LaneState<V>, V>(dimension, quadratures);
}

}  // namespace rotorsweep::testing
