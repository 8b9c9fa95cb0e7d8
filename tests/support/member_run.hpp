// Test support: one rotor array (a scalar member) set up with FM/AFM initial conditions
// (model.md §2) and run period by period, returning per-period integrals averaged.
#pragma once

#include <array>
#include <cstddef>
#include <numbers>
#include <random>
#include <vector>

#include "kernels/adaptive_integrator.hpp"
#include "kernels/period_driver.hpp"
#include "kernels/row_model.hpp"

namespace rotorsweep::testing {

enum class Start { fm, afm };

/// θ_j = π·(j mod 2 for AFM) + η_j, η_j ~ U[-noise, noise] from a fixed seed.
inline std::vector<double> initial_angles(std::size_t rows, Start start, double noise = 0.01,
                                          unsigned seed = 7) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> eta(-noise, noise);
  std::vector<double> theta(rows);
  for (std::size_t j = 0; j < rows; ++j)
    theta[j] = (start == Start::afm && j % 2 == 1 ? std::numbers::pi : 0.0) + eta(rng);
  return theta;
}

/// Per-period integrals averaged over `average` periods after `relax` periods, per quadrature.
template <kernels::Integrals Q, template <class> class Stepper>
std::array<double, Q.count()> mean_period_integrals(std::size_t rows, double A, double g, Start start,
                                                    int relax, int average, double rtol,
                                                    double atol) {
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
