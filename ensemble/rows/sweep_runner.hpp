// The compile-time side of run_members: picks the lane type and the row model a scene needs, and
// runs lane schedulers of that instantiation on OpenMP threads.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>

#include "ensemble/engine/compile_time_choice.hpp"
#include "ensemble/engine/lane_scheduler.hpp"
#include "ensemble/engine/stopping_threads.hpp"
#include "ensemble/rows/row_problem.hpp"
#include "ensemble/rows/row_setup.hpp"
#include "ensemble/rows/sweep.hpp"
#include "kernels/models/rows/coupled_rows.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

/// Runs the members of `range` (one variant) on `threads` lane schedulers that share one counter
/// (run_on_threads: an exception in one of them, an allocation that fails, stops the others).
template <class Model, class Integrator, class Setup>
SweepOutcome run_lane_schedulers(const Scene& scene, const VariantRange& range, const Setup& setup,
                                 int threads, const SweepControl& control, const ResultSink& sink) {
  SweepOutcome outcome;
  auto& stats = outcome.statistics;
  stats.threads = threads;
  stats.lane_width = kernels::lane_width<typename Model::lane_type>;
  std::atomic<std::size_t> next{range.begin}, done{0};
  std::mutex progress_lock, statistics_lock;
  const auto start = std::chrono::steady_clock::now();
  const Member variant = range.source->at(range.begin);

  run_on_threads(
      threads, [&] { return control.stopped(); },
      [&](const auto& stopped) {
        LaneScheduler<RowProblem<Model, Integrator, Setup>> scheduler(scene, variant, setup);
        const auto next_member = [&]() -> std::optional<Member> {
          if (stopped()) return std::nullopt;
          const std::size_t k =
              range.source->claim ? range.source->claim(range) : next.fetch_add(1, std::memory_order_relaxed);
          if (k >= range.end) return std::nullopt;
          return range.source->at(k);
        };
        const auto retire = [&](MemberResult&& result) {
          sink(std::move(result));
          const std::size_t finished = done.fetch_add(1, std::memory_order_relaxed) + 1;
          if (control.progress && progress_lock.try_lock()) {
            control.progress(finished);
            progress_lock.unlock();
          }
        };
        const auto period_closed = [&] {  // progress within long members
          if (!control.periods) return;
          control.periods->fetch_add(1, std::memory_order_relaxed);
          if (control.progress && progress_lock.try_lock()) {
            control.progress(done.load(std::memory_order_relaxed));
            progress_lock.unlock();
          }
        };
        scheduler.run(next_member, retire, stopped, period_closed);
        const std::lock_guard guard(statistics_lock);
        stats.lane_steps_busy += scheduler.lane_steps_busy();
        stats.lane_steps_total += scheduler.lane_steps_total();
      });
  stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.interrupted = control.stopped();
  return outcome;
}

/// Calls f.template operator()<Model>() with the row model in the scene's lane type:
/// NearestNeighbourRows for today's model, CoupledRows for a coupling table or open rows. The
/// quadratures its observables need are chosen at run time (RowSetup::model_arguments).
template <class F>
decltype(auto) with_row_model(const Scene& scene, F&& f) {
  return with_flag(scene.lanes == LaneKind::simd, [&]<bool simd>() {
    using V = std::conditional_t<simd, kernels::simd_lane, double>;
    return with_flag(!scene.couplings.nearest_neighbour(), [&]<bool coupled>() {
      using Model = std::conditional_t<coupled, kernels::CoupledRows<V>, kernels::NearestNeighbourRows<V>>;
      return f.template operator()<Model>();
    });
  });
}

/// One variant's members on the row model with the scene's stepper, of family `family` (its tableau
/// is data: RowProblem's integrator settings).
template <kernels::StepperFamily family>
SweepOutcome run_row_sweep(const Scene& scene, const VariantRange& range, int threads,
                           const SweepControl& control, const ResultSink& sink) {
  return with_row_model(scene, [&]<class Model>() {
    using Stepper = kernels::family_stepper<family, Model>;
    return run_lane_schedulers<Model, kernels::AdaptiveIntegrator<Model, Stepper>>(
        scene, range, RowSetup<Model>(&scene), threads, control, sink);
  });
}

}  // namespace rotorsweep::ensemble
