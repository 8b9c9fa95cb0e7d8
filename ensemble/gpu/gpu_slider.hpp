// The slider on the GPU (docs/architecture.md "Teams"): a member per team of a warp's threads
// (SliderTeamMember), its chunks of slots run by run_slider_members_in_slots.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ensemble/gpu/gpu_launch.hpp"
#include "ensemble/slider/slider_scene.hpp"
#include "ensemble/slider/slider_slot_sweep.hpp"
#include "ensemble/slider/slider_sweep.hpp"

namespace rotorsweep::ensemble {

/// Threads per slider member of `size`: launch.team where set (2 … 32; the slider has no member per
/// thread), else the smallest power of two ≥ rotors/3 (two or three rotors per
/// thread), at most a warp. A team size outside 2 … 32 throws GpuLaunchError naming it.
unsigned gpu_slider_team_size(SliderSize size, const GpuLaunch& launch);

/// "cpu", or for numerics.device = "gpu" the result file's "device": "gpu (<name>; 32 threads per
/// member)" (per size where the scene has several).
std::string slider_device_label(const SliderScene& scene);

/// run_slider_members on the GPU: members `plan_indices` (ascending) in chunks of one size and speed,
/// each chunk's members to `finished` as it returns, the substrate tables built by `build_table` on
/// the host. Throws std::runtime_error where there is no GPU backend or no GPU.
RunOutcome run_gpu_slider_members(const SliderScene& scene, const std::vector<std::size_t>& plan_indices,
                                  const RunControl& control,
                                  const std::function<void(std::vector<SliderMember>&&)>& finished,
                                  const SliderTableBuilder& build_table);

}  // namespace rotorsweep::ensemble
