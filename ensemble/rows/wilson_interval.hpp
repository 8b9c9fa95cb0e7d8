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

/// (p̂ + z²/2n ± z √(p̂(1 − p̂)/n + z²/4n²)) / (1 + z²/n), p̂ = k/n; NaN for n = 0. The bounds always
/// bracket p̂ and are exactly 0 at k = 0 and exactly 1 at k = n (where the closed form gives them
/// only to rounding, e.g. 3.5e-18 for 0 of 100).
inline Interval wilson_interval(std::size_t k, std::size_t n, double z = 1.959963984540054) {
  if (n == 0) return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  const double N = double(n), p = double(k) / N, z2 = z * z;
  const double centre = (p + z2 / (2 * N)) / (1 + z2 / N);
  const double half = z / (1 + z2 / N) * std::sqrt(p * (1 - p) / N + z2 / (4 * N * N));
  const double low = k == 0 ? 0.0 : std::min(p, std::max(0.0, centre - half));
  const double high = k == n ? 1.0 : std::max(p, std::min(1.0, centre + half));
  return {low, high};
}

}  // namespace rotorsweep::ensemble
