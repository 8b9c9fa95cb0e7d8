// Member plan of a scene: the Cartesian product variant × A × g × noise × offset × kind × replica in
// that nesting order, so that the members of one curve point (all but replica) are consecutive.
#include "ensemble/rows/member_plan.hpp"

namespace rotorsweep::ensemble {

MemberPlan::MemberPlan(const Scene& scene)
    : scene_(&scene), variants_(scene.variants()), size_(scene.member_count()) {}

Member MemberPlan::operator[](std::size_t index) const {
  const Scene& scene = *scene_;
  std::size_t rest = index;
  const auto digit = [&](std::size_t radix) {
    const std::size_t d = rest % radix;
    rest /= radix;
    return d;
  };
  const auto replica = int(digit(std::size_t(scene.replicas)));
  const InitialKind kind = scene.kinds[digit(scene.kinds.size())];
  const double offset = scene.offset_values[digit(scene.offset_values.size())];
  const double noise = scene.noise_values[digit(scene.noise_values.size())];
  const double g = scene.g_values[digit(scene.g_values.size())];
  const double A = scene.A_values[digit(scene.A_values.size())];
  const std::size_t v = rest;
  return {index,
          std::size_t(replica),
          A,
          g,
          kind,
          replica,
          v,
          variants_[v].rows,
          variants_[v].rtol,
          variants_[v].atol,
          noise,
          offset,
          1.0,
          nullptr};
}

std::vector<Member> plan_members(const Scene& scene) {
  const MemberPlan plan(scene);
  std::vector<Member> members;
  members.reserve(plan.size());
  for (std::size_t i = 0; i < plan.size(); ++i) members.push_back(plan[i]);
  return members;
}

std::vector<Member> shard_members(const std::vector<Member>& plan, std::size_t index, std::size_t count) {
  std::vector<Member> shard;
  for (std::size_t i = index - 1; i < plan.size(); i += count) shard.push_back(plan[i]);
  return shard;
}

std::vector<double> member_initial_angles(const Scene& scene, const Member& member) {
  if (member.start) return *member.start;
  const InitialCondition ic{member.kind, member.noise, member.offset, scene.exact_angles};
  return initial_angles(ic, member.rows, scene.seed, member.stream);
}

}  // namespace rotorsweep::ensemble
