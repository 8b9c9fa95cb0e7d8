// run_group_in_chunks, the device executor of every problem (ensemble/engine/chunk_runs.hpp): a group's
// positions each in one chunk, claimed through the control where it has a claim, queued reruns as
// chunks of their own once they fill one or the group ran out, progress and the device's seconds counted,
// and no chunk started once stopped.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cstddef>
#include <vector>

#include "ensemble/engine/chunk_runs.hpp"

using namespace rotorsweep::ensemble;

namespace {

/// A chunk: the positions it holds, or (reruns) how many queued reruns.
struct Chunk {
  std::vector<std::size_t> positions;
  std::size_t reruns = 0;
};

/// Runs nothing: records the chunks started and says each ran for a quarter of a second.
struct RecordingDevice final : SlotDevice<Chunk> {
  std::vector<Chunk> started;
  void start(Chunk& chunk, std::size_t) override { started.push_back(chunk); }
  double finish(Chunk&, std::size_t) override { return 0.25; }
};

/// Positions [2, 12) in chunks of 3; each even position delivered queues a rerun, which completes it
/// (it reaches the sink with its rerun). Returns the device's record; `delivered`, `last` and the
/// statistics as the executor left them.
struct Run {
  RecordingDevice device;
  std::vector<int> sunk = std::vector<int>(12, 0);
  std::size_t delivered = 0, last = 0;
  SweepStatistics stats;
  bool halted = false;
};
Run run(const RunControl& control) {
  Run r;
  std::size_t queued = 0;
  std::vector<std::size_t> held;  // even positions waiting for their reruns
  std::array<Chunk, 2> chunks;
  RunControl counted = control;
  counted.progress = [&](std::size_t done) { r.last = done; };
  r.halted = run_group_in_chunks(
      r.device, {2, 12}, 3, counted, r.delivered, r.stats, [&] { return queued; },
      [&](std::size_t slot, const std::vector<std::size_t>& positions) -> Chunk& {
        chunks[slot] = {positions, positions.empty() ? std::min<std::size_t>(queued, 3) : 0};
        queued -= chunks[slot].reruns;
        return chunks[slot];
      },
      [&](Chunk& chunk) {
        ChunkDelivery d{0, double(chunk.positions.size() + chunk.reruns)};
        for (const std::size_t k : chunk.positions)
          if (k % 2 == 0) {
            held.push_back(k);
            ++queued;
          } else {
            ++r.sunk[k];
            ++d.members;
          }
        for (std::size_t i = 0; i < chunk.reruns; ++i) {
          ++r.sunk[held.front()];
          held.erase(held.begin());
          ++d.members;
        }
        return d;
      });
  return r;
}

}  // namespace

TEST_CASE("run_group_in_chunks runs every position once and the reruns as chunks of their own", "[engine]") {
  const Run r = run({});
  for (std::size_t k = 0; k < 12; ++k) CHECK(r.sunk[k] == (k >= 2 ? 1 : 0));
  CHECK_FALSE(r.halted);
  CHECK(r.delivered == 10);
  CHECK(r.last == 10);
  std::size_t plan = 0, reruns = 0, mixed = 0;
  for (const Chunk& c : r.device.started) {
    plan += c.positions.size();
    reruns += c.reruns;
    mixed += !c.positions.empty() && c.reruns > 0;
    CHECK(c.positions.size() + c.reruns <= 3);
  }
  CHECK(plan == 10);
  CHECK(reruns == 5);
  CHECK(mixed == 0);
  // the three reruns queued by the first chunks fill a chunk before the group has run out
  CHECK(r.device.started.size() == 6);
  CHECK(r.device.started[3].reruns == 3);
  CHECK(r.stats.kernel_seconds == 0.25 * 6);
  CHECK(r.stats.lane_steps_busy == 15);
}

TEST_CASE("run_group_in_chunks claims through the control and starts nothing once stopped", "[engine]") {
  std::vector<std::size_t> asked;
  const Run claimed = run({.claim = [&](std::size_t begin, std::size_t end) {
    asked.push_back(begin);
    const std::size_t k = begin + 2 * asked.size() - 2;  // every other position: the rest is another rank's
    return k < end ? k : end;
  }});
  for (std::size_t k = 2; k < 12; ++k) CHECK(claimed.sunk[k] == (k % 2 == 0 ? 1 : 0));
  CHECK(claimed.delivered == 5);

  const Run stopped = run({.stop = [] { return true; }});
  CHECK(stopped.halted);
  CHECK(stopped.device.started.empty());
  CHECK(stopped.delivered == 0);
}
