// One host buffer of a chunk of member slots (docs/architecture.md "Backends"): what a device backend
// copies to the device before a chunk runs (inputs) and back after it (outputs).
#pragma once

#include <cstddef>

namespace rotorsweep::ensemble {

/// A buffer's data and size in bytes, and whether it is an input (else an output).
struct SlotBuffer {
  void* data;
  std::size_t bytes;
  bool input;
};

}  // namespace rotorsweep::ensemble
