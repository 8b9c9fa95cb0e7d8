// Expands a scene into its members: the Cartesian product variant (N, tolerances) × A × g × noise ×
// offset × initial kind × replica (replica innermost); a member's random stream is its replica.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "ensemble/rows/scene.hpp"

namespace rotorsweep::ensemble {

struct Member {
  std::size_t index = 0;   ///< position in the plan and in the output
  std::size_t stream = 0;  ///< keys the random streams: the replica index, so a member keeps its draw
                           ///< across every other axis (a noise scan rescales the same draw)
  double A = 0.0;
  double g = 0.0;
  InitialKind kind = InitialKind::afm;
  int replica = 0;
  std::size_t variant = 0;  ///< position in Scene::variants()
  std::size_t rows = 20;
  double rtol = 1e-6, atol = 1e-9;
  double noise = 0.01;  ///< η of its FM/AFM start
  double offset = 0.0;  ///< θ0 of its FM/AFM start
  /// 1; below 1 for the member's shadow run at tolerances rtol·scale, atol·scale
  /// (ensemble/engine/shadow_run.hpp)
  double tolerance_scale = 1.0;
  /// θ(0) given rather than drawn: a shadow run starts where its primary's averaged periods began
  std::shared_ptr<const std::vector<double>> start;
};

/// The plan of a scene without holding it: member i is computed from i (mixed radix over the axes).
class MemberPlan {
 public:
  explicit MemberPlan(const Scene& scene);
  std::size_t size() const { return size_; }
  Member operator[](std::size_t index) const;

 private:
  const Scene* scene_;
  std::vector<Variant> variants_;
  std::size_t size_ = 0;
};

/// Every member of the plan, in order.
std::vector<Member> plan_members(const Scene& scene);

/// Part `index` (1-based) of `count` of a plan: the members whose plan index is index − 1 modulo
/// count, so that every shard holds every kind of member and they cost about the same.
std::vector<Member> shard_members(const std::vector<Member>& plan, std::size_t index, std::size_t count);

/// θ(0) of a member: its kind with its noise and offset and the scene's angles, drawn from the
/// stream (scene seed, member.stream); or member.start where that is given.
std::vector<double> member_initial_angles(const Scene& scene, const Member& member);

}  // namespace rotorsweep::ensemble
