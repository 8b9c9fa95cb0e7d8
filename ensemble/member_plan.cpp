// Member plan of a scene: the Cartesian product variant × A × g × noise × offset × kind × replica in
// that nesting order, so that the members of one curve point (all but replica) are consecutive.
#include "ensemble/member_plan.hpp"

#include <algorithm>

#include "ensemble/member_result.hpp"

namespace rotorsweep::ensemble {

std::vector<Member> plan_members(const Scene& scene) {
  std::vector<Member> members;
  members.reserve(scene.member_count());
  const auto variants = scene.variants();
  for (std::size_t v = 0; v < variants.size(); ++v)
    for (double A : scene.A_values)
      for (double g : scene.g_values)
        for (double noise : scene.noise_values)
          for (double offset : scene.offset_values)
            for (InitialKind kind : scene.kinds)
              for (int replica = 0; replica < scene.replicas; ++replica)
                members.push_back({members.size(), std::size_t(replica), A, g, kind, replica, v,
                                   variants[v].rows, variants[v].rtol, variants[v].atol, noise, offset});
  return members;
}

std::vector<Member> shard_members(const std::vector<Member>& plan, std::size_t index, std::size_t count) {
  std::vector<Member> shard;
  for (std::size_t i = index - 1; i < plan.size(); i += count) shard.push_back(plan[i]);
  return shard;
}

double plan_memory_bytes(const Scene& scene) {
  const double rows = double(scene.max_rows());
  const double columns = 2 * 8 * rows + 8 * 64;  // written copies of the angles and scalar columns
  const int periods = std::max(scene.max_periods, scene.relax_periods + scene.average_periods);
  const double series = scene.period_series ? double(periods) * 2 * sizeof(PeriodRecord) : 0.0;
  const double per_member = sizeof(Member) + sizeof(MemberResult) + 2 * 8 * rows + columns + series;
  double count = 1;
  for (std::size_t n : scene.axis_sizes()) count *= double(n);
  return count * per_member;
}

std::vector<double> member_initial_angles(const Scene& scene, const Member& member) {
  const InitialCondition ic{member.kind, member.noise, member.offset, scene.exact_angles};
  return initial_angles(ic, member.rows, scene.seed, member.stream);
}

}  // namespace rotorsweep::ensemble
