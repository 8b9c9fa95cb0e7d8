// Member plan of a scene: the Cartesian product A × g × kind × replica in that nesting order,
// so that the members of one (A, g, kind) point are consecutive.
#include "ensemble/member_plan.hpp"

namespace rotorsweep::ensemble {

std::vector<Member> plan_members(const Scene& scene) {
  std::vector<Member> members;
  members.reserve(scene.member_count());
  for (double A : scene.A_values)
    for (double g : scene.g_values)
      for (InitialKind kind : scene.kinds)
        for (int replica = 0; replica < scene.replicas; ++replica)
          members.push_back({members.size(), A, g, kind, replica});
  return members;
}

std::vector<double> member_initial_angles(const Scene& scene, const Member& member) {
  const InitialCondition ic{member.kind, scene.noise, scene.offset, scene.exact_angles};
  return initial_angles(ic, scene.rows, scene.seed, member.index);
}

}  // namespace rotorsweep::ensemble
