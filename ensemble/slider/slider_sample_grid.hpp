// When a slider member is sampled (docs/model.md §9 "Observables"): its speed's grid of stops, a fixed
// number per substrate period through the start of sliding, with every period boundary on it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "ensemble/slider/slider_scene.hpp"
#include "kernels/lanes/angles.hpp"

namespace rotorsweep::ensemble {

/// The times (scaled) at which the members of one speed stop and are sampled: a grid of
/// `samples_per_period` per period through the start of sliding, from 0 to the end; every period
/// boundary is on it.
struct SliderSampleGrid {
  std::vector<double> stops;
  std::vector<long> index;  ///< samples since the start of sliding (negative during the rest)
  std::size_t samples_per_period;
  std::size_t periods;

  /// The grid of a scene whose speed and end are set (slider_variant).
  explicit SliderSampleGrid(const SliderScene& scene) : samples_per_period(scene.samples_per_period) {
    const SliderUnits units(scene);
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
  /// Whether stop `stop` is a period boundary (the start of sliding or a whole period after it).
  bool boundary(std::size_t stop) const {
    return index[stop] >= 0 && index[stop] % long(samples_per_period) == 0 &&
           std::size_t(index[stop] / long(samples_per_period)) <= periods;
  }
};

}  // namespace rotorsweep::ensemble
