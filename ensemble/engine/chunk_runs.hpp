// A problem's members in chunks on a device (docs/architecture.md "The run API"): a group's positions
// claimed through the run's control, queued reruns as chunks of their own, two chunks in flight (one
// executor for rows and slider), and where the host's time went.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <vector>

#include "ensemble/engine/chunk_pipeline.hpp"
#include "ensemble/engine/run_control.hpp"
#include "ensemble/engine/slot_device.hpp"

namespace rotorsweep::ensemble {

/// What a chunk's delivery handed over: members that reached the sink (a member held for its reruns
/// reaches it with its last) and the step attempts of the chunk's members.
struct ChunkDelivery {
  std::size_t members = 0;
  double attempts = 0;
};

/// Runs the positions of `group` in chunks of up to `capacity` on `device`, two in flight
/// (run_chunks_two_in_flight: while the device runs one chunk the host fills the next and delivers the
/// one before). A chunk holds positions claimed through control.next or, once the problem's queued reruns
/// (`queued()`) fill a chunk or the group has run out, queued reruns: fill(slot, positions) → Chunk& makes
/// the slot's chunk (reruns where `positions` is empty), deliver(chunk) → ChunkDelivery hands its members
/// over. `delivered` counts the run's members delivered (progress after each chunk); the device's seconds
/// and the host's fill, wait and delivery go into `stats`. No chunk starts once the control's stop holds;
/// returns whether it ended the group.
template <class Chunk, class Queued, class Fill, class Deliver>
bool run_group_in_chunks(SlotDevice<Chunk>& device, PositionRange group, std::size_t capacity,
                         const RunControl& control, std::size_t& delivered, SweepStatistics& stats,
                         Queued&& queued, Fill&& fill, Deliver&& deliver) {
  const auto seconds_since = [](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  };
  std::atomic<std::size_t> next{group.begin};
  bool group_left = true;
  std::vector<std::size_t> positions;  // the next chunk's
  std::array<Chunk*, 2> chunks{};
  return run_chunks_two_in_flight(
      [&](std::size_t slot) {
        const auto fill_start = std::chrono::steady_clock::now();
        positions.clear();
        const bool reruns = queued() >= capacity;
        while (!reruns && group_left && positions.size() < capacity) {
          const std::size_t k = control.next(group.begin, group.end, next);
          if (k < group.end)
            positions.push_back(k);
          else
            group_left = false;
        }
        if (positions.empty() && queued() == 0) return false;
        chunks[slot] = &fill(slot, positions);
        device.start(*chunks[slot], slot);
        stats.fill_seconds += seconds_since(fill_start);
        return true;
      },
      [&](std::size_t slot) {
        const auto wait_start = std::chrono::steady_clock::now();
        stats.kernel_seconds += device.finish(*chunks[slot], slot);
        stats.wait_seconds += seconds_since(wait_start);
        const auto deliver_start = std::chrono::steady_clock::now();
        const ChunkDelivery delivery = deliver(*chunks[slot]);
        stats.deliver_seconds += seconds_since(deliver_start);
        stats.lane_steps_busy += delivery.attempts;
        stats.lane_steps_total += delivery.attempts;
        delivered += delivery.members;
        if (control.progress) control.progress(delivered);
      },
      [&] { return control.stopped(); });
}

}  // namespace rotorsweep::ensemble
