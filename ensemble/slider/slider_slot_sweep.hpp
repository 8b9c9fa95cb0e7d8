// A slider scan through slots on a device (docs/architecture.md "Teams"): the members of each size and
// speed in chunks, each separation's substrate table built once and placed where the device reads it.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "ensemble/engine/run_control.hpp"
#include "ensemble/engine/slot_device.hpp"
#include "ensemble/slider/slider_scene.hpp"
#include "ensemble/slider/slider_slots.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "kernels/models/slider/substrate_table.hpp"

namespace rotorsweep::ensemble {

/// What runs chunks of slider slots: the GPU (ensemble/gpu/gpu_sweep_slider.cu), or a host team; besides
/// running chunks it sizes them and places the substrate tables where its members read them.
class SliderSlotDevice : public SlotDevice<SliderSlotChunk> {
 public:
  /// The most members one chunk of a slider of `schedule` holds (enough to keep the device busy); chunks
  /// of the schedule before are finished.
  virtual std::size_t chunk_members(const SliderSlotSchedule& schedule) = 0;
  /// Views of `tables` where the members read them (copies in device memory, kept until the next
  /// call), in their order; a null table gives an empty view.
  virtual std::vector<kernels::SubstrateTableView> place_tables(
      const std::vector<const kernels::SubstrateTable*>& tables) = 0;
};

/// Builds the substrate table of a slider of `size` at separation h (m) over the scene's path, its
/// tracks moved by dy and the substrate farther by ddepth (units of a; substrate_table<V>: the
/// caller's lanes, every V giving the same table).
using SliderTableBuilder = std::function<kernels::SubstrateTable(const SliderScene&, SliderSize, double h,
                                                                 double dy, double ddepth)>;

/// An executor that runs slider members off the CPU's lanes (the GPU's: ensemble/gpu/gpu_executor.hpp),
/// handed to run_slider_members by its caller: the scan names no backend.
class SliderDevice {
 public:
  virtual ~SliderDevice() = default;
  /// run_slider_members on the device: members `plan_indices` (ascending) in chunks of one size and speed,
  /// each chunk's members to `finished` as it returns, the substrate tables built by `build_table` on the host.
  virtual RunOutcome run_members(const SliderScene& scene, const std::vector<std::size_t>& plan_indices,
                                 const RunControl& control,
                                 const std::function<void(std::vector<SliderMember>&&)>& finished,
                                 const SliderTableBuilder& build_table) const = 0;
};

/// The first-step scale of the scene's stepper at its tolerances (kernels::AdaptiveIntegrator's).
double slider_first_step_scale(const SliderScene& scene);

/// run_slider_members on `device`: members `plan_indices` (ascending) in chunks of one size and speed, two
/// in flight (claimed with control.claim where set), each chunk's members to `finished` at once (series on
/// the scene's timeline), their separations' tables (with SliderScene::forces also the four at shifted
/// tracks) built by `build_table` on the control's threads; progress after each chunk, no chunk started
/// once a stop holds. Statistics: the wall time and the device's.
RunOutcome run_slider_members_in_slots(const SliderScene& scene, const std::vector<std::size_t>& plan_indices,
                                       const RunControl& control,
                                       const std::function<void(std::vector<SliderMember>&&)>& finished,
                                       SliderSlotDevice& device, const SliderTableBuilder& build_table);

}  // namespace rotorsweep::ensemble
