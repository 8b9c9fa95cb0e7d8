// The GPU backend's launch settings (docs/architecture.md "Teams"): the block shape, a team's size and
// its scratch as the environment asks for them, and the device of a node's rank.
#pragma once

#include <stdexcept>

namespace rotorsweep::ensemble {

/// A bad value of a ROTORSWEEP_GPU_* variable (the message names it and what is allowed): like a bad
/// scene key, the command line's exit code 2.
class GpuLaunchError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Where a team keeps its member's vectors: the block's shared memory where its teams' fit, else global
/// memory (automatic), or as asked.
enum class GpuScratch { automatic, shared, global };

/// How the GPU backend launches: threads per block, blocks (0: as many as fit at once), threads per
/// member (0: by N, gpu_team_size) and where a team's scratch lives. Results do not depend on the
/// block shape; a team's size changes the last bits (docs/numerics.md "The stage solve on a team").
struct GpuLaunch {
  int threads_per_block = 128;
  int blocks = 0;
  unsigned team = 0;
  GpuScratch scratch = GpuScratch::automatic;
};

/// The launch in use: the defaults, or from the environment ROTORSWEEP_GPU_BLOCK (a multiple of 32 up
/// to 1024), ROTORSWEEP_GPU_BLOCKS, ROTORSWEEP_GPU_TEAM (a power of two up to 32) and
/// ROTORSWEEP_GPU_SCRATCH (shared or global); a bad value throws GpuLaunchError naming it.
GpuLaunch gpu_launch();

/// The CUDA device this process runs on among `devices` visible ones (docs/architecture.md "Backends"):
/// its node-local rank modulo `devices` under mpirun (OMPI_COMM_WORLD_LOCAL_RANK) or srun
/// (SLURM_LOCALID), so that a node's ranks spread over its GPUs; device 0 outside them. A local rank
/// that is not a non-negative integer throws GpuLaunchError naming the variable.
int gpu_device_index(int devices);

}  // namespace rotorsweep::ensemble
