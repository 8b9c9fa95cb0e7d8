// A slider scan through slots (docs/architecture.md "Teams"): groups of one size and speed, their
// separations' substrate tables (docs/model.md §9 "Substrate field") built once, chunks on the device,
// the members' shadow runs (ensemble/slider/slider_shadow.hpp) as chunks of their own between them.
#include "ensemble/slider/slider_slot_sweep.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>

#include "ensemble/engine/chunk_runs.hpp"
#include "ensemble/engine/rerun_queue.hpp"
#include "ensemble/slider/slider_shadow.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

namespace {

/// The tables of a group's separations (`used`; none for the others), built on `threads`: per
/// separation its table and, with forces, the four at shifted tracks (SliderModel::GradientTable), the
/// first over the speed's path and the others over the scene's, as the CPU's lanes build them (the same
/// path, their bits).
std::vector<std::optional<kernels::SubstrateTable>> group_tables(const SliderScene& scene, std::size_t speed,
                                                                 SliderSize size,
                                                                 const std::vector<bool>& used, int threads,
                                                                 const SliderTableBuilder& build_table) {
  using Model = kernels::SliderModel<double, true>;
  const SliderScene variant = slider_variant(scene, speed, 0);
  const std::size_t per = scene.forces ? 5 : 1;
  std::vector<std::optional<kernels::SubstrateTable>> tables(used.size() * per);
#pragma omp parallel for schedule(dynamic) num_threads(threads)
  for (std::size_t i = 0; i < tables.size(); ++i) {
    const std::size_t s = i / per, g = i % per;
    if (!used[s]) continue;
    const double dy = g ? Model::gradient_shifts[g - 1][0] : 0.0,
                 ddepth = g ? Model::gradient_shifts[g - 1][1] : 0.0;
    tables[i].emplace(build_table(g ? scene : variant, size, scene.separations[s], dy, ddepth));
  }
  return tables;
}

/// group_tables' views, placed, per separation.
std::vector<SliderTableViews> per_separation(const std::vector<kernels::SubstrateTableView>& placed,
                                             bool forces) {
  const std::size_t per = forces ? 5 : 1;
  std::vector<SliderTableViews> views(placed.size() / per);
  for (std::size_t s = 0; s < views.size(); ++s) {
    views[s].substrate = placed[s * per];
    for (std::size_t g = 1; g < per; ++g) views[s].gradient[g - 1] = placed[s * per + g];
  }
  return views;
}

}  // namespace

double slider_first_step_scale(const SliderScene& scene) {
  using Model = kernels::SliderModel<double, true>;
  return kernels::with_stepper<Model>(scene.stepper, [&]<class Stepper>(const auto& method) {
    return kernels::AdaptiveIntegrator<Model, Stepper>::first_step_scale({scene.rtol, scene.atol}, method);
  });
}

RunOutcome run_slider_members_in_slots(const SliderScene& scene, const std::vector<std::size_t>& plan_indices,
                                       const RunControl& control,
                                       const std::function<void(std::vector<SliderMember>&&)>& finished,
                                       SliderSlotDevice& device, const SliderTableBuilder& build_table) {
  const auto start = std::chrono::steady_clock::now();
  const double first_step_scale = slider_first_step_scale(scene);
  const SliderScene shadow_scene = slider_shadow_scene(scene);
  const double shadow_first_step_scale = slider_first_step_scale(shadow_scene);
  RunOutcome outcome;
  SweepStatistics& stats = outcome.statistics;
  stats.threads = control.thread_count();
  std::size_t done = 0;
  const auto end_run = [&](bool halted) {
    stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    outcome.interrupted = halted && done < plan_indices.size();
    return outcome;
  };
  for (std::size_t begin = 0; begin < plan_indices.size();) {
    // a group: the consecutive members of one size and speed
    const SliderMemberIndex first = slider_plan_member(scene, plan_indices[begin]).index;
    std::size_t end = begin;
    std::vector<bool> used(scene.separations.size(), false);
    for (; end < plan_indices.size(); ++end) {
      const SliderMemberIndex at = slider_plan_member(scene, plan_indices[end]).index;
      if (at.size != first.size || at.speed != first.speed) break;
      used[at.separation] = true;
    }
    if (control.stopped()) return end_run(true);

    const SliderSize size = scene.sizes[first.size];
    const auto tables = group_tables(scene, first.speed, size, used, stats.threads, build_table);
    std::vector<const kernels::SubstrateTable*> placed;
    for (const auto& t : tables) placed.push_back(t ? &*t : nullptr);
    const std::vector<SliderTableViews> views = per_separation(device.place_tables(placed), scene.forces);

    const SliderSlotSchedule schedule = slider_slot_schedule(scene, first.speed, size, first_step_scale);
    const SliderSlotSchedule shadow_schedule =
        slider_slot_schedule(shadow_scene, first.speed, size, shadow_first_step_scale);
    const std::size_t capacity =
        std::min(std::max<std::size_t>(1, device.chunk_members(schedule)), end - begin);
    std::array<std::optional<SliderSlotChunk>, 2> chunks;  // a slot's chunk made at its first start
    std::array<bool, 2> shadows{};                         // whether a slot's chunk runs shadows
    std::vector<std::size_t> claimed;                      // a chunk's plan indices
    RerunQueue<std::size_t, SliderMember> reruns;          // shadows waiting for a chunk, their members held
    const bool halted = run_group_in_chunks(
        device, {begin, end}, capacity, control, done, stats, [&] { return reruns.queued(); },
        [&](std::size_t slot, const std::vector<std::size_t>& positions) -> SliderSlotChunk& {
          claimed.clear();
          for (const std::size_t k : positions) claimed.push_back(plan_indices[k]);
          shadows[slot] = positions.empty();  // the queued shadows
          while (shadows[slot] && claimed.size() < capacity && reruns.queued() > 0)
            claimed.push_back(*reruns.take());
          if (!chunks[slot]) chunks[slot].emplace(scene, first.speed, schedule, capacity);
          chunks[slot]->set_tolerances(shadows[slot] ? shadow_schedule : schedule);
          chunks[slot]->fill(claimed, views);
          return *chunks[slot];
        },
        [&](SliderSlotChunk& chunk) {
          const bool shadow = chunks[1] && &chunk == &*chunks[1] ? shadows[1] : shadows[0];
          std::vector<SliderMember> members;
          for (std::size_t k = 0; k < chunk.count(); ++k) {
            SliderMember member = chunk.member(k);
            if (shadow) {
              members.push_back(*reruns.finish(
                  member.plan_index, [&](SliderMember& held) { take_slider_shadow(held, member); }));
            } else if (needs_slider_shadow(scene, member)) {
              const std::size_t index = member.plan_index;
              reruns.hold(index, std::move(member), {index});
            } else {
              members.push_back(std::move(member));
            }
          }
          const std::size_t count = members.size();
          if (count > 0) finished(std::move(members));
          return ChunkDelivery{count, 0.0};
        });
    if (halted) return end_run(true);
    begin = end;
  }
  return end_run(false);
}

}  // namespace rotorsweep::ensemble
