// Expands a scene into its members: the Cartesian product A × g × initial kind × replica
// (replica innermost), each with its index, the key of its random stream (model.md §2).
#pragma once

#include <cstddef>
#include <vector>

#include "ensemble/scene.hpp"

namespace rotorsweep::ensemble {

struct Member {
  std::size_t index = 0;  ///< position in the plan and in the output; keys the random stream
  double A = 0.0;
  double g = 0.0;
  InitialKind kind = InitialKind::afm;
  int replica = 0;
};

std::vector<Member> plan_members(const Scene& scene);

/// θ(0) of a member: its kind with the scene's noise, offset and angles, drawn from the
/// stream (scene seed, member index).
std::vector<double> member_initial_angles(const Scene& scene, const Member& member);

}  // namespace rotorsweep::ensemble
