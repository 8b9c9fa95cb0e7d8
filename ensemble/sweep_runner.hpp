// The compile-time side of run_sweep: picks the quadratures (Integrals) and lane type a scene
// needs, and runs lane blocks of that instantiation on OpenMP threads.
#pragma once

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>

#include "ensemble/lane_block.hpp"
#include "ensemble/sweep.hpp"
#include "kernels/row_model.hpp"
#include "kernels/stepper_choice.hpp"

namespace rotorsweep::ensemble {

template <class Model, class Stepper>
SweepOutcome run_lane_blocks(const Scene& scene, const std::vector<Member>& members, int threads,
                             const ProgressCallback& progress) {
  SweepOutcome outcome;
  outcome.results.resize(members.size());
  auto& stats = outcome.statistics;
  stats.threads = threads;
  stats.lane_width = kernels::lane_width<typename Model::lane_type>;
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex progress_lock, statistics_lock;
  const auto start = std::chrono::steady_clock::now();

#pragma omp parallel num_threads(threads)
  {
    LaneBlock<Model, Stepper> block(scene);
    const auto next_member = [&]() -> std::optional<Member> {
      const std::size_t i = next.fetch_add(1, std::memory_order_relaxed);
      if (i >= members.size()) return std::nullopt;
      return members[i];
    };
    const auto retire = [&](MemberResult&& result) {
      // members are in plan order (sorted by index): find the result's position
      const auto at = std::lower_bound(members.begin(), members.end(), result.index,
                                       [](const Member& m, std::size_t index) { return m.index < index; });
      outcome.results[std::size_t(at - members.begin())] = std::move(result);
      const std::size_t finished = done.fetch_add(1, std::memory_order_relaxed) + 1;
      if (progress && progress_lock.try_lock()) {
        progress(finished);
        progress_lock.unlock();
      }
    };
    block.run(next_member, retire);
    const std::lock_guard guard(statistics_lock);
    stats.lane_steps_busy += block.lane_steps_busy();
    stats.lane_steps_total += block.lane_steps_total();
  }
  stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

/// Calls f.template operator()<b>() with the run-time flag b as a compile-time constant.
template <class F>
decltype(auto) with_flag(bool b, F&& f) {
  return b ? f.template operator()<true>() : f.template operator()<false>();
}

/// run_lane_blocks for the stepper `kind`, the scene's lane type and its quadratures.
template <kernels::StepperKind kind>
SweepOutcome run_sweep_with(const Scene& scene, const std::vector<Member>& members, int threads,
                            const ProgressCallback& progress) {
  return with_flag(scene.lanes == LaneKind::simd, [&]<bool simd>() {
    using V = std::conditional_t<simd, kernels::simd_lane, double>;
    return with_flag(scene.dissipation, [&]<bool drive>() {
      return with_flag(scene.estimators, [&]<bool estimators>() {
        return with_flag(scene.alignment, [&]<bool alignment>() {
          return with_flag(scene.energy, [&]<bool energy>() {
            constexpr kernels::Integrals Q{drive, estimators, estimators, alignment, energy};
            using Model = kernels::NearestNeighbourRows<V, Q>;
            using Stepper = typename kernels::stepper_of<kind, Model>::type;
            return run_lane_blocks<Model, Stepper>(scene, members, threads, progress);
          });
        });
      });
    });
  });
}

}  // namespace rotorsweep::ensemble
