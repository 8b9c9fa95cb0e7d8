// run_row_chunks (docs/architecture.md "Backends"): a variant's row members in chunks on a device, two in
// flight, the shadow runs their members need (RowReruns) as chunks of their own between the plan's.
#include "ensemble/rows/row_chunks.hpp"

#include <array>
#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ensemble/engine/chunk_pipeline.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/row_reruns.hpp"

namespace rotorsweep::ensemble {

SweepOutcome run_row_chunks(const Scene& scene, const VariantRange& range, const SlotSchedule& schedule,
                            std::size_t capacity, const RunControl& control, const ResultSink& sink,
                            RowSlotDevice& device) {
  if (scene.slip_kinds) throw std::logic_error("run_row_chunks: slower reruns run on the CPU lanes");
  const auto seconds_since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  const auto start = std::chrono::steady_clock::now();
  SweepOutcome outcome;
  SweepStatistics& stats = outcome.statistics;
  stats.lane_width = 1;

  const SlotSchedule shadow_schedule = shadow_slot_schedule(scene, schedule);
  RowReruns reruns(scene, schedule.stochastic, schedule.rtol);
  std::mutex reruns_lock;                          // deliver hands results over on several threads
  std::array<std::optional<SlotChunk>, 2> chunks;  // a slot's chunk made at its first start
  std::vector<Member> members;                     // the next chunk's
  std::atomic<std::size_t> next{range.begin};
  bool plan_left = true;
  std::atomic<std::size_t> delivered = 0;

  const bool halted = run_chunks_two_in_flight(
      [&](std::size_t slot) {
        const auto fill_start = std::chrono::steady_clock::now();
        members.clear();
        bool shadows = reruns.queued() >= capacity;
        while (!shadows && plan_left && members.size() < capacity) {
          const std::size_t k = control.next(range.begin, range.end, next);
          if (k < range.end)
            members.push_back(range.source->at(k));
          else
            plan_left = false;
        }
        if (members.empty()) {
          if (reruns.queued() == 0) return false;
          shadows = true;
          while (members.size() < capacity && reruns.queued() > 0) members.push_back(*reruns.take_queued());
        }
        if (!chunks[slot]) chunks[slot].emplace(schedule, capacity);
        SlotChunk& chunk = *chunks[slot];
        chunk.set_schedule(shadows ? shadow_schedule : schedule);
        chunk.fill(scene, members);
        device.start(chunk, slot);
        stats.fill_seconds += seconds_since(fill_start);
        return true;
      },
      [&](std::size_t slot) {
        SlotChunk& chunk = *chunks[slot];
        const auto wait_start = std::chrono::steady_clock::now();
        stats.kernel_seconds += device.finish(chunk, slot);
        stats.wait_seconds += seconds_since(wait_start);
        const auto deliver_start = std::chrono::steady_clock::now();
        const double attempts =
            chunk.deliver(scene, control.thread_count(), [&](const Member& member, MemberResult&& result) {
              std::optional<MemberResult> done;
              {
                const std::lock_guard guard(reruns_lock);
                reruns.finish(
                    member, std::move(result), [&](MemberResult&& finished) { done = std::move(finished); },
                    [&](const Member& m) { return member_initial_angles(scene, m); });
              }
              if (!done) return;
              sink(std::move(*done));
              ++delivered;
            });
        stats.deliver_seconds += seconds_since(deliver_start);
        stats.lane_steps_busy += attempts;
        stats.lane_steps_total += attempts;
        if (control.progress) control.progress(delivered);
      },
      [&] { return control.stopped(); });
  stats.wall_seconds = seconds_since(start);
  outcome.interrupted = halted && delivered < range.end - range.begin;
  return outcome;
}

}  // namespace rotorsweep::ensemble
