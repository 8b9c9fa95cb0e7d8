// Test support: one member of the nearest-neighbour rows (docs/model.md §1) integrated over two periods
// from an AFM start by the CPU lanes' AdaptiveIntegrator, the reference for the team and register ones.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "kernels/lanes/angles.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "support/kernel_scratch.hpp"

namespace rotorsweep::testing {

/// The tolerances these comparisons run at.
inline constexpr kernels::Tolerances tight_tolerances{1e-10, 1e-13};

/// An AFM start, rows alternately near 0 and π.
inline std::vector<double> afm_start(std::size_t n) {
  std::vector<double> theta(n);
  for (std::size_t j = 0; j < n; ++j)
    theta[j] = 3.141592653589793 * double(j % 2) + 0.01 * std::sin(1.7 * double(j));
  return theta;
}

/// Where two periods from afm_start end: the angles, the quadratures (R, W, S, ρ̄, H and the moments of
/// R, W, S) and the step attempts.
struct TwoPeriods {
  std::vector<double> theta;
  std::vector<double> quad;
  double steps = 0;
};

/// Two periods of `model` (N = n) on the double lane with `table` at tight_tolerances; `ok` is set to
/// whether the integration finished.
inline TwoPeriods on_lanes(const kernels::NearestNeighbourRows<double>& model, std::size_t n,
                           const kernels::RosenbrockTableau& table, bool& ok) {
  using Model = kernels::NearestNeighbourRows<double>;
  auto integrator =
      built<kernels::AdaptiveIntegrator<Model, kernels::RosenbrockStepper<Model>>, double>(
          model, table, tight_tolerances, kernels::StepLimits{});
  auto state = built<kernels::LaneState<double>, double>(n, Model::max_quadratures);
  const auto theta = afm_start(n);
  for (std::size_t j = 0; j < n; ++j) state.y[j] = theta[j];
  state.t_stop = 2 * kernels::two_pi;
  integrator.advance(model, state);
  ok = state.status[0] == kernels::LaneStatus::ok;
  return {std::vector<double>(state.y, state.y + n), std::vector<double>(state.quad, state.quad + 8),
          state.steps_accepted + state.steps_rejected};
}

}  // namespace rotorsweep::testing
