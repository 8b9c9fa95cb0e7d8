// Final-state classification: circular sublattice means, deviations, domain walls, detached rows
// and the orbit's period from the end-of-period states (rules in final_state.hpp).
#include "ensemble/rows/final_state.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernels/lanes/angles.hpp"

namespace rotorsweep::ensemble {

namespace {

/// x reduced to (−π, π].
double centred(double x) {
  const double w = kernels::wrap_2pi(x);
  return w > std::numbers::pi ? w - 2 * std::numbers::pi : w;
}

/// Circular means of the even and odd rows.
std::pair<double, double> sublattice_means(const std::vector<double>& theta) {
  double s[2] = {0, 0}, c[2] = {0, 0};
  for (std::size_t j = 0; j < theta.size(); ++j) {
    s[j % 2] += std::sin(theta[j]);
    c[j % 2] += std::cos(theta[j]);
  }
  return {std::atan2(s[0], c[0]), std::atan2(s[1], c[1])};
}

double largest_deviation(const std::vector<double>& theta) {
  const auto [even, odd] = sublattice_means(theta);
  double worst = 0;
  for (std::size_t j = 0; j < theta.size(); ++j)
    worst = std::max(worst, std::fabs(centred(theta[j] - (j % 2 ? odd : even))));
  return worst;
}

}  // namespace

FinalState classify_final_state(const std::vector<std::vector<double>>& end_states,
                                const std::string& regime) {
  FinalState f;
  const auto& last = end_states.back();
  const std::size_t n = last.size();
  for (const auto& theta : end_states)
    f.sublattice_deviation = std::max(f.sublattice_deviation, largest_deviation(theta));
  const auto [even, odd] = sublattice_means(last);
  f.sublattice_even = kernels::wrap_2pi(even);
  f.sublattice_odd = kernels::wrap_2pi(odd);
  // a row is detached when it is far from the circular mean of the other rows of its sublattice
  double s[2] = {0, 0}, c[2] = {0, 0};
  for (std::size_t j = 0; j < n; ++j) {
    s[j % 2] += std::sin(last[j]);
    c[j % 2] += std::cos(last[j]);
  }
  for (std::size_t j = 0; j < n; ++j) {
    const double others = std::atan2(s[j % 2] - std::sin(last[j]), c[j % 2] - std::cos(last[j]));
    f.detached_rows += std::fabs(centred(last[j] - others)) > detached_angle;
  }
  int changes = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const bool aligned = std::cos(last[j] - last[(j + 1) % n]) > 0;
    const bool next_aligned = std::cos(last[(j + 1) % n] - last[(j + 2) % n]) > 0;
    changes += aligned != next_aligned;
  }
  f.domain_walls = changes / 2;
  // clusters on the circle: sort, split at gaps wider than group_gap (the wrap-around gap included)
  std::vector<double> sorted(n);
  for (std::size_t j = 0; j < n; ++j) sorted[j] = kernels::wrap_2pi(last[j]);
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> sizes;
  std::size_t start = 0;
  for (std::size_t j = 1; j <= n; ++j)
    if (j == n || sorted[j] - sorted[j - 1] > group_gap) {
      sizes.push_back(int(j - start));
      start = j;
    }
  if (sizes.size() > 1 && sorted.front() + 2 * std::numbers::pi - sorted.back() <= group_gap) {
    sizes.front() += sizes.back();  // the first and last clusters meet across 0 = 2π
    sizes.pop_back();
  }
  f.angle_groups = int(sizes.size());
  std::sort(sizes.rbegin(), sizes.rend());
  for (std::size_t k = 2; k < sizes.size(); ++k) f.stray_rows += sizes[k];
  for (int p = 1; p <= 3 && f.orbit_period == 0; ++p) {
    if (end_states.size() < std::size_t(p) + 1) break;
    const auto& before = end_states[end_states.size() - 1 - std::size_t(p)];
    double worst = 0;
    for (std::size_t j = 0; j < n; ++j) worst = std::max(worst, std::fabs(centred(last[j] - before[j])));
    if (worst < orbit_tol) f.orbit_period = p;
  }
  std::string structure;
  if (f.sublattice_deviation < two_sublattice_tol)
    structure = "2SL";
  else if (f.domain_walls > 0)
    structure = "walls" + std::to_string(f.domain_walls);
  else if (f.detached_rows > 0)
    structure = "detached" + std::to_string(f.detached_rows);
  else
    structure = "other";
  f.attractor = regime + ":" + structure + ":p" + std::to_string(f.orbit_period);
  return f;
}

}  // namespace rotorsweep::ensemble
