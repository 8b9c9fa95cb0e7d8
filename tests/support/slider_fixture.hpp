// Test support: the slider model at the experiment's values (scaled units, docs/model.md §9), a substrate
// lattice centred under a grid with its field table over the path, and random states.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <random>
#include <vector>

#include "kernels/lanes/angles.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "support/kernel_scratch.hpp"

namespace rotorsweep::testing::slider_fixture {

using namespace rotorsweep::kernels;

// The experiment's values in the scaled units of docs/model.md §9 (a = 16 mm, v = 8 mm/s):
// I = 7.48e-10 kg m², γ = 2.5e-6 kg m²/s, m = 4.57e-2 A m², m_sub = 5.03e-2 A m².
constexpr double energy_unit = 1e-7 * 4.57e-2 * 4.57e-2 / (0.016 * 0.016 * 0.016);
constexpr double time_unit = 0.016 / (two_pi * 0.008);
constexpr double inertia = 7.48e-10 / (energy_unit * time_unit * time_unit);
constexpr double damping = 2.5e-6 / (energy_unit * time_unit);
constexpr double moment_ratio = 5.03e-2 / 4.57e-2;
constexpr double speed = 1.0 / two_pi;

/// A substrate under a slider of `columns` × `rows`, centred, with its table over the slider's path.
struct Substrate {
  SubstrateLattice lattice;
  SubstrateTable table;
  Substrate(SliderGrid grid, double eta, std::size_t size = 35, const SliderPlacement& placement = {},
            double angle = 0.0)
      : lattice{size,
                size,
                0.5 * double(grid.columns - 1) - 0.5 * double(size - 1),
                0.5 * double(grid.rows - 1) - 0.5 * double(size - 1),
                eta,
                angle},
        table(lattice, placement.track_y(grid), start_x_range(grid, placement)[0] - 0.5,
              start_x_range(grid, placement)[1] + 5.5, eta / 32.0, placement.tilt) {}

  /// The smallest and largest x of the rotors at ξ = 0.
  static std::array<double, 2> start_x_range(SliderGrid grid, const SliderPlacement& placement) {
    std::array<double, 2> range{placement.start_x(0, 0), placement.start_x(0, 0)};
    for (std::size_t j = 0; j < grid.rows; ++j)
      for (std::size_t i = 0; i < grid.columns; ++i) {
        range[0] = std::min(range[0], placement.start_x(i, j));
        range[1] = std::max(range[1], placement.start_x(i, j));
      }
    return range;
  }
};

template <class Model>
Model make_model(SliderGrid grid, const typename Model::Parameters& p,
                 const SliderPlacement& placement = {}) {
  auto arena = rotorsweep::testing::scratch<typename Model::lane_type>(Model::storage_size(grid));
  Model m(grid, placement, arena);
  for (std::size_t l = 0; l < lane_width<typename Model::lane_type>; ++l) m.set_lane(l, p);
  return m;
}

inline std::vector<double> random_state(std::size_t n, unsigned seed, double velocity_scale) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), velocity(-1.0, 1.0);
  std::vector<double> y(n);
  for (std::size_t k = 0; k < n; ++k)
    y[k] = k < n / 2 || velocity_scale == 0.0 ? angle(rng) : velocity_scale * velocity(rng);
  return y;
}

/// A model's parameters over a substrate (its table), resting until `rest`.
template <class Model>
typename Model::Parameters parameters(const Substrate& s, double rest = 0.0) {
  return {s.table.view(), moment_ratio, inertia, damping, speed, rest};
}

}  // namespace rotorsweep::testing::slider_fixture
