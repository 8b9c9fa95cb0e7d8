// The GPU backend's launch settings from the environment (docs/architecture.md "Teams"), read by
// gpu_executor() once, and the device of a node's rank.
#include "ensemble/gpu/gpu_launch.hpp"

#include <cstdlib>
#include <string>

namespace rotorsweep::ensemble {

namespace {

int positive_from_environment(const char* name, int fallback) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*end != '\0' || value < 1 || value > (1 << 20))
    throw GpuLaunchError(std::string(name) + " = '" + text + "': must be a positive integer");
  return int(value);
}

GpuScratch scratch_from_environment() {
  const char* text = std::getenv("ROTORSWEEP_GPU_SCRATCH");
  if (!text || !*text) return GpuScratch::automatic;
  const std::string value = text;
  if (value == "shared") return GpuScratch::shared;
  if (value == "global") return GpuScratch::global;
  throw GpuLaunchError("ROTORSWEEP_GPU_SCRATCH = '" + value + "': allowed: shared, global");
}

}  // namespace

int gpu_device_index(int devices) {
  for (const char* name : {"OMPI_COMM_WORLD_LOCAL_RANK", "SLURM_LOCALID"}) {
    const char* text = std::getenv(name);
    if (!text || !*text) continue;
    char* end = nullptr;
    const long rank = std::strtol(text, &end, 10);
    if (*end != '\0' || rank < 0 || rank > (1 << 24))
      throw GpuLaunchError(std::string(name) + " = '" + text +
                           "': not a local rank (a non-negative integer)");
    return devices > 0 ? int(rank % devices) : 0;
  }
  return 0;
}

GpuLaunch gpu_launch() {
  GpuLaunch launch;
  launch.threads_per_block = positive_from_environment("ROTORSWEEP_GPU_BLOCK", launch.threads_per_block);
  if (launch.threads_per_block > 1024 || launch.threads_per_block % 32 != 0)
    throw GpuLaunchError("ROTORSWEEP_GPU_BLOCK: must be a multiple of 32 from 32 to 1024");
  launch.blocks = positive_from_environment("ROTORSWEEP_GPU_BLOCKS", 0);
  const int team = positive_from_environment("ROTORSWEEP_GPU_TEAM", 0);
  if (team > 32 || (team & (team - 1)) != 0)
    throw GpuLaunchError("ROTORSWEEP_GPU_TEAM = " + std::to_string(team) +
                         ": allowed: 1, 2, 4, 8, 16 or 32 (1: a member per thread, 2 … 32: a team of a "
                         "warp's threads)");
  launch.team = unsigned(team);
  launch.scratch = scratch_from_environment();
  return launch;
}

}  // namespace rotorsweep::ensemble
