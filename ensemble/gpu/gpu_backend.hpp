// The GPU backend (docs/architecture.md "Backends", "Teams"): whether a CUDA GPU is there, and the
// limits of a member's scratch on a thread and on a team.
#pragma once

#include <cstddef>
#include <string>

namespace rotorsweep::ensemble {

struct GpuInfo {
  bool available = false;
  std::string name;  ///< the device's name, e.g. "NVIDIA H100 80GB HBM3"
  std::string why;   ///< why none is available
  int index = 0;     ///< the CUDA device's index (gpu_device_index)
  int devices = 0;   ///< CUDA devices visible to the process
  int multiprocessors = 0;
  double memory_gib = 0;
};

/// The process's CUDA device (gpu_device_index: the local rank's under mpirun or srun, else the first),
/// probed once; made the calling thread's device by use_gpu().
const GpuInfo& gpu_info();

/// Makes gpu_info()'s device the calling thread's CUDA device (each thread that runs a sweep on it);
/// the process's first call creates the device's context (CUDA 12 and later do so in cudaSetDevice).
/// Throws std::runtime_error where there is no GPU backend or no GPU.
void use_gpu();

/// Scratch (lane values per GPU thread) the kernel is compiled for: one size, so each stepper has
/// one kernel. Local memory is reserved at this size for every resident thread (64 KiB each, about
/// 18 GiB on an H100), but a member touches only DeviceMember::storage_size(N) of it.
inline constexpr std::size_t gpu_thread_scratch = 8192;

}  // namespace rotorsweep::ensemble
