// A slider member's results on the host (docs/model.md §9 "Observables"): samples in SI, per-period
// friction (impulse / period), work v·impulse, dissipation, stored energy and their balance.
#include "ensemble/slider/slider_member_summary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "kernels/lanes/angles.hpp"

namespace rotorsweep::ensemble {

namespace {

/// Per period of sliding, the trapezoidal mean of a series over the period's samples (NaN when the
/// member failed).
std::vector<double> period_means(const SliderSampleGrid& grid, const std::vector<double>& series, bool ok) {
  const auto start = std::size_t(std::find(grid.index.begin(), grid.index.end(), 0L) - grid.index.begin());
  const std::size_t per = grid.samples_per_period;
  std::vector<double> means;
  for (std::size_t p = 0; p < grid.periods; ++p) {
    const std::size_t first = start + p * per;
    double sum = 0.5 * (series[first] + series[first + per]);
    for (std::size_t k = first + 1; k < first + per; ++k) sum += series[k];
    means.push_back(ok ? sum / double(per) : std::nan(""));
  }
  return means;
}

/// The series of sums over the rotors with whether the scene asks for each (SliderScene::energies,
/// field, sublattices), in record_slider_rotor_sums' order.
std::array<std::pair<bool, std::vector<double>*>, 10> rotor_series(SliderMember& m,
                                                                   const SliderScene& scene) {
  const bool e = scene.energies, f = scene.field, s = scene.sublattices;
  return {{{e, &m.substrate_energy_series},
           {e, &m.pair_energy_series},
           {f, &m.field_axis_series},
           {f, &m.field_z_series},
           {s, &m.moment_axis_even_series},
           {s, &m.moment_z_even_series},
           {s, &m.torque_even_series},
           {s, &m.moment_axis_odd_series},
           {s, &m.moment_z_odd_series},
           {s, &m.torque_odd_series}}};
}

}  // namespace

void size_slider_series(SliderMember& m, const SliderScene& scene, std::size_t samples) {
  const std::size_t rotors = m.size.rotors();
  for (auto* series : {&m.friction_series, &m.order_x_series, &m.order_y_series, &m.energy_series})
    series->assign(samples, 0.0);
  if (scene.angles) m.angles.assign(samples * rotors, 0.0);
  for (const auto& [asked, series] : rotor_series(m, scene))
    if (asked) series->assign(samples, 0.0);
  if (scene.torques) m.torques.assign(samples * rotors, 0.0);
  if (scene.forces)
    for (auto* series : {&m.force_x_series, &m.force_y_series, &m.force_z_series})
      series->assign(samples, 0.0);
}

void record_slider_rotor_sums(SliderMember& m, std::size_t k, const SliderRotorSums& sums,
                              const SliderScene& scene) {
  const SliderUnits units(scene);
  // μB in units of μ0 m_sub/(4π a³) times m_sub/m: B = μB · μ0 m/(4π a³), in T
  const double tesla = 1e-7 * scene.moment / std::pow(scene.spacing, 3), n = double(m.size.rotors());
  const std::array<double, 2> count{double(m.size.columns * ((m.size.rows + 1) / 2)),
                                    double(m.size.columns * (m.size.rows / 2))};
  const auto mean = [&](double sum, std::size_t parity) {
    return count[parity] ? sum / count[parity] : std::nan("");  // a one-row slider has no odd rows
  };
  const std::array<double, 10> values{sums.substrate * units.energy,
                                      sums.pairs * units.energy,
                                      sums.field_axis / n * tesla,
                                      sums.field_z / n * tesla,
                                      mean(sums.moment_axis[0], 0),
                                      mean(sums.moment_z[0], 0),
                                      mean(sums.torque[0], 0) * units.energy,
                                      mean(sums.moment_axis[1], 1),
                                      mean(sums.moment_z[1], 1),
                                      mean(sums.torque[1], 1) * units.energy};
  const auto series = rotor_series(m, scene);
  for (std::size_t v = 0; v < series.size(); ++v)
    if (series[v].first) (*series[v].second)[k] = values[v];
}

void record_slider_forces(SliderMember& m, std::size_t k, const std::array<double, 3>& force,
                          const SliderUnits& units) {
  m.force_x_series[k] = force[0] * units.force;
  m.force_y_series[k] = force[1] * units.force;
  m.force_z_series[k] = force[2] * units.force;
}

void record_slider_sample(SliderMember& m, std::size_t k, const SliderSample& sample,
                          const SliderUnits& units) {
  m.friction_series[k] = sample.force * units.force;
  m.order_x_series[k] = sample.order_x;
  m.order_y_series[k] = sample.order_y;
  m.energy_series[k] = sample.energy * units.energy;
}

void summarize_slider_member(const SliderScene& scene, const SliderSampleGrid& grid,
                             const SliderBoundaries& at, bool ok, SliderMember& m) {
  const SliderUnits units(scene);
  const double nan = std::nan("");
  const double speed = 1.0 / kernels::two_pi, period = kernels::two_pi;
  for (std::size_t p = 0; p < grid.periods; ++p) {
    if (!ok) {
      for (auto* values :
           {&m.period_friction, &m.period_work, &m.period_dissipation, &m.period_stored, &m.period_balance})
        values->push_back(nan);
      continue;
    }
    const double impulse = at.impulse[p + 1] - at.impulse[p];
    const double work = speed * impulse, dissipated = at.dissipation[p + 1] - at.dissipation[p];
    const double stored = at.energy[p + 1] - at.energy[p];
    m.period_friction.push_back(impulse / period * units.force);
    m.period_work.push_back(work * units.energy);
    m.period_dissipation.push_back(dissipated * units.energy);
    m.period_stored.push_back(stored * units.energy);
    m.period_balance.push_back((work - dissipated - stored) /
                               std::max({std::fabs(work), std::fabs(dissipated), 1e-300}));
  }
  const std::size_t first = grid.periods > 0 ? scene.averaging_start(grid.periods) : 0;
  m.friction = ok && grid.periods > first ? (at.impulse[grid.periods] - at.impulse[first]) /
                                                (period * double(grid.periods - first)) * units.force
                                          : nan;
  double sum_x = 0.0, sum_y = 0.0;
  std::size_t count = 0;
  for (std::size_t k = 0; k < grid.stops.size(); ++k) {
    if (grid.index[k] <= long(first * grid.samples_per_period)) continue;
    sum_x += m.order_x_series[k];
    sum_y += m.order_y_series[k];
    ++count;
  }
  m.order_x = ok && count ? sum_x / double(count) : nan;
  m.order_y = ok && count ? sum_y / double(count) : nan;
  if (scene.forces) {
    m.period_force_y = period_means(grid, m.force_y_series, ok);
    m.period_force_z = period_means(grid, m.force_z_series, ok);
  }
}

void pad_to_timeline(SliderMember& m, std::size_t samples) {
  const std::size_t missing = samples - m.friction_series.size(), rotors = m.size.rotors();
  if (missing == 0) return;
  for (auto* series : {&m.friction_series, &m.order_x_series, &m.order_y_series, &m.energy_series,
                       &m.substrate_energy_series, &m.pair_energy_series, &m.field_axis_series,
                       &m.field_z_series, &m.moment_axis_even_series, &m.moment_z_even_series,
                       &m.torque_even_series, &m.moment_axis_odd_series, &m.moment_z_odd_series,
                       &m.torque_odd_series, &m.force_x_series, &m.force_y_series, &m.force_z_series})
    if (!series->empty()) series->insert(series->begin(), missing, std::nan(""));
  for (auto* per_rotor : {&m.angles, &m.torques})
    if (!per_rotor->empty()) per_rotor->insert(per_rotor->begin(), missing * rotors, std::nan(""));
}

}  // namespace rotorsweep::ensemble
