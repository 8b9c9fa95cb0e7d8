// The slider scan: lane blocks of members integrated from sample to sample by the adaptive steppers,
// friction and dissipation from the quadratures at period boundaries, converted to SI (docs/model.md §9).
#include "ensemble/slider/slider_sweep.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <memory>

#include "kernels/lanes/lane.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/lane_state.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

namespace {

using kernels::lane_get;
using kernels::lane_vector;
using V = kernels::simd_lane;
constexpr std::size_t W = kernels::lane_width<V>;

/// The times (scaled) at which every lane stops and is sampled: a grid of `samples_per_period` per
/// period through the start of sliding, from 0 to the end; every period boundary is on it.
struct Schedule {
  std::vector<double> stops;
  std::vector<long> index;  ///< samples since the start of sliding (negative during the rest)
  std::size_t samples_per_period;
  std::size_t periods;

  Schedule(const SliderScene& scene, const SliderUnits& units)
      : samples_per_period(scene.samples_per_period) {
    const double dt = kernels::two_pi / double(samples_per_period);
    const double rest = scene.rest / units.time, end = scene.end / units.time;
    const long first = -long(std::floor(rest / dt + 1e-9));
    if (rest + double(first) * dt > 1e-12) {
      stops.push_back(0.0);
      index.push_back(first - 1);
    }
    for (long k = first; rest + double(k) * dt <= end * (1 + 1e-12); ++k) {
      stops.push_back(rest + double(k) * dt);
      index.push_back(k);
    }
    periods = std::size_t(std::max(0L, index.back()) / long(samples_per_period));
  }
  bool boundary(std::size_t stop) const {
    return index[stop] >= 0 && index[stop] % long(samples_per_period) == 0 &&
           std::size_t(index[stop] / long(samples_per_period)) <= periods;
  }
};

/// The members of one lane block through the whole schedule.
template <bool Inertial, class Stepper>
void run_block(const SliderScene& scene, const Schedule& schedule, std::vector<SliderMember>& block) {
  using Model = kernels::SliderModel<V, Inertial>;
  using Integrator = kernels::AdaptiveIntegrator<Model, Stepper>;
  const SliderUnits units(scene);
  const SliderSize size = block.front().size;
  const kernels::SliderGrid grid{size.columns, size.rows};
  const std::size_t n = grid.rotors(), dim = Inertial ? 2 * n : n;

  std::vector<std::unique_ptr<kernels::SubstrateTable>> tables;
  for (std::size_t l = 0; l < block.size(); ++l)
    tables.push_back(
        std::make_unique<kernels::SubstrateTable>(substrate_table(scene, size, block[l].separation)));

  kernels::StepLimits limits;
  limits.h_max = kernels::two_pi / double(scene.samples_per_period);
  limits.max_steps = scene.max_steps;
  const kernels::Tolerances tolerances{scene.rtol, scene.atol};
  // what the block builds over its storage (counted first, over an arena without storage)
  struct Parts {
    Model model;
    Integrator integrator;
    kernels::LaneState<V> state;
    typename Model::Workspace work;
    V* f;
    V* q;  // quadrature integrands (only the first two used)
    Parts(const kernels::SliderGrid& grid, std::size_t dim, kernels::Tolerances tol, kernels::StepLimits lim,
          kernels::LaneArena<V>& arena)
        : model(grid, arena),
          integrator(model, tol, lim, arena),
          state(dim, Model::max_quadratures, arena),
          work(dim, arena),
          f(arena.take(dim)),
          q(arena.take(dim)) {}
  };
  const std::size_t storage = kernels::counted_storage<V>(
      [&](kernels::LaneArena<V>& counter) { const Parts parts(grid, dim, tolerances, limits, counter); });
  lane_vector<V> memory(storage);
  kernels::LaneArena<V> arena(memory.data(), storage);
  Parts parts(grid, dim, tolerances, limits, arena);
  Model& model = parts.model;
  for (std::size_t l = 0; l < W; ++l) {
    model.set_lane(l, slider_parameters(scene, *tables[std::min(l, block.size() - 1)]));
  }
  Integrator& integrator = parts.integrator;
  kernels::LaneState<V>& state = parts.state;
  typename Model::Workspace& work = parts.work;
  V* f = parts.f;
  V* q = parts.q;

  for (std::size_t l = 0; l < W; ++l) {
    const auto& m = block[std::min(l, block.size() - 1)];
    const auto theta = slider_start(scene, m.index);
    for (std::size_t r = 0; r < n; ++r) kernels::lane_set(state.y[r], l, theta[r]);
  }

  const std::size_t samples = schedule.stops.size();
  for (std::size_t l = 0; l < block.size(); ++l) {
    auto& m = block[l];
    m.friction_series.assign(samples, 0.0);
    m.order_x_series.assign(samples, 0.0);
    m.order_y_series.assign(samples, 0.0);
    m.energy_series.assign(samples, 0.0);
    if (scene.angles) m.angles.assign(samples * n, 0.0);
  }
  std::vector<double> impulse_at, dissipation_at, energy_at;  // per boundary × lane
  for (std::size_t k = 0; k < samples; ++k) {
    state.t_stop = V(schedule.stops[k]);
    integrator.advance(model, state);
    const V t = state.t;
    model.evaluate(work, state.y, t, f, q);
    V along_x, across_y;
    model.order_parameters(state.y, along_x, across_y);
    const V energy = model.energy(work, state.y, t) + model.kinetic_energy(state.y);
    for (std::size_t l = 0; l < block.size(); ++l) {
      auto& m = block[l];
      m.friction_series[k] = lane_get(q[Model::impulse_index], l) * units.force;
      m.order_x_series[k] = lane_get(along_x, l);
      m.order_y_series[k] = lane_get(across_y, l);
      m.energy_series[k] = lane_get(energy, l) * units.energy;
      if (scene.angles)
        for (std::size_t r = 0; r < n; ++r) m.angles[k * n + r] = lane_get(state.y[r], l);
    }
    if (schedule.boundary(k))
      for (std::size_t l = 0; l < W; ++l) {
        impulse_at.push_back(lane_get(state.quad[Model::impulse_index], l));
        dissipation_at.push_back(lane_get(state.quad[Model::dissipation_index], l));
        energy_at.push_back(lane_get(energy, l));
      }
  }

  const double speed = 1.0 / kernels::two_pi, period = kernels::two_pi;
  for (std::size_t l = 0; l < block.size(); ++l) {
    auto& m = block[l];
    m.status = std::string(kernels::status_name(state.status[l]));
    m.steps_accepted = lane_get(state.steps_accepted, l);
    m.steps_rejected = lane_get(state.steps_rejected, l);
    for (std::size_t p = 0; p < schedule.periods; ++p) {
      const std::size_t a = p * W + l, b = (p + 1) * W + l;
      const double impulse = impulse_at[b] - impulse_at[a];
      const double work = speed * impulse, dissipated = dissipation_at[b] - dissipation_at[a];
      const double stored = energy_at[b] - energy_at[a];
      m.period_friction.push_back(impulse / period * units.force);
      m.period_work.push_back(work * units.energy);
      m.period_dissipation.push_back(dissipated * units.energy);
      m.period_stored.push_back(stored * units.energy);
      m.period_balance.push_back((work - dissipated - stored) /
                                 std::max({std::fabs(work), std::fabs(dissipated), 1e-300}));
    }
    if (schedule.periods > 0) {
      const std::size_t last = schedule.periods * W + l;
      m.friction = (impulse_at[last] - impulse_at[l]) / (period * double(schedule.periods)) * units.force;
    } else {
      m.friction = std::nan("");
    }
    double sum_x = 0.0, sum_y = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < samples; ++k) {
      if (schedule.index[k] <= 0) continue;
      sum_x += m.order_x_series[k];
      sum_y += m.order_y_series[k];
      ++count;
    }
    m.order_x = count ? sum_x / double(count) : std::nan("");
    m.order_y = count ? sum_y / double(count) : std::nan("");
    if (m.status != "ok") {  // a stopped lane's values would describe a frozen state: flag them all
      const double nan = std::nan("");
      m.friction = m.order_x = m.order_y = nan;
      for (auto* period :
           {&m.period_friction, &m.period_work, &m.period_dissipation, &m.period_stored, &m.period_balance})
        std::fill(period->begin(), period->end(), nan);
    }
  }
}

/// Runs the blocks; returns whether stopped() left any of them out.
template <bool Inertial>
bool run_blocks(const SliderScene& scene, const Schedule& schedule,
                std::vector<std::vector<SliderMember>>& blocks, const SliderScanControl& control,
                const std::function<void(std::vector<SliderMember>&&)>& finished) {
  std::atomic<bool> skipped{false};
  std::exception_ptr failure;  // the first exception of a worker (it must not leave the parallel region)
  const int threads = control.threads > 0 ? control.threads : omp_get_max_threads();
  kernels::with_stepper<kernels::SliderModel<V, Inertial>>(scene.stepper, [&]<class Stepper>() {
    std::size_t done = 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      if (skipped || (control.stopped && control.stopped())) {
        skipped = true;
        continue;
      }
      try {
        run_block<Inertial, Stepper>(scene, schedule, blocks[b]);
      } catch (...) {
#pragma omp critical(slider_failure)
        if (!failure) failure = std::current_exception();
        skipped = true;
        continue;
      }
#pragma omp critical(slider_finished)
      {
        done += blocks[b].size();
        finished(std::move(blocks[b]));
        if (control.progress) control.progress(done);
      }
    }
  });
  if (failure) std::rethrow_exception(failure);
  return skipped;
}

}  // namespace

SliderMember slider_plan_member(const SliderScene& scene, std::size_t plan_index) {
  const std::size_t replicas = scene.replicas, separations = scene.separations.size();
  SliderMember m;
  m.plan_index = plan_index;
  m.index = {plan_index / (separations * replicas), plan_index / replicas % separations,
             plan_index % replicas};
  m.size = scene.sizes[m.index.size];
  m.separation = scene.separations[m.index.separation];
  return m;
}

SliderTimeline slider_timeline(const SliderScene& scene) {
  const SliderUnits units(scene);
  const Schedule schedule(scene, units);
  SliderTimeline timeline;
  timeline.period = scene.spacing / scene.speed;
  timeline.periods = schedule.periods;
  for (const double t : schedule.stops) timeline.sample_times.push_back(t * units.time);
  return timeline;
}

bool run_slider_members(const SliderScene& scene, const std::vector<std::size_t>& plan_indices,
                        const SliderScanControl& control,
                        const std::function<void(std::vector<SliderMember>&&)>& finished) {
  const Schedule schedule(scene, SliderUnits(scene));
  // lane blocks of members of one size (a block shares its grid)
  std::vector<std::vector<SliderMember>> blocks;
  for (const std::size_t i : plan_indices) {
    SliderMember m = slider_plan_member(scene, i);
    if (blocks.empty() || blocks.back().size() == W || !(blocks.back().front().size == m.size))
      blocks.emplace_back();
    blocks.back().push_back(std::move(m));
  }
  return scene.overdamped ? run_blocks<false>(scene, schedule, blocks, control, finished)
                          : run_blocks<true>(scene, schedule, blocks, control, finished);
}

SliderResult run_slider_scan(const SliderScene& scene, const SliderScanControl& control) {
  SliderResult result;
  result.timeline = slider_timeline(scene);
  result.members.resize(scene.member_count());
  std::vector<std::size_t> all(scene.member_count());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  result.stopped = run_slider_members(scene, all, control, [&](std::vector<SliderMember>&& block) {
    for (auto& m : block) result.members[m.plan_index] = std::move(m);
  });
  return result;
}

}  // namespace rotorsweep::ensemble
