// The host side of slider slots (docs/architecture.md "Teams"): a chunk's inputs from the scene's plan
// (parameters, start, the speed's sample grid) and its members' results from the slots' samples.
#include "ensemble/slider/slider_slots.hpp"

#include <algorithm>
#include <string>

#include "kernels/steppers/lane_status.hpp"

namespace rotorsweep::ensemble {

SliderSlotSchedule slider_slot_schedule(const SliderScene& scene, std::size_t speed, SliderSize size,
                                        double first_step_scale) {
  const SliderSampleGrid grid(slider_variant(scene, speed, 0));
  SliderSlotSchedule schedule;
  schedule.grid = {size.columns, size.rows};
  schedule.placement = slider_placement(scene);
  schedule.methods = kernels::stepper_methods(scene.stepper);
  schedule.rtol = scene.rtol;
  schedule.atol = scene.atol;
  schedule.h_max = kernels::two_pi / double(scene.samples_per_period);  // as SliderProblem's lanes
  schedule.max_steps = scene.max_steps;
  schedule.first_step_scale = first_step_scale;
  schedule.stops = grid.stops.size();
  for (std::size_t s = 0; s < grid.stops.size(); ++s) schedule.boundaries += grid.boundary(s) ? 1 : 0;
  schedule.rotor_sums = scene.energies || scene.field || scene.sublattices;
  schedule.forces = scene.forces;
  schedule.angles = scene.angles;
  schedule.torques = scene.torques;
  return schedule;
}

SliderSlotChunk::SliderSlotChunk(const SliderScene& scene, std::size_t speed,
                                 const SliderSlotSchedule& schedule, std::size_t capacity)
    : scene_(scene),
      grid_(slider_variant(scene, speed, 0)),
      timeline_samples_(slider_timeline(scene).samples),
      schedule_(schedule),
      capacity_(capacity),
      stops_(grid_.stops) {
  for (std::size_t s = 0; s < grid_.stops.size(); ++s) boundary_.push_back(grid_.boundary(s) ? 1 : 0);
  const std::size_t per_rotor = capacity * schedule_.stops * schedule_.grid.rotors();
  parameters_.resize(capacity);
  gradients_.resize(schedule_.forces ? 4 * capacity : 0);
  y0_.resize(capacity * dimension());
  samples_.resize(capacity * schedule_.stops * schedule_.sample_values());
  boundary_values_.resize(capacity * schedule_.boundaries * slider_boundary_values);
  angles_.resize(schedule_.angles ? per_rotor : 0);
  torques_.resize(schedule_.torques ? per_rotor : 0);
  status_.resize(capacity);
  steps_.resize(2 * capacity);
}

std::size_t SliderSlotChunk::dimension() const {
  return (scene_.overdamped ? 1 : 2) * schedule_.grid.rotors();
}

void SliderSlotChunk::fill(const std::vector<std::size_t>& plan_indices,
                           const std::vector<SliderTableViews>& tables) {
  plan_indices_ = plan_indices;
  const std::size_t dim = dimension();
  std::fill(y0_.begin(), y0_.end(), 0.0);
  for (std::size_t k = 0; k < plan_indices.size(); ++k) {
    const SliderMember m = slider_plan_member(scene_, plan_indices[k]);
    const SliderTableViews& views = tables[m.index.separation];
    parameters_[k] =
        slider_parameters(slider_variant(scene_, m.index.speed, m.index.damping), views.substrate);
    if (schedule_.forces) std::copy(views.gradient.begin(), views.gradient.end(), gradients_.begin() + 4 * k);
    const std::vector<double> theta = slider_start(scene_, m.index);
    std::copy(theta.begin(), theta.end(), y0_.begin() + std::ptrdiff_t(k * dim));
  }
}

SliderMember SliderSlotChunk::member(std::size_t k) const {
  SliderMember m = slider_plan_member(scene_, plan_indices_[k]);
  const auto status = kernels::LaneStatus(status_[k]);
  m.status = std::string(kernels::status_name(status));
  m.steps_accepted = steps_[2 * k];
  m.steps_rejected = steps_[2 * k + 1];
  const SliderUnits units(scene_);
  const std::size_t stops = schedule_.stops, rotors = schedule_.grid.rotors();
  size_slider_series(m, scene_, stops);
  for (std::size_t s = 0; s < stops; ++s) {
    const double* v = samples_.data() + (k * stops + s) * schedule_.sample_values();
    record_slider_sample(m, s, {v[0], v[1], v[2], v[3]}, units);
    if (schedule_.rotor_sums) {
      const double* r = v + schedule_.rotor_sums_at();
      record_slider_rotor_sums(m, s, {r[0], r[1], r[2], r[3], {r[4], r[5]}, {r[6], r[7]}, {r[8], r[9]}},
                               scene_);
    }
    if (schedule_.forces) {
      const double* f = v + schedule_.forces_at();
      record_slider_forces(m, s, {f[0], f[1], f[2]}, units);
    }
  }
  const std::size_t first = k * stops * rotors;
  if (schedule_.angles)
    std::copy(angles_.begin() + std::ptrdiff_t(first),
              angles_.begin() + std::ptrdiff_t(first + stops * rotors), m.angles.begin());
  if (schedule_.torques)
    for (std::size_t i = 0; i < stops * rotors; ++i) m.torques[i] = torques_[first + i] * units.energy;
  SliderBoundaries at;
  for (std::size_t b = 0; b < schedule_.boundaries; ++b) {
    const double* v = boundary_values_.data() + (k * schedule_.boundaries + b) * slider_boundary_values;
    at.impulse.push_back(v[0]);
    at.dissipation.push_back(v[1]);
    at.energy.push_back(v[2]);
  }
  summarize_slider_member(scene_, grid_, at, status == kernels::LaneStatus::ok, m);
  pad_to_timeline(m, timeline_samples_);
  return m;
}

SliderSlotViews SliderSlotChunk::views() { return slider_slot_views(slot_pointers(buffers()).data()); }

std::vector<SliderSlotChunk::Buffer> SliderSlotChunk::buffers() {
  return {slot_buffer(parameters_, true),
          slot_buffer(gradients_, true),
          slot_buffer(y0_, true),
          slot_buffer(stops_, true),
          slot_buffer(boundary_, true),
          slot_buffer(samples_, false),
          slot_buffer(boundary_values_, false),
          slot_buffer(angles_, false),
          slot_buffer(torques_, false),
          slot_buffer(status_, false),
          slot_buffer(steps_, false)};
}

SliderSlotViews slider_slot_views(void* const* p) {
  return {static_cast<const kernels::SliderParameters*>(p[0]),
          static_cast<const kernels::SubstrateTableView*>(p[1]),
          static_cast<const double*>(p[2]),
          static_cast<const double*>(p[3]),
          static_cast<const std::uint8_t*>(p[4]),
          static_cast<double*>(p[5]),
          static_cast<double*>(p[6]),
          static_cast<double*>(p[7]),
          static_cast<double*>(p[8]),
          static_cast<std::uint8_t*>(p[9]),
          static_cast<double*>(p[10])};
}

}  // namespace rotorsweep::ensemble
