// The replica statistic of every result file's curves (docs/output.md "Output file"): over the replicas that
// finished, the mean, the population spread (÷ n), the standard error of the mean spread / √(n − 1), min,
// max.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace rotorsweep::ensemble {

struct ReplicaStatistics {
  std::size_t count = 0;                                ///< replicas that finished
  double mean = 0, std = 0, sem = 0, min = 0, max = 0;  ///< NaN where count = 0; sem NaN below 2
};

/// The statistics of value(i) over the i in [0, n) with finished(i).
template <class Value, class Finished>
ReplicaStatistics replica_statistics(std::size_t n, Value&& value, Finished&& finished) {
  ReplicaStatistics s;
  double sum = 0;
  s.min = std::numeric_limits<double>::infinity();
  s.max = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    if (!finished(i)) continue;
    ++s.count;
    sum += value(i);
    s.min = std::min(s.min, value(i));
    s.max = std::max(s.max, value(i));
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (s.count == 0) {
    s.mean = s.std = s.sem = s.min = s.max = nan;
    return s;
  }
  const double count = double(s.count);
  s.mean = sum / count;
  double spread = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (finished(i)) spread += std::pow(value(i) - s.mean, 2) / count;
  s.std = std::sqrt(spread);
  s.sem = s.count > 1 ? s.std / std::sqrt(count - 1) : nan;
  return s;
}

}  // namespace rotorsweep::ensemble
