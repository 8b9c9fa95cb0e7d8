// The symmetry probe (docs/numerics.md "Symmetry-limited members"): whether a member's D depends on an
// asymmetry of the rows below the tolerance. Its averaged periods run again with A_j = A (1 + s rtol ξ_j).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "ensemble/rows/disorder.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/shadow_attractor.hpp"

namespace rotorsweep::ensemble {

/// The seed of the probe's substrate deviations ξ_j (realization `replica` of it), apart from any
/// scene's disorder.seed stream by being added to the scene's own deviations.
inline constexpr std::uint64_t probe_disorder_seed = 0x9e3779b97f4a7c15;
/// s: the probe's asymmetry σ_A = s · rtol, below the tolerance, so that D's linear response to it
/// stays well inside the error the tolerance gives D where D converges.
inline constexpr double probe_asymmetry_scale = 0.1;
/// An end state within this (radians, largest row difference) of a symmetric pattern lies on it.
inline constexpr double symmetric_set_tol = 1e-3;

/// Whether the rows' angles θ (at the member's last period end) repeat with a period p < N that
/// divides N (strict FM for p = 1, two sublattices for p = 2, any commensurate pattern), to within
/// symmetric_set_tol; open rows: whether they are mirror-symmetric, θ_j = θ_{N−1−j}. Such sets are
/// invariant under the dynamics of uniform rows (periodic: shifts by p; open: the mirror).
inline bool on_symmetric_set(const std::vector<double>& theta, bool open) {
  const std::size_t n = theta.size();
  const auto apart = [](double x, double y) {
    return std::fabs(std::remainder(x - y, 2 * std::numbers::pi)) > symmetric_set_tol;
  };
  if (open) {
    for (std::size_t j = 0; j < n / 2; ++j)
      if (apart(theta[j], theta[n - 1 - j])) return false;
    return n > 1;
  }
  for (std::size_t p = 1; p < n; ++p) {
    if (n % p != 0) continue;
    bool repeats = true;
    for (std::size_t j = 0; j + p < n && repeats; ++j) repeats = !apart(theta[j], theta[j + p]);
    if (repeats) return true;
  }
  return false;
}

/// Whether a finished member of a scene without a physical perturbation above rtol gets a probe: its
/// averaged periods slip (each escape grows out of the rows' asymmetry), or it ends on a symmetric
/// set (which it leaves, if that set is unstable, only through an asymmetry).
inline bool needs_probe(const MemberResult& result, bool open) {
  return result.status == kernels::LaneStatus::ok &&
         (result.mean(Channel::slips) > 0 || on_symmetric_set(result.theta_final, open));
}

/// The scene's deviations `d` of an array of `rows` rows with the probe's added to A's:
/// δ_j + s rtol ξ_j, ξ_j realization `replica` of probe_disorder_seed.
inline RowDeviations probe_deviations(RowDeviations d, std::size_t rows, int replica, double rtol) {
  Disorder probe;
  probe.A = probe_asymmetry_scale * rtol;
  probe.seed = probe_disorder_seed;
  const std::vector<double> xi = row_deviations(probe, rows, replica).A;
  if (d.A.empty()) d.A.assign(rows, 0.0);
  for (std::size_t j = 0; j < rows; ++j) d.A[j] += xi[j];
  return d;
}

/// Whether the members of a scene's variant of tolerance rtol get probes (needs_probe decides which):
/// shadow runs are on (a deterministic integrator) and no physical perturbation exceeds rtol.
inline bool runs_probes(const Scene& scene, bool stochastic, double rtol) {
  return scene.runs_shadows() && !stochastic && scene.symmetry_limited(rtol);
}

/// The deviations `member` runs with: the scene's realization of its replica, a probe's added.
inline RowDeviations member_deviations(const Disorder& disorder, const Member& member) {
  RowDeviations d = row_deviations(disorder, member.rows, member.replica);
  if (member.rerun != Rerun::probe) return d;
  return probe_deviations(std::move(d), member.rows, member.replica, member.rtol);
}

/// Gives `primary` its probe's D and whether the probe reached its attractor.
inline void take_probe(MemberResult& primary, const MemberResult& probe) {
  const bool finished = probe.status == kernels::LaneStatus::ok;
  primary.dissipation_probe = finished ? probe.dissipation() : std::numeric_limits<double>::quiet_NaN();
  primary.probe_followed = finished && shadow_reached_attractor(primary, probe);
}

/// The verdict once a probed member's reruns have all finished, so that an asymmetry below the
/// tolerance decides D: symmetry-limited where the probe reached another attractor, or where the
/// member slips and the probe moved D by more than D's error (its shadow's included);
/// `symmetry_held` where the member did not slip (held on a symmetric set the probe left). A member
/// without a probe keeps its flags.
inline void settle_symmetry(MemberResult& primary) {
  if (std::isnan(primary.dissipation_probe) && primary.probe_followed) return;  // no probe ran
  const bool slips = primary.slips_per_period() > 0;
  const bool moved = !(std::fabs(primary.dissipation_probe - primary.dissipation()) <= primary.dissipation_error());
  primary.symmetry_limited = !primary.probe_followed || (slips && moved);
  primary.symmetry_held = primary.symmetry_limited && !slips;
}

}  // namespace rotorsweep::ensemble
