// Final-state classification: circular sublattice means, deviations, domain walls, detached rows
// and the orbit's period from the end-of-period states (rules in final_state.hpp); each angle's sine
// and cosine taken once.
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

/// A state's sines and cosines, each taken once, and their sums over the even and odd rows (in row
/// order) that give the sublattices' circular means.
struct StateTrig {
  std::vector<double> sines, cosines;
  double s[2] = {0, 0}, c[2] = {0, 0};

  explicit StateTrig(const std::vector<double>& theta) : sines(theta.size()), cosines(theta.size()) {
    for (std::size_t j = 0; j < theta.size(); ++j) {
      const double sine = std::sin(theta[j]), cosine = std::cos(theta[j]);
      sines[j] = sine;
      cosines[j] = cosine;
      s[j % 2] += sine;
      c[j % 2] += cosine;
    }
  }
  double even_mean() const { return std::atan2(s[0], c[0]); }
  double odd_mean() const { return std::atan2(s[1], c[1]); }
};

double largest_deviation(const std::vector<double>& theta, const StateTrig& trig) {
  const double even = trig.even_mean(), odd = trig.odd_mean();
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
  for (std::size_t e = 0; e + 1 < end_states.size(); ++e)
    f.sublattice_deviation =
        std::max(f.sublattice_deviation, largest_deviation(end_states[e], StateTrig(end_states[e])));
  const StateTrig trig(last);
  f.sublattice_deviation = std::max(f.sublattice_deviation, largest_deviation(last, trig));
  f.sublattice_even = kernels::wrap_2pi(trig.even_mean());
  f.sublattice_odd = kernels::wrap_2pi(trig.odd_mean());
  // a row is detached when it is far from the circular mean of the other rows of its sublattice
  for (std::size_t j = 0; j < n; ++j) {
    const double others = std::atan2(trig.s[j % 2] - trig.sines[j], trig.c[j % 2] - trig.cosines[j]);
    f.detached_rows += std::fabs(centred(last[j] - others)) > detached_angle;
  }
  // link j joins rows j and j + 1; a wall lies between an aligned and an anti-aligned link
  std::vector<char> aligned(n);
  for (std::size_t j = 0; j < n; ++j) aligned[j] = std::cos(last[j] - last[(j + 1) % n]) > 0;
  int changes = 0;
  for (std::size_t j = 0; j < n; ++j) changes += aligned[j] != aligned[(j + 1) % n];
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
