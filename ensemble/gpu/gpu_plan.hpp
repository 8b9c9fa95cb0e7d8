// One GPU plan (docs/architecture.md "Teams"): from the launch settings, how the GPU runs a variant's row
// members or a slider size's — a member per thread, per team of k threads or in registers of a shape —,
// where a team's vectors live and how many members a chunk holds. Every rule of the mapping is here.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "ensemble/gpu/gpu_launch.hpp"
#include "ensemble/gpu/gpu_registers.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/slider/slider_scene.hpp"

namespace rotorsweep::ensemble {

/// How a member's work lies on the GPU's threads.
enum class GpuMapping { thread, team, registers };

struct GpuPlan {
  GpuMapping mapping = GpuMapping::thread;
  unsigned team = 1;                   ///< threads per member: 1, a team's size, or a register shape's lanes
  std::optional<RegisterShape> shape;  ///< the register kernel's, with GpuMapping::registers
  int threads_per_block = 128;
  int blocks = 0;  ///< 0: as many as fit at once
  /// Where a team's vectors live where a block's teams fit its shared memory (else global memory)...
  GpuScratch scratch = GpuScratch::shared;
  /// ...unless ROTORSWEEP_GPU_SCRATCH asked for it: shared that does not fit is then an error.
  bool scratch_asked = false;
  /// A chunk holds chunk_per_resident × the members resident at once, at least chunk_floor: enough to
  /// keep the GPU busy while the host fills the next and summarizes the last.
  std::size_t chunk_per_resident = 8;
  std::size_t chunk_floor = std::size_t(1) << 16;

  /// The members of a chunk of a group of `members`, with `resident` at once.
  std::size_t chunk_members(std::size_t resident, std::size_t members) const;
  /// "8 threads per member, rows in registers", "8 threads per member" or "1 thread per member".
  std::string threads_per_member() const;
};

/// Whether the scene's members can run on a team (ensemble/rows/team_member.hpp): rows (nearest
/// neighbours or a coupling table) at T > 0 or with a linearly implicit stepper.
bool gpu_teams_fit(const Scene& scene);

/// Threads per member of N = `rows`: 1 where teams do not fit the scene; else launch.team where set;
/// else 1 up to 4 rows and above that the smallest power of two ≥ N/3 (two or three rows per thread),
/// at most a warp (32).
unsigned gpu_team_size(const Scene& scene, std::size_t rows, const GpuLaunch& launch);

/// The shape among `shapes` that runs members of N = `rows` of the scene in registers, or none:
/// T = 0, nearest neighbours, a linearly implicit stepper, no row profiles, no ROTORSWEEP_GPU_TEAM (which
/// asks for a thread or a team), and a shape that holds N, disordered where the scene has disorder or may
/// run symmetry probes, with stage vectors for the scene's stepper, that can carry the scene's quadratures
/// and whose occupancy bound admits the launch's threads per block. Of those that fit, the fewest slots in
/// all, then the most lanes, then the fewest stages, then the fewest quadratures, then the most resident
/// blocks.
std::optional<RegisterShape> choose_register_shape(std::span<const RegisterShape> shapes, const Scene& scene,
                                                   std::size_t rows, const GpuLaunch& launch);

/// The plan for a variant of the row scene with N = `rows`: registers where a shape among `shapes` holds
/// it, else a team of gpu_team_size threads, else a thread; a team's vectors in shared memory where they
/// fit; chunks of 8 × the resident members, at least 65 536.
GpuPlan plan_row_variant(const Scene& scene, std::size_t rows, const GpuLaunch& launch,
                         std::span<const RegisterShape> shapes = gpu_register_shapes());

/// Threads per slider member of `size`: launch.team where set (2 … 32; the slider has no member per
/// thread), else the smallest power of two ≥ rotors/3 (two or three rotors per thread), at most a warp.
/// A team size outside 2 … 32 throws GpuLaunchError naming it.
unsigned gpu_slider_team_size(SliderSize size, const GpuLaunch& launch);

/// The plan for slider members of `size`: a team of gpu_slider_team_size threads, its vectors in global
/// memory unless asked otherwise (more teams resident, the L1 cache left to the local arrays: faster on
/// an H100, docs/performance.md); chunks of 4 × the resident members, at least 1 024.
GpuPlan plan_slider_size(SliderSize size, const GpuLaunch& launch);

}  // namespace rotorsweep::ensemble
