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

#include "ensemble/engine/chunk_runs.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/row_reruns.hpp"

namespace rotorsweep::ensemble {

SweepOutcome run_row_chunks(const Scene& scene, const VariantRange& range, const SlotSchedule& schedule,
                            std::size_t capacity, const RunControl& control, const ResultSink& sink,
                            RowSlotDevice& device) {
  if (scene.slip_kinds) throw std::logic_error("run_row_chunks: slower reruns run on the CPU lanes");
  const auto start = std::chrono::steady_clock::now();
  SweepOutcome outcome;
  outcome.statistics.lane_width = 1;
  const SlotSchedule shadow_schedule = shadow_slot_schedule(scene, schedule);
  RowReruns reruns(scene, schedule.stochastic, schedule.rtol);
  std::mutex reruns_lock;                          // deliver hands results over on several threads
  std::array<std::optional<SlotChunk>, 2> chunks;  // a slot's chunk made at its first start
  std::vector<Member> members;                     // the next chunk's
  std::size_t delivered = 0;

  const bool halted = run_group_in_chunks(
      device, {range.begin, range.end}, capacity, control, delivered, outcome.statistics,
      [&] { return reruns.queued(); },
      [&](std::size_t slot, const std::vector<std::size_t>& positions) -> SlotChunk& {
        members.clear();
        for (const std::size_t k : positions) members.push_back(range.source->at(k));
        if (members.empty())  // the queued shadows
          while (members.size() < capacity && reruns.queued() > 0) members.push_back(*reruns.take_queued());
        if (!chunks[slot]) chunks[slot].emplace(shadow_schedule, capacity);  // its disorder arrays hold both
        SlotChunk& chunk = *chunks[slot];
        chunk.set_schedule(positions.empty() ? shadow_schedule : schedule);
        chunk.fill(scene, members);
        return chunk;
      },
      [&](SlotChunk& chunk) {
        std::atomic<std::size_t> sunk = 0;
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
              ++sunk;
            });
        return ChunkDelivery{sunk.load(), attempts};
      });
  outcome.statistics.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.interrupted = halted && delivered < range.end - range.begin;
  return outcome;
}

}  // namespace rotorsweep::ensemble
