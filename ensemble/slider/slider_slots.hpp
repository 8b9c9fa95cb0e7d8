// Slider members laid out as flat arrays for a device (docs/architecture.md "Teams"): a chunk of one
// size and speed — each member's parameters (its substrate table a view of coefficients on the device)
// and start, the speed's sample grid — and the slots its samples and period boundaries go to.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ensemble/engine/slot_buffer.hpp"
#include "ensemble/slider/slider_member_summary.hpp"
#include "ensemble/slider/slider_sample_grid.hpp"
#include "ensemble/slider/slider_scene.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "kernels/models/slider/slider_model.hpp"

namespace rotorsweep::ensemble {

/// What every member of a chunk shares: the rotor grid and its placement, the tolerances and step
/// limits of the CPU's lanes (SliderProblem), the speed's sample grid's size and the series the scene
/// asks for beyond friction, order parameters and energy.
struct SliderSlotSchedule {
  kernels::SliderGrid grid;
  kernels::SliderPlacement placement;
  kernels::StepperMethods methods{};  ///< the scene's (linearly implicit) stepper's tableau
  double rtol = 0, atol = 0, h_max = 0, max_steps = 0;
  double first_step_scale = 0;  ///< the stepper's (kernels::AdaptiveIntegrator), computed on the host
  std::size_t stops = 0;        ///< samples (SliderSampleGrid::stops)
  std::size_t boundaries = 0;   ///< period boundaries among them (periods + 1)
  bool rotor_sums = false;      ///< SliderScene::energies, field or sublattices: SliderRotorSums per sample
  bool forces = false;          ///< SliderScene::forces: F per sample (and gradient tables per member)
  bool angles = false, torques = false;  ///< every rotor's angle, substrate torque per sample

  /// Values a slot keeps per sample: the SliderSample (force, order along x, across y, energy), then
  /// with rotor_sums the SliderRotorSums (substrate, pairs, field_axis, field_z, moment_axis even/odd,
  /// moment_z even/odd, torque even/odd), then with forces F_x, F_y, F_z; all scaled.
  ROTORSWEEP_HD std::size_t sample_values() const { return 4 + (rotor_sums ? 10 : 0) + (forces ? 3 : 0); }
  ROTORSWEEP_HD std::size_t rotor_sums_at() const { return 4; }
  ROTORSWEEP_HD std::size_t forces_at() const { return rotor_sums ? 14 : 4; }
};

/// The schedule of the members of `scene` at speed `speed` with rotor grid `size`; first_step_scale:
/// the stepper's at the scene's tolerances.
SliderSlotSchedule slider_slot_schedule(const SliderScene& scene, std::size_t speed, SliderSize size,
                                        double first_step_scale);

/// Values a slot keeps per period boundary (impulse, dissipation, energy), scaled.
inline constexpr std::size_t slider_boundary_values = 3;

/// Where a member reads one separation's tables: the field, and with forces the four tables at
/// shifted tracks (SliderModel::GradientTable order).
struct SliderTableViews {
  kernels::SubstrateTableView substrate;
  std::array<kernels::SubstrateTableView, 4> gradient{};
};

/// Device-visible views of a chunk (k: the chunk position; inputs, then outputs).
struct SliderSlotViews {
  const kernels::SliderParameters* parameters = nullptr;   ///< [k]: its table where the device reads it
  const kernels::SubstrateTableView* gradients = nullptr;  ///< [4k + g] with forces
  const double* y0 = nullptr;                              ///< [k · dimension + i]
  const double* stops = nullptr;                           ///< [s] the grid's stops (scaled time)
  const std::uint8_t* boundary = nullptr;                  ///< [s] whether stop s is a period boundary
  double* samples = nullptr;                               ///< [(k · stops + s) · sample_values() + c]
  double* boundary_values = nullptr;  ///< [(k · boundaries + b) · slider_boundary_values + c]
  double* angles = nullptr;           ///< [(k · stops + s) · rotors + r] with angles
  double* torques = nullptr;          ///< [(k · stops + s) · rotors + r] with torques (scaled, E0)
  std::uint8_t* status = nullptr;     ///< [k] kernels::LaneStatus
  double* steps = nullptr;            ///< [2k] accepted, [2k + 1] rejected
};

/// Host buffers of a chunk of one size and speed in the SliderSlotViews layout, the host side that fills
/// them and makes SliderMembers of their outputs.
class SliderSlotChunk {
 public:
  /// A chunk of up to `capacity` members of `scene` at speed `speed` (the dampings differ by member)
  /// with `schedule` (slider_slot_schedule's for that speed).
  SliderSlotChunk(const SliderScene& scene, std::size_t speed, const SliderSlotSchedule& schedule,
                  std::size_t capacity);

  /// Fills members `plan_indices` (at most capacity, all of this size and speed); tables[s]: where the
  /// members read separation s's tables.
  void fill(const std::vector<std::size_t>& plan_indices, const std::vector<SliderTableViews>& tables);
  /// Chunk member k's results from the outputs: series in SI on the scene's timeline, summaries.
  SliderMember member(std::size_t k) const;

  SliderSlotViews views();
  const SliderSlotSchedule& schedule() const { return schedule_; }
  /// The tolerances (and the first step's scale) the next members run at: `schedule`'s, which must be
  /// this chunk's but for them (a shadow run's, slider_slot_schedule of slider_shadow_scene).
  void set_tolerances(const SliderSlotSchedule& schedule) {
    schedule_.rtol = schedule.rtol;
    schedule_.atol = schedule.atol;
    schedule_.first_step_scale = schedule.first_step_scale;
  }
  std::size_t count() const { return plan_indices_.size(); }
  std::size_t capacity() const { return capacity_; }
  /// The state's dimension (θ, and ω with inertia).
  std::size_t dimension() const;

  /// Each buffer in SliderSlotViews order, inputs first (for copies to and from a device).
  using Buffer = SlotBuffer;
  std::vector<Buffer> buffers();

 private:
  const SliderScene& scene_;
  SliderSampleGrid grid_;
  std::size_t timeline_samples_;
  SliderSlotSchedule schedule_;
  std::size_t capacity_;
  std::vector<std::size_t> plan_indices_;
  std::vector<kernels::SliderParameters> parameters_;
  std::vector<kernels::SubstrateTableView> gradients_;
  std::vector<double> y0_, stops_, samples_, boundary_values_, angles_, torques_, steps_;
  std::vector<std::uint8_t> boundary_, status_;
};

/// Views over buffers given in SliderSlotChunk::buffers() order (host or device memory).
SliderSlotViews slider_slot_views(void* const* p);

}  // namespace rotorsweep::ensemble
