// Expands a scene into its members: variant (N, tolerances) × A × g × noise × offset × initial kind ×
// replica (replica innermost), where noise and offset multiply only the kinds that use them.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "ensemble/rows/scene.hpp"

namespace rotorsweep::ensemble {

/// A rerun completes its primary member's result: a shadow run at tighter tolerances
/// (ensemble/rows/shadow_run.hpp) or the slower rerun at g/10 (ensemble/rows/slip_kinds.hpp).
enum class Rerun { none, shadow, slower, probe };

struct Member {
  std::size_t index = 0;   ///< position in the plan and in the output
  std::size_t stream = 0;  ///< keys the random streams: the replica index, so a member keeps its draw
                           ///< across every other axis (a noise scan rescales the same draw)
  std::size_t point = 0;   ///< its curve point (row of /curves): the members of a point are consecutive
  double A = 0.0;
  double g = 0.0;
  InitialKind kind = InitialKind::afm;
  int replica = 0;
  std::size_t variant = 0;  ///< position in Scene::variants()
  std::size_t rows = 20;
  double rtol = 1e-6, atol = 1e-9;
  double noise = 0.01;  ///< η of its FM/AFM start (the first initial.noise for other kinds)
  double offset = 0.0;  ///< θ0 of its FM/AFM start (the first initial.offset for other kinds)
  /// 1; below 1 for the member's shadow run at tolerances rtol·scale, atol·scale
  /// (ensemble/rows/shadow_run.hpp)
  double tolerance_scale = 1.0;
  /// θ(0) given rather than drawn: a shadow run or a probe starts where its primary's averaged periods began
  std::shared_ptr<const std::vector<double>> start;
  Rerun rerun = Rerun::none;  ///< a plan member, or a rerun of member `index`
};

/// The plan of a scene without holding it: member i is computed from i. A (variant, A, g) block is
/// its first start (noise 0, offset 0) with every kind, then each further (noise, offset) with the
/// kinds that use them (kind_uses_noise); each kind with Scene::replicas_of(kind) replicas.
class MemberPlan {
 public:
  explicit MemberPlan(const Scene& scene);
  std::size_t size() const { return size_; }
  Member operator[](std::size_t index) const;
  /// Curve points (replica groups) of the plan, and the first member of point p (size() for p = count).
  std::size_t point_count() const { return point_count_; }
  std::size_t point_first(std::size_t point) const;
  /// Member i's place on the full grid of Scene::axis_sizes (rows, rtol, A, g, noise, offset, kind,
  /// replica): where a Dataset over all axes puts it.
  std::array<std::size_t, 8> axis_position(std::size_t index) const;

 private:
  /// Member i decoded: its indices on the axes and its curve point.
  struct Position {
    std::size_t variant, A, g, start, kind, replica, point;  ///< start: noise × offset; kind: in Scene::kinds
  };
  Position position(std::size_t index) const;
  std::size_t points_per_block() const;

  const Scene* scene_;
  std::vector<Variant> variants_;
  std::vector<std::size_t>
      noisy_kinds_;                 ///< positions in Scene::kinds of the kinds that use noise and offset
  std::vector<std::size_t> first_;  ///< first member of each kind in a block's first start (K + 1)
  std::size_t replicas_ = 1;
  std::size_t block_ = 0;  ///< members of one (variant, A, g)
  std::size_t size_ = 0, point_count_ = 0;
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
