// The row profile observer of a lane block (docs/model.md §3 "Row profiles"): RowProfileIntegral
// (R_j = A_j ∫ sin(θ_j − t) dt per row, ∫ cos²((θ_j − θ_{j+1})/2) dt per link) on the loop's hooks.
#pragma once

#include <cstddef>
#include <vector>

#include "ensemble/rows/row_profile_integral.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/model_concept.hpp"

namespace rotorsweep::ensemble {

/// Owns the storage of a RowProfileIntegral over the loop's lanes. Switched off (or for a model
/// without row profiles) it costs one branch per step.
template <class Loop>
class RowProfileObserver {
 public:
  using V = typename Loop::V;
  using Model = typename Loop::model_type;
  static constexpr bool reports = kernels::ReportsRowProfile<Model>;
  using Integral = RowProfileIntegral<Model, Loop::stochastic>;

  RowProfileObserver(std::size_t dimension, bool enabled)
      : n_(dimension),
        enabled_(enabled && reports),
        storage_(kernels::counted_storage<V>(
            [&](kernels::LaneArena<V>& arena) { const Integral counted(enabled_ ? dimension : 0, arena); })),
        integral_(over(storage_, enabled_ ? dimension : 0)) {}

  bool enabled() const { return enabled_; }
  std::size_t links() const { return integral_.links(); }

  void start(Loop& loop, std::size_t lane) {
    if constexpr (reports)
      if (enabled_) integral_.start(loop.model(), loop.workspace(), loop.state(), lane);
  }
  void before_step(Loop& loop) {
    if constexpr (reports)
      if (enabled_) integral_.before_step(loop.model(), loop.workspace(), loop.state());
  }
  void after_step(Loop& loop, kernels::lane_mask<V> accepted) {
    if constexpr (reports)
      if (enabled_) integral_.after_step(loop.model(), loop.workspace(), loop.state(), accepted);
  }

  /// The lane's period just ended: its R_j (rows) then its link integrals (links), and a fresh start.
  std::vector<double> take_period(std::size_t lane) {
    std::vector<double> values(n_ + integral_.links());
    integral_.take_period(lane, values.data());
    return values;
  }

 private:
  /// The integral's views over `storage` (sized by counted_storage above).
  static Integral over(kernels::lane_vector<V>& storage, std::size_t rows) {
    kernels::LaneArena<V> arena(storage.data(), storage.size());
    return Integral(rows, arena);
  }

  std::size_t n_;
  bool enabled_;
  kernels::lane_vector<V> storage_;
  Integral integral_;
};

}  // namespace rotorsweep::ensemble
