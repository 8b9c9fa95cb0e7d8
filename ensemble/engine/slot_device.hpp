// What runs chunks of member slots (docs/architecture.md "The run API"): a GPU's kernels, or a host in the
// tests; one interface for every problem's chunks, two in flight (run_chunks_two_in_flight).
#pragma once

#include <cstddef>

namespace rotorsweep::ensemble {

/// Runs a problem's chunks (Chunk: its members' inputs and outputs in slots' buffers) in two slots.
template <class Chunk>
class SlotDevice {
 public:
  virtual ~SlotDevice() = default;
  /// Starts every member of `chunk` in `slot` (0 or 1), inputs from its buffers; may return before they
  /// have finished.
  virtual void start(Chunk& chunk, std::size_t slot) = 0;
  /// Waits for the members started in `slot`; their outputs are then in the chunk's buffers. Returns the
  /// seconds the device ran them (0 where it does not time them).
  virtual double finish(Chunk& chunk, std::size_t slot) = 0;
};

}  // namespace rotorsweep::ensemble
