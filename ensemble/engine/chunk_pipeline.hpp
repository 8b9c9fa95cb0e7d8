// Chunks of members through a device, two in flight (docs/architecture.md "Backends"): while the
// device runs one chunk, the host fills and starts the next, then finishes the one before.
#pragma once

#include <array>
#include <cstddef>

namespace rotorsweep::ensemble {

/// Runs chunks 0, 1, 2, … through two slots, chunk i in slot i mod 2: start(slot) fills the slot with
/// the next members and starts them on the device, returning false where none was left; finish(slot)
/// waits for the slot's members and delivers them, and may leave new members to start (reruns). Each
/// chunk starts before the one before it is finished, so the host's fill and delivery run beside the
/// device; where none could start then, start is asked again after the finish. Once stopped() holds
/// nothing more starts, and every chunk started is finished. Returns whether stopped() ended the run
/// (members may be left).
template <class Start, class Finish, class Stopped>
bool run_chunks_two_in_flight(Start&& start, Finish&& finish, Stopped&& stopped) {
  bool halted = false;
  const auto start_if_running = [&](std::size_t slot) {
    if (halted || stopped()) {
      halted = true;
      return false;
    }
    return bool(start(slot));
  };
  std::array<bool, 2> running{start_if_running(0), false};
  for (std::size_t slot = 0; running[slot]; slot ^= 1) {
    running[slot ^ 1] = start_if_running(slot ^ 1);
    finish(slot);
    running[slot] = false;
    if (!running[slot ^ 1]) running[slot ^ 1] = start_if_running(slot ^ 1);
  }
  return halted;
}

}  // namespace rotorsweep::ensemble
