// The Wilson score interval of a binomial fraction (docs/model.md §3, "Basin fractions"): the 95 %
// confidence interval of k successes in n trials, sensible also at k = 0 and k = n.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace rotorsweep::ensemble {

struct Interval {
  double low, high;
};

/// (p̂ + z²/2n ± z √(p̂(1 − p̂)/n + z²/4n²)) / (1 + z²/n), p̂ = k/n; NaN for n = 0.
inline Interval wilson_interval(std::size_t k, std::size_t n, double z = 1.959963984540054) {
  if (n == 0) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  const double N = double(n), p = double(k) / N, z2 = z * z;
  const double centre = (p + z2 / (2 * N)) / (1 + z2 / N);
  const double half = z / (1 + z2 / N) * std::sqrt(p * (1 - p) / N + z2 / (4 * N * N));
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

}  // namespace rotorsweep::ensemble
