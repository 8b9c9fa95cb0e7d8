// The row problem's steady-state test (docs/scenes.md "Row scenes", key schedule.steady_tol): a member
// has settled once two successive periods' dissipations agree to steady_tol, on CPU lanes and GPU threads
// alike.
#pragma once

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"

namespace rotorsweep::ensemble {

/// Whether two successive periods' dissipations agree: |D_k - D_{k-1}| <= tol · max(|D_k|, |D_{k-1}|).
ROTORSWEEP_HD inline bool dissipations_agree(double before, double now, double tol) {
  const double a = kernels::lane_abs(now), b = kernels::lane_abs(before);
  return kernels::lane_abs(now - before) <= tol * (a < b ? b : a);
}

/// One member's test: each closed period's D against the one before (0 before the first period, which
/// MemberProgress never takes as settled).
struct SteadyDissipation {
  double tol = 0;
  double last = 0;

  /// Takes the period's dissipation D; returns whether it agrees with the period before.
  ROTORSWEEP_HD bool close(double dissipation) {
    const double before = last;
    last = dissipation;
    return dissipations_agree(before, dissipation, tol);
  }
};

}  // namespace rotorsweep::ensemble
