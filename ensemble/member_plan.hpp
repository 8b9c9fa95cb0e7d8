// Expands a scene into its members: the Cartesian product variant (N, tolerances) × A × g ×
// initial kind × replica (replica innermost), each with its index, which keys its random stream.
#pragma once

#include <cstddef>
#include <vector>

#include "ensemble/scene.hpp"

namespace rotorsweep::ensemble {

struct Member {
  std::size_t index = 0;   ///< position in the plan and in the output
  std::size_t stream = 0;  ///< position within its variant: keys the random stream, so the same
                           ///< member under another N or tolerance starts from the same draw
  double A = 0.0;
  double g = 0.0;
  InitialKind kind = InitialKind::afm;
  int replica = 0;
  std::size_t variant = 0;  ///< position in Scene::variants()
  std::size_t rows = 20;
  double rtol = 1e-6, atol = 1e-9;
};

std::vector<Member> plan_members(const Scene& scene);

/// Bytes a run of the whole plan holds at its peak, as an estimate: per member its Member and
/// MemberResult, its initial and final angles, the columns being written and, with
/// period_series, every period record of the longest schedule.
double plan_memory_bytes(const Scene& scene);

/// θ(0) of a member: its kind with the scene's noise, offset and angles, drawn from the
/// stream (scene seed, member.stream).
std::vector<double> member_initial_angles(const Scene& scene, const Member& member);

}  // namespace rotorsweep::ensemble
