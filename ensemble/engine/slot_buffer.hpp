// One host buffer of a chunk of member slots (docs/architecture.md "Backends"): what a device backend
// copies to the device before a chunk runs (inputs) and back after it (outputs).
#pragma once

#include <cstddef>
#include <vector>

namespace rotorsweep::ensemble {

/// A buffer's data and size in bytes, and whether it is an input (else an output).
struct SlotBuffer {
  void* data;
  std::size_t bytes;
  bool input;
};

/// The buffer of a vector's values.
template <class T>
SlotBuffer slot_buffer(std::vector<T>& values, bool input) {
  return {values.data(), values.size() * sizeof(T), input};
}

/// Each buffer's data, in order: what a chunk's views are made of.
inline std::vector<void*> slot_pointers(const std::vector<SlotBuffer>& buffers) {
  std::vector<void*> pointers;
  for (const SlotBuffer& b : buffers) pointers.push_back(b.data);
  return pointers;
}

}  // namespace rotorsweep::ensemble
