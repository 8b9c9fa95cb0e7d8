// A variant's row members through chunks of member slots on a device (docs/architecture.md "Backends"):
// two chunks in flight, and the reruns their members need run as chunks of their own between the plan's.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <concepts>
#include <cstddef>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ensemble/engine/chunk_pipeline.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/row_reruns.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/sweep.hpp"

namespace rotorsweep::ensemble {

/// What runs chunks of row slots (the GPU's kernels, ensemble/gpu/gpu_runner.cuh; the host in tests):
/// start(chunk, slot) starts every member of `chunk` in `slot` (0 or 1) with chunk.schedule() and may
/// return before they have finished; finish(chunk, slot) waits for them, leaves their outputs in the
/// chunk's buffers and returns the seconds the device ran them.
template <class Device>
concept RowSlotDevice = requires(Device device, SlotChunk& chunk, std::size_t slot) {
  device.start(chunk, slot);
  { device.finish(chunk, slot) } -> std::convertible_to<double>;
};

/// The members of `range` with `schedule` in chunks of up to `capacity` on `device`, two in flight
/// (run_chunks_two_in_flight): while the device runs one chunk the host fills the next and delivers
/// the one before (summaries on `host_threads`). Members are taken in plan order, or one by one through
/// the source's claim where it has one (the ranks of mpirun, each with its device). A member that needs a
/// shadow run is held (RowReruns) and its shadow queued; the queued shadows run as a chunk of their own
/// (shadow_slot_schedule) once they fill one or the plan has run out, and each completes its primary, which
/// then goes to `sink`. Progress counts the members handed to `sink`; no chunk starts once control.stop is
/// raised (held primaries are then left out). Statistics: the device's seconds, the host's fill, wait and
/// delivery.
template <RowSlotDevice Device>
SweepOutcome run_row_chunks(const Scene& scene, const VariantRange& range, const SlotSchedule& schedule,
                            std::size_t capacity, int host_threads, const SweepControl& control,
                            const ResultSink& sink, Device& device) {
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
  std::size_t next = range.begin;
  bool plan_left = true;
  std::atomic<std::size_t> delivered = 0;

  run_chunks_two_in_flight(
      [&](std::size_t slot) {
        const auto fill_start = std::chrono::steady_clock::now();
        members.clear();
        bool shadows = reruns.queued() >= capacity;
        while (!shadows && plan_left && members.size() < capacity) {
          const std::size_t k = range.source->claim ? range.source->claim(range) : next++;
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
            chunk.deliver(scene, host_threads, [&](const Member& member, MemberResult&& result) {
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
  outcome.interrupted = control.stopped();
  return outcome;
}

}  // namespace rotorsweep::ensemble
