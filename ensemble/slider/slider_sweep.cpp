// The slider scan: the members of each size on lane schedulers over OpenMP threads (SliderProblem:
// sampled on their speed's sample grid, friction and dissipation from the quadratures at period
// boundaries, SI; docs/model.md §9).
#include "ensemble/slider/slider_sweep.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <tuple>

#include "ensemble/engine/lane_groups.hpp"
#include "ensemble/engine/lane_scheduler.hpp"
#include "ensemble/slider/slider_member_summary.hpp"
#include "ensemble/slider/slider_problem.hpp"
#include "ensemble/slider/slider_slot_sweep.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/models/slider/spectral_pairs.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

namespace {

using V = kernels::simd_lane;

/// One thread's lane scheduler over the members of one size (`range`: positions in `plan_indices`), on lanes
/// of V over pair sums `Pairs`, fed from `next` (run_lane_groups' hooks); a stopped substrate table's build
/// stops the thread as the others stop within a step.
template <class W, bool Inertial, class Pairs, class Hooks>
LaneSteps run_size(const SliderScene& scene, const std::vector<SliderSampleGrid>& grids, std::size_t samples,
                   const std::vector<std::size_t>& plan_indices, PositionRange range,
                   const std::function<void(std::vector<SliderMember>&&)>& finished, const Hooks& hooks) {
  const auto& [next, retired, stopped, stop_closed] = hooks;
  return kernels::with_stepper<kernels::SliderModel<W, Inertial, Pairs>>(
      scene.stepper, [&]<class Stepper>(const auto&) {
        LaneScheduler<SliderProblem<W, Inertial, Stepper, Pairs>> scheduler(
            scene, grids, slider_plan_member(scene, plan_indices[range.begin]).size,
            std::function<bool()>(stopped));
        try {
          scheduler.run(
              [&]() -> std::optional<SliderRun> {
                const auto k = next();
                if (!k) return std::nullopt;
                return SliderRun(plan_indices[*k]);
              },
              [&](SliderMember&& member) {
                pad_to_timeline(member, samples);
                std::vector<SliderMember> one;
                one.push_back(std::move(member));
#pragma omp critical(slider_finished)
                finished(std::move(one));
                retired();
              },
              stopped, stop_closed);
        } catch (const kernels::SubstrateTableStopped&) {
          // a substrate table's build was stopped: this thread stops as the others do within a step
        }
        return LaneSteps{scheduler.lane_steps_busy(), scheduler.lane_steps_total()};
      });
}

/// Runs the members of each size (`sizes`: runs of positions in `plan_indices`) on lane schedulers,
/// one per thread and size (run_lane_groups): a thread whose size has no member left goes on to the next
/// size while the others finish theirs. A size that runs matrix-free (matrix_free) takes one member per
/// thread (the double lane: its FFTs and solves are per member; a thread with no member left helps the
/// others with their convolutions, LatticeConvolution::apply), the others SIMD lanes. `grids`: each speed's
/// sample grid. Each finished member goes to `finished` (one call at a time) with its
/// series on `samples` columns.
template <bool Inertial>
RunOutcome run_sizes(const SliderScene& scene, const std::vector<SliderSampleGrid>& grids,
                     std::size_t samples, const std::vector<std::size_t>& plan_indices,
                     const std::vector<PositionRange>& sizes, const RunControl& control,
                     const std::function<void(std::vector<SliderMember>&&)>& finished) {
  return run_lane_groups(sizes, control, slider_thread_lanes(scene),
                         [&](std::size_t s, const auto& next, const auto& retired, const auto& stopped,
                             const auto& stop_closed) {
                           const auto hooks = std::tie(next, retired, stopped, stop_closed);
                           const PositionRange range = sizes[s];
                           if (matrix_free(scene, slider_plan_member(scene, plan_indices[range.begin]).size))
                             return run_size<double, Inertial, kernels::SpectralPairs<double>>(
                                 scene, grids, samples, plan_indices, range, finished, hooks);
                           return run_size<V, Inertial, kernels::DirectPairs<V>>(
                               scene, grids, samples, plan_indices, range, finished, hooks);
                         });
}

}  // namespace

RunOutcome run_slider_members(const SliderScene& scene, const std::vector<std::size_t>& plan_indices,
                              const RunControl& control,
                              const std::function<void(std::vector<SliderMember>&&)>& finished,
                              const SliderDevice* device) {
  if (scene.device == Device::gpu) {
    if (!device)
      throw std::invalid_argument("numerics.device = \"gpu\": run_slider_members was given no GPU executor");
    return device->run_members(
        scene, plan_indices, control, finished,
        [](const SliderScene& variant, SliderSize size, double separation, double dy, double ddepth) {
          return substrate_table<V>(variant, size, separation, dy, ddepth);
        });
  }
  std::vector<SliderSampleGrid> grids;
  for (std::size_t v = 0; v < scene.speeds.size(); ++v) grids.emplace_back(slider_variant(scene, v, 0));
  // the members of each size in turn (a lane scheduler's loop has one grid of rotors)
  std::vector<PositionRange> sizes;
  for (std::size_t k = 0; k < plan_indices.size(); ++k)
    if (k == 0 || slider_plan_member(scene, plan_indices[k]).index.size !=
                      slider_plan_member(scene, plan_indices[k - 1]).index.size)
      sizes.push_back({k, k + 1});
    else
      sizes.back().end = k + 1;
  const std::size_t samples = slider_timeline(scene).samples;
  return scene.overdamped ? run_sizes<false>(scene, grids, samples, plan_indices, sizes, control, finished)
                          : run_sizes<true>(scene, grids, samples, plan_indices, sizes, control, finished);
}

double slider_thread_bytes(const SliderScene& scene) {
  // the largest lane block of any size (a matrix-free one is O(n) for one member, a dense one O(n²) for a
  // lane block) and the lanes that hold tables
  double block = 0, lanes = 1;
  for (const SliderSize size : scene.sizes) {
    const bool spectral = matrix_free(scene, size);
    const auto bytes = [&]<class W, bool Inertial, class Pairs>() {
      return kernels::with_stepper<kernels::SliderModel<W, Inertial, Pairs>>(
          scene.stepper, [&]<class Stepper>(const auto& method) {
            using Loop = typename SliderProblem<W, Inertial, Stepper, Pairs>::Loop;
            const std::size_t dimension = Inertial ? 2 * size.rotors() : size.rotors();
            return double(Loop::storage_size(dimension, typename Loop::Settings{method, {}, {}},
                                             kernels::SliderGrid{size.columns, size.rows},
                                             slider_placement(scene))) *
                   double(sizeof(W));
          });
    };
    double b;
    if (spectral)
      b = scene.overdamped ? bytes.template operator()<double, false, kernels::SpectralPairs<double>>()
                           : bytes.template operator()<double, true, kernels::SpectralPairs<double>>();
    else
      b = scene.overdamped ? bytes.template operator()<V, false, kernels::DirectPairs<V>>()
                           : bytes.template operator()<V, true, kernels::DirectPairs<V>>();
    block = std::max(block, b);
    if (!spectral) lanes = double(kernels::lane_width<V>);
  }
  // the longest path is the slowest speed's; the most nodes at the closest separation
  double table = 0;
  for (const SliderSize size : scene.sizes)
    for (std::size_t v = 0; v < scene.speeds.size(); ++v)
      table = std::max(
          table, substrate_table_layout(slider_variant(scene, v, 0), size,
                                        *std::min_element(scene.separations.begin(), scene.separations.end()))
                     .bytes());
  const double tables_per_lane = scene.forces ? 5 : 1;
  return block + (lanes * tables_per_lane + 1) * table;
}

std::size_t slider_thread_lanes(const SliderScene& scene) {
  for (const SliderSize size : scene.sizes)
    if (!matrix_free(scene, size)) return kernels::lane_width<V>;
  return 1;
}

SliderResult run_slider_scan(const SliderScene& scene, const RunControl& control, const SliderDevice* device) {
  SliderResult result;
  result.timeline = slider_timeline(scene);
  result.members.resize(scene.member_count());
  std::vector<std::size_t> all(scene.member_count());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  result.outcome = run_slider_members(
      scene, all, control,
      [&](std::vector<SliderMember>&& block) {
        for (auto& m : block) result.members[m.plan_index] = std::move(m);
      },
      device);
  return result;
}

}  // namespace rotorsweep::ensemble
