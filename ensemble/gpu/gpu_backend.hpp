// The GPU backend (docs/architecture.md "Backends"): whether a CUDA GPU is there, and the sweep of
// one variant on it, one member per GPU thread through the device driver (ensemble/engine/device_member.hpp).
#pragma once

#include <cstddef>
#include <string>

#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/sweep.hpp"

namespace rotorsweep::ensemble {

struct GpuInfo {
  bool available = false;
  std::string name;  ///< the device's name, e.g. "NVIDIA H100 80GB HBM3"
  std::string why;   ///< why none is available
  int multiprocessors = 0;
  double memory_gib = 0;
};

/// The first CUDA device (probed once).
const GpuInfo& gpu_info();

/// "cpu", or "gpu (<name>)" for a scene with numerics.device = "gpu" (the result file's "device").
std::string device_label(const Scene& scene);

/// Scratch (lane values per GPU thread) the kernel is compiled for: one size, so each stepper has
/// one kernel. Local memory is reserved at this size for every resident thread (64 KiB each, about
/// 18 GiB on an H100), but a member touches only DeviceMember::storage_size(N) of it.
inline constexpr std::size_t gpu_thread_scratch = 8192;

/// The most rows one member may have on the GPU with the scene's stepper (its scratch lives in
/// per-thread memory of a fixed size), an even number like every row count.
std::size_t gpu_max_rows(const Scene& scene);

/// How the GPU backend launches: threads per block, and blocks (0: as many as fit at once).
struct GpuLaunch {
  int threads_per_block = 128;
  int blocks = 0;
};

/// The launch in use: the defaults, or ROTORSWEEP_GPU_BLOCK and ROTORSWEEP_GPU_BLOCKS from the
/// environment (results do not depend on it; tests and benchmarks vary it).
GpuLaunch gpu_launch();

/// Runs the members of `range` (one variant) on the GPU; results go to `sink` as each chunk
/// returns. Throws std::runtime_error where there is no GPU backend or no GPU.
SweepOutcome run_gpu_row_sweep(const Scene& scene, const VariantRange& range, int host_threads,
                               const SweepControl& control, const ResultSink& sink);

}  // namespace rotorsweep::ensemble
