// Test support: one rotor array (a scalar member) set up with FM/AFM initial conditions
// (model.md §2) and run period by period, returning per-period integrals averaged.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "ensemble/initial_conditions.hpp"
#include "kernels/adaptive_integrator.hpp"
#include "kernels/period_driver.hpp"
#include "kernels/row_model.hpp"

namespace rotorsweep::testing {

enum class Start { fm, afm };

/// FM or AFM angles with noise η_j ~ U[-noise, noise], member `member` of seed 7.
inline std::vector<double> initial_angles(std::size_t rows, Start start, double noise = 0.01,
                                          unsigned member = 0) {
  const ensemble::InitialCondition ic{
      start == Start::afm ? ensemble::InitialKind::afm : ensemble::InitialKind::fm, noise, 0.0, {}};
  return ensemble::initial_angles(ic, rows, 7, member);
}

/// Per-period integrals averaged over `average` periods after `relax` periods, per quadrature.
template <kernels::Integrals Q, template <class> class Stepper>
std::array<double, Q.count()> mean_period_integrals(std::size_t rows, double A, double g, Start start,
                                                    int relax, int average, double rtol, double atol) {
  using Model = kernels::NearestNeighbourRows<double, Q>;
  const Model model(rows, A, g);
  kernels::AdaptiveIntegrator<Model, Stepper<Model>> integrator(model, {rtol, atol});
  kernels::LaneState<double> state(rows, Q.count());
  const auto theta = initial_angles(rows, start);
  for (std::size_t j = 0; j < rows; ++j) state.theta[j] = theta[j];
  std::array<double, Q.count()> mean{};
  kernels::run_periods(model, integrator, state, relax + average, [&](int k, const auto& s) {
    if (k < relax) return;
    for (std::size_t p = 0; p < Q.count(); ++p) mean[p] += s.quad[p] / average;
  });
  return mean;
}

}  // namespace rotorsweep::testing
