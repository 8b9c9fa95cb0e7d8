// The host side of member slots: a chunk's inputs from the plan (initial angles, A, g, the
// strict-FM mark, disorder, couplings and noise keys as RowSetup gives them) and each slot's
// result, summarized as LaneScheduler does.
#include "ensemble/rows/member_slots.hpp"

#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "ensemble/rows/disorder.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_summary.hpp"
#include "ensemble/rows/row_models.hpp"
#include "ensemble/rows/symmetry_probe.hpp"
#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/counter_random.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

SlotSchedule slot_schedule(const Scene& scene, const Member& variant, double first_step_scale) {
  SlotSchedule s;
  s.rows = variant.rows;
  s.periods = scene.period_schedule();
  s.steady_tol = scene.steady_tol;
  s.wrap_angles = scene.wrap_angles;
  s.slips = scene.has(Observable::slips);
  s.slip_energies = scene.slip_kinds;
  s.slip_rate = scene.slip_rate;
  s.methods = kernels::stepper_methods(scene.stepper);
  s.rtol = variant.rtol;
  s.atol = variant.atol;
  s.error_rtol = kernels::stepper_swing_error_factors[scene.stepper] * variant.rtol;
  s.h_max = scene.h_max;
  s.max_steps = scene.max_steps;
  s.controller = scene.controller;
  s.first_step_scale = first_step_scale;
  s.quadratures = scene.observables.quadratures();
  s.channels = quadrature_channels(s.quadratures);
  // the averaged periods and the two the steady test compares; every period with period_series
  s.record_capacity = std::size_t(std::max(scene.average_periods, 2));
  if (scene.period_series) s.record_capacity = std::max(s.record_capacity, std::size_t(s.periods.limit()));
  s.end_capacity = end_state_capacity(scene.average_periods);
  s.stochastic = scene.thermal.on();
  s.temperature = scene.thermal.temperature;
  s.steps_per_period = scene.thermal.steps_per_period;
  s.step_fraction = scene.thermal.step_fraction;
  s.row_profiles = scene.row_profiles;
  s.links = scene.couplings.open ? s.rows - 1 : s.rows;
  s.profile_capacity = scene.row_profiles ? std::size_t(scene.average_periods) : 0;
  const RowDeviations d = row_deviations(scene.disorder, s.rows, 0);
  s.A_rows = !d.A.empty();
  s.anisotropy_rows = !d.anisotropy.empty();
  s.coupling_rows = !d.coupling.empty();
  if (row_model_traits(scene.model).coupling_table) {
    const CouplingTable table = scene.couplings.for_rows(s.rows);
    s.coupling_a = table.a;
    s.coupling_range = table.range();
    s.open = scene.couplings.open;
  }
  return s;
}

SlotSchedule shadow_slot_schedule(const Scene& scene, const SlotSchedule& primary) {
  SlotSchedule s = primary;
  s.periods = scene.shadow_schedule();
  s.steady_tol = 0;
  s.A_rows = s.A_rows || runs_probes(scene, s.stochastic, s.rtol);  // the probes' deviations
  return s;
}

SlotChunk::SlotChunk(const SlotSchedule& schedule, std::size_t capacity)
    : schedule_(schedule),
      capacity_(capacity),
      members_(capacity),
      A_(capacity),
      g_(capacity),
      y0_(capacity * schedule.rows),
      tolerance_scale_(capacity),
      A_rows_(schedule.A_rows ? capacity * schedule.rows : 0),
      anisotropy_rows_(schedule.anisotropy_rows ? capacity * schedule.rows : 0),
      coupling_rows_(schedule.coupling_rows ? capacity * schedule.rows : 0),
      noise_key_(schedule.stochastic ? capacity : 0),
      table_b_(schedule.coupling_range),
      table_c_(schedule.coupling_range),
      strict_fm_(capacity),
      status_(capacity),
      settled_(capacity),
      periods_(capacity),
      steps_(2 * capacity),
      theta_(capacity * schedule.rows),
      records_(capacity * schedule.record_capacity * channel_count),
      end_states_(capacity * schedule.end_capacity * schedule.rows),
      profiles_(capacity * schedule.profile_capacity * 2 * schedule.rows) {}

void SlotChunk::fill(const Scene& scene, std::span<const Member> members) {
  const std::size_t n = schedule_.rows;
  count_ = members.size();
  for (std::size_t k = 0; k < count_; ++k) {
    const Member& member = members_[k] = members[k];
    const std::vector<double> y0 = member_initial_angles(scene, member);
    A_[k] = member.A;
    g_[k] = member.g;
    tolerance_scale_[k] = member.tolerance_scale;
    strict_fm_[k] = std::all_of(y0.begin(), y0.end(), [&](double x) { return x == y0[0]; }) ? 1 : 0;
    std::copy(y0.begin(), y0.end(), y0_.begin() + std::ptrdiff_t(k * n));
    if (schedule_.stochastic) noise_key_[k] = kernels::RandomStream(scene.thermal.seed, member.stream).key();
    if (!schedule_.A_rows && !schedule_.anisotropy_rows && !schedule_.coupling_rows) continue;
    const RowDeviations d = member_deviations(scene.disorder, member);
    const auto at = std::ptrdiff_t(k * n);
    const auto put = [&](const std::vector<double>& values, std::vector<double>& slots) {  // none: zeros
      if (values.empty())
        std::fill_n(slots.begin() + at, n, 0.0);
      else
        std::copy(values.begin(), values.end(), slots.begin() + at);
    };
    if (schedule_.A_rows) put(d.A, A_rows_);
    if (schedule_.anisotropy_rows) put(d.anisotropy, anisotropy_rows_);
    if (schedule_.coupling_rows) put(d.coupling, coupling_rows_);
  }
  if (schedule_.coupling_range > 0 && !table_filled_) {
    const CouplingTable table = scene.couplings.for_rows(n);
    std::copy(table.b.begin(), table.b.end(), table_b_.begin());
    std::copy(table.c.begin(), table.c.end(), table_c_.begin());
    table_filled_ = true;
  }
}

MemberResult SlotChunk::result(const Scene& scene, std::size_t k) const {
  const std::size_t n = schedule_.rows, ring = schedule_.record_capacity;
  RetiredLane lane;
  lane.index = members_[k].index;
  lane.status = kernels::LaneStatus(status_[k]);
  lane.settled = settled_[k] != 0;
  lane.periods = periods_[k];
  lane.steps_accepted = steps_[2 * k];
  lane.steps_rejected = steps_[2 * k + 1];
  lane.theta.assign(theta_.begin() + std::ptrdiff_t(k * n), theta_.begin() + std::ptrdiff_t((k + 1) * n));
  const std::size_t periods = std::size_t(lane.periods);
  for (std::size_t p = periods - std::min(periods, ring); p < periods; ++p) {
    PeriodRecord record;
    const double* slot = &records_[(k * ring + p % ring) * channel_count];
    std::copy(slot, slot + channel_count, record.values.begin());
    lane.history.push_back(record);
  }
  const std::size_t ends = schedule_.end_capacity;
  std::vector<std::vector<double>> kept;
  for (std::size_t p = periods - std::min(periods, ends); p < periods; ++p) {
    const double* end = &end_states_[(k * ends + p % ends) * n];
    kept.emplace_back(end, end + n);
  }
  keep_end_states(lane, std::move(kept), scene.average_periods);
  const std::size_t profiles = schedule_.profile_capacity, stride = 2 * n;
  for (std::size_t p = periods - std::min(periods, profiles); p < periods; ++p) {
    const double* profile = &profiles_[(k * profiles + p % profiles) * stride];
    lane.profiles.emplace_back(profile, profile + n + schedule_.links);
  }
  lane.links = schedule_.links;
  return retired_member_result(
      std::move(lane), summary_rules(scene, schedule_.stochastic, kernels::two_pi, schedule_.row_profiles));
}

void SlotChunk::set_schedule(const SlotSchedule& schedule) {
  const auto layout = [](const SlotSchedule& s) {
    return std::tuple(s.rows, s.record_capacity, s.end_capacity, s.profile_capacity, s.links, s.stochastic,
                      s.coupling_range);
  };
  const bool arrays_held = (!schedule.A_rows || !A_rows_.empty()) &&
                           (!schedule.anisotropy_rows || !anisotropy_rows_.empty()) &&
                           (!schedule.coupling_rows || !coupling_rows_.empty());
  if (layout(schedule) != layout(schedule_) || !arrays_held)
    throw std::logic_error("SlotChunk: a schedule of other slots");
  schedule_ = schedule;
}

double SlotChunk::deliver(const Scene& scene, int threads, const Sink& sink) const {
  double attempts = 0;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64) reduction(+ : attempts)
  for (std::size_t k = 0; k < count_; ++k) {
    attempts += steps_[2 * k] + steps_[2 * k + 1];
    sink(members_[k], result(scene, k));
  }
  return attempts;
}

SlotViews SlotChunk::views() { return slot_views(slot_pointers(buffers()).data()); }

std::vector<SlotChunk::Buffer> SlotChunk::buffers() {
  return {slot_buffer(A_, true),
          slot_buffer(g_, true),
          slot_buffer(strict_fm_, true),
          slot_buffer(y0_, true),
          slot_buffer(tolerance_scale_, true),
          slot_buffer(A_rows_, true),
          slot_buffer(anisotropy_rows_, true),
          slot_buffer(coupling_rows_, true),
          slot_buffer(noise_key_, true),
          slot_buffer(table_b_, true),
          slot_buffer(table_c_, true),
          slot_buffer(status_, false),
          slot_buffer(settled_, false),
          slot_buffer(periods_, false),
          slot_buffer(steps_, false),
          slot_buffer(theta_, false),
          slot_buffer(records_, false),
          slot_buffer(end_states_, false),
          slot_buffer(profiles_, false)};
}

}  // namespace rotorsweep::ensemble
