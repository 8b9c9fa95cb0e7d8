// Per-point statistics of a sweep (/curves of the output): for each (N, rtol, A, g, noise, offset, kind),
// count, mean, spread and range of D over its replicas, and the fraction in each regime.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"

namespace rotorsweep::ensemble {

struct CurvePoint {
  std::size_t index = 0;  ///< the point's position in the plan (row of /curves)
  std::size_t rows = 0;
  double rtol = 0;
  double A = 0, g = 0;
  InitialKind kind = InitialKind::afm;
  double noise = 0, offset = 0;
  std::size_t members = 0;     ///< replicas at this point (Scene::replicas_of its kind)
  std::size_t count = 0;       ///< of them, members that finished with status ok (the statistics use these)
  std::size_t unresolved = 0;  ///< of those, members whose D is not resolved (dissipation_resolved)
  double dissipation_mean = 0, dissipation_std = 0, dissipation_min = 0, dissipation_max = 0;
  double dissipation_sem = 0;  ///< standard error of dissipation_mean: sample spread / √count (NaN for one)
  /// Bound on the integration's bias of dissipation_mean: the mean of the members' dissipation_error
  double dissipation_bias = 0;
  std::size_t symmetry_limited = 0;  ///< members of count whose D an asymmetry below rtol decides
  std::size_t symmetry_held = 0;     ///< of those, members held on a symmetric set without slipping
  std::size_t shadow_departed = 0;   ///< members of count whose shadow run reached another attractor
  /// Members of the point in each regime (all_regimes order; finished members only) and failed.
  std::array<std::size_t, std::size(all_regimes)> regime_count{};
  std::size_t failed = 0;
  std::map<std::string, std::size_t> attractor_count;  ///< members per attractor label (failed included)
};

/// One point per run of consecutive members with the same Member::point (its replicas), in order.
std::vector<CurvePoint> aggregate_curves(const std::vector<Member>& members,
                                         const std::vector<MemberResult>& results);

}  // namespace rotorsweep::ensemble
