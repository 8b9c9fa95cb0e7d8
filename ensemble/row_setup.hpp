// How a member of a scene becomes a lane of the row model (docs/model.md §1–2): its initial angles
// from its own stream, and its parameters A, g and the strict-FM mark.
#pragma once

#include <algorithm>
#include <vector>

#include "ensemble/member_plan.hpp"
#include "ensemble/scene.hpp"

namespace rotorsweep::ensemble {

template <class Model>
struct RowSetup {
  const Scene* scene;

  std::vector<double> initial_state(const Member& member) const {
    return member_initial_angles(*scene, member);
  }

  /// A member that starts with all rows equal is marked strict FM (symmetry protection).
  typename Model::Parameters parameters(const Member& member, const std::vector<double>& theta) const {
    const bool strict_fm = std::all_of(theta.begin(), theta.end(), [&](double x) { return x == theta[0]; });
    return {member.A, member.g, strict_fm};
  }
};

}  // namespace rotorsweep::ensemble
