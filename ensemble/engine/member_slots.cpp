// The host side of member slots: a chunk's inputs from the plan (initial angles, A, g, the
// strict-FM mark as RowSetup gives them) and each slot's result, summarized as LaneScheduler does.
#include "ensemble/engine/member_slots.hpp"

#include <algorithm>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_summary.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

SlotSchedule slot_schedule(const Scene& scene, const Member& variant, double first_step_scale) {
  SlotSchedule s;
  s.rows = variant.rows;
  s.periods = scene.period_schedule();
  s.wrap_angles = scene.wrap_angles;
  s.slips = scene.has(Observable::slips);
  s.slip_rate = scene.slip_rate;
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
  return s;
}

SlotChunk::SlotChunk(const SlotSchedule& schedule, std::size_t capacity)
    : schedule_(schedule),
      capacity_(capacity),
      index_(capacity),
      A_(capacity),
      g_(capacity),
      y0_(capacity * schedule.rows),
      tolerance_scale_(capacity),
      strict_fm_(capacity),
      status_(capacity),
      settled_(capacity),
      periods_(capacity),
      steps_(2 * capacity),
      theta_(capacity * schedule.rows),
      records_(capacity * schedule.record_capacity * channel_count),
      end_states_(capacity * schedule.end_capacity * schedule.rows) {}

void SlotChunk::fill(const Scene& scene, const VariantRange& range, std::size_t first, std::size_t count) {
  const std::size_t n = schedule_.rows;
  count_ = count;
  for (std::size_t k = 0; k < count; ++k) {
    const Member member = range.source->at(first + k);
    const std::vector<double> y0 = member_initial_angles(scene, member);
    index_[k] = member.index;
    A_[k] = member.A;
    g_[k] = member.g;
    tolerance_scale_[k] = member.tolerance_scale;
    strict_fm_[k] = std::all_of(y0.begin(), y0.end(), [&](double x) { return x == y0[0]; }) ? 1 : 0;
    std::copy(y0.begin(), y0.end(), y0_.begin() + std::ptrdiff_t(k * n));
  }
}

MemberResult SlotChunk::result(const Scene& scene, std::size_t k) const {
  const std::size_t n = schedule_.rows, ring = schedule_.record_capacity;
  RetiredLane lane;
  lane.index = index_[k];
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
  return retired_member_result(std::move(lane), scene.average_periods, scene.classifies_regimes(),
                               scene.period_series);
}

double SlotChunk::deliver(const Scene& scene, int threads, const ResultSink& sink) const {
  double attempts = 0;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64) reduction(+ : attempts)
  for (std::size_t k = 0; k < count_; ++k) {
    attempts += steps_[2 * k] + steps_[2 * k + 1];
    sink(result(scene, k));
  }
  return attempts;
}

SlotViews SlotChunk::views() {
  std::vector<void*> pointers;
  for (const Buffer& b : buffers()) pointers.push_back(b.data);
  return slot_views(pointers.data());
}

std::vector<SlotChunk::Buffer> SlotChunk::buffers() {
  const auto bytes = [](const auto& v) { return v.size() * sizeof(v[0]); };
  return {{A_.data(), bytes(A_), true},
          {g_.data(), bytes(g_), true},
          {strict_fm_.data(), bytes(strict_fm_), true},
          {y0_.data(), bytes(y0_), true},
          {tolerance_scale_.data(), bytes(tolerance_scale_), true},
          {status_.data(), bytes(status_), false},
          {settled_.data(), bytes(settled_), false},
          {periods_.data(), bytes(periods_), false},
          {steps_.data(), bytes(steps_), false},
          {theta_.data(), bytes(theta_), false},
          {records_.data(), bytes(records_), false},
          {end_states_.data(), bytes(end_states_), false}};
}

}  // namespace rotorsweep::ensemble
