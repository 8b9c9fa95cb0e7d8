// The slider scan: the members of each size on lane schedulers over OpenMP threads (SliderProblem:
// sampled on their speed's sample grid, friction and dissipation from the quadratures at period
// boundaries, SI; docs/model.md §9).
#include "ensemble/slider/slider_sweep.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <optional>

#include "ensemble/engine/lane_scheduler.hpp"
#include "ensemble/engine/stopping_threads.hpp"
#include "ensemble/gpu/gpu_slider.hpp"
#include "ensemble/slider/slider_member_summary.hpp"
#include "ensemble/slider/slider_problem.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

namespace {

using V = kernels::simd_lane;

/// Runs the members of each size (`sizes`: runs [begin, end) of `plan_indices`) on lane schedulers,
/// one per thread and size, with one claim per size (control.claim, else a counter): a thread whose
/// size has no member left goes on to the next size while the others finish theirs. `grids`: each
/// speed's sample grid. Each finished member goes to `finished` (one call at a time) with its series on
/// `samples` columns. Returns whether a stop left any out; an exception in a worker (std::bad_alloc)
/// stops the others and is rethrown here.
template <bool Inertial>
bool run_sizes(const SliderScene& scene, const std::vector<SliderSampleGrid>& grids, std::size_t samples,
               const std::vector<std::size_t>& plan_indices,
               const std::vector<std::pair<std::size_t, std::size_t>>& sizes,
               const SliderScanControl& control,
               const std::function<void(std::vector<SliderMember>&&)>& finished) {
  const int threads = control.threads > 0 ? control.threads : omp_get_max_threads();
  std::vector<std::atomic<std::size_t>> next(sizes.size());
  for (std::size_t s = 0; s < sizes.size(); ++s) next[s] = sizes[s].first;
  std::size_t done = 0, members = 0;
  for (const auto& [begin, end] : sizes) members += end - begin;
  std::atomic<bool> stop_asked{false};
  const auto asked = [&] {  // once asked, for good
    if (!stop_asked && control.stopped && control.stopped()) stop_asked = true;
    return stop_asked.load();
  };
  kernels::with_stepper<kernels::SliderModel<V, Inertial>>(scene.stepper, [&]<class Stepper>(const auto&) {
    run_on_threads(threads, asked, [&](const auto& stop) {
      try {
        for (std::size_t s = 0; s < sizes.size() && !stop(); ++s) {
          const auto [begin, end] = sizes[s];
          LaneScheduler<SliderProblem<V, Inertial, Stepper>> scheduler(
              scene, grids, slider_plan_member(scene, plan_indices[begin]).size, std::function<bool()>(stop));
          scheduler.run(
              [&]() -> std::optional<std::size_t> {
                if (stop()) return std::nullopt;
                const std::size_t k = control.claim ? control.claim(begin, end)
                                                    : next[s].fetch_add(1, std::memory_order_relaxed);
                if (k >= end) return std::nullopt;
                return plan_indices[k];
              },
              [&](SliderMember&& member) {
                pad_to_timeline(member, samples);
                std::vector<SliderMember> one;
                one.push_back(std::move(member));
#pragma omp critical(slider_finished)
                {
                  finished(std::move(one));
                  ++done;
                  if (control.progress) control.progress(done);
                }
              },
              stop);
        }
      } catch (const kernels::SubstrateTableStopped&) {
        // a substrate table's build was stopped: this thread stops as the others do within a step
      }
    });
  });
  return stop_asked && done < members;
}

}  // namespace

bool run_slider_members(const SliderScene& scene, const std::vector<std::size_t>& plan_indices,
                        const SliderScanControl& control,
                        const std::function<void(std::vector<SliderMember>&&)>& finished) {
  if (scene.device == Device::gpu)
    return run_gpu_slider_members(
        scene, plan_indices, control, finished,
        [](const SliderScene& variant, SliderSize size, double separation, double dy, double ddepth) {
          return substrate_table<V>(variant, size, separation, dy, ddepth);
        });
  std::vector<SliderSampleGrid> grids;
  for (std::size_t v = 0; v < scene.speeds.size(); ++v) grids.emplace_back(slider_variant(scene, v, 0));
  // the members of each size in turn (a lane scheduler's loop has one grid of rotors)
  std::vector<std::pair<std::size_t, std::size_t>> sizes;
  for (std::size_t k = 0; k < plan_indices.size(); ++k)
    if (k == 0 || slider_plan_member(scene, plan_indices[k]).index.size !=
                      slider_plan_member(scene, plan_indices[k - 1]).index.size)
      sizes.emplace_back(k, k + 1);
    else
      sizes.back().second = k + 1;
  if (sizes.empty()) return false;
  const std::size_t samples = slider_timeline(scene).samples;
  return scene.overdamped ? run_sizes<false>(scene, grids, samples, plan_indices, sizes, control, finished)
                          : run_sizes<true>(scene, grids, samples, plan_indices, sizes, control, finished);
}

double slider_thread_bytes(const SliderScene& scene) {
  const SliderSize largest =
      *std::max_element(scene.sizes.begin(), scene.sizes.end(),
                        [](SliderSize a, SliderSize b) { return a.rotors() < b.rotors(); });
  const auto block = [&]<bool Inertial>() {
    return kernels::with_stepper<kernels::SliderModel<V, Inertial>>(scene.stepper, [&]<class Stepper>(
                                                                                const auto& method) {
      using Loop = typename SliderProblem<V, Inertial, Stepper>::Loop;
      const std::size_t dimension = Inertial ? 2 * largest.rotors() : largest.rotors();
      return double(Loop::storage_size(dimension, typename Loop::Settings{method, {}, {}},
                                       kernels::SliderGrid{largest.columns, largest.rows},
                                       slider_placement(scene))) *
             double(sizeof(V));
    });
  };
  // the longest path is the slowest speed's; the most nodes at the closest separation
  double table = 0;
  for (std::size_t v = 0; v < scene.speeds.size(); ++v)
    table = std::max(
        table, substrate_table_layout(slider_variant(scene, v, 0), largest,
                                      *std::min_element(scene.separations.begin(), scene.separations.end()))
                   .bytes());
  const double tables_per_lane = scene.forces ? 5 : 1;
  return (scene.overdamped ? block.template operator()<false>() : block.template operator()<true>()) +
         (double(kernels::lane_width<V>) * tables_per_lane + 1) * table;
}

SliderResult run_slider_scan(const SliderScene& scene, const SliderScanControl& control) {
  SliderResult result;
  result.timeline = slider_timeline(scene);
  result.members.resize(scene.member_count());
  std::vector<std::size_t> all(scene.member_count());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  result.stopped = run_slider_members(scene, all, control, [&](std::vector<SliderMember>&& block) {
    for (auto& m : block) result.members[m.plan_index] = std::move(m);
  });
  return result;
}

}  // namespace rotorsweep::ensemble
