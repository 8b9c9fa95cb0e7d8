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

template <class Integrator, class Model>
Integrator integrator(const Model& model, kernels::Tolerances tolerances, kernels::StepLimits limits = {}) {
  auto arena = scratch<typename Model::lane_type>(Integrator::storage_size(model.dimension()));
  return Integrator(model, tolerances, limits, arena);
}

template <class V>
kernels::LaneState<V> lane_state(std::size_t dimension, std::size_t quadratures) {
  auto arena = scratch<V>(kernels::LaneState<V>::storage_size(dimension, quadratures));
  return kernels::LaneState<V>(dimension, quadratures, arena);
}

}  // namespace rotorsweep::testing
