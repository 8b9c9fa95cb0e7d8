// Member plan of a scene: variant × A × g × noise × offset × kind × replica in that nesting order,
// noise and offset only for the kinds that use them, so the members of one curve point are consecutive.
#include "ensemble/rows/member_plan.hpp"

#include <algorithm>

namespace rotorsweep::ensemble {

MemberPlan::MemberPlan(const Scene& scene)
    : scene_(&scene), variants_(scene.variants()), replicas_(std::size_t(scene.replicas)) {
  first_.push_back(0);
  for (std::size_t k = 0; k < scene.kinds.size(); ++k) {
    first_.push_back(first_.back() + scene.replicas_of(scene.kinds[k]));
    if (kind_uses_noise(scene.kinds[k])) noisy_kinds_.push_back(k);
  }
  const std::size_t further_starts = scene.noise_values.size() * scene.offset_values.size() - 1;
  block_ = first_.back() + further_starts * noisy_kinds_.size() * replicas_;
  const std::size_t blocks = variants_.size() * scene.A_values.size() * scene.g_values.size();
  size_ = blocks * block_;
  point_count_ = blocks * points_per_block();
}

std::size_t MemberPlan::points_per_block() const {
  const Scene& scene = *scene_;
  return scene.kinds.size() +
         (scene.noise_values.size() * scene.offset_values.size() - 1) * noisy_kinds_.size();
}

std::size_t MemberPlan::point_first(std::size_t point) const {
  const std::size_t per_block = points_per_block(), block = point / per_block, q = point % per_block;
  const std::size_t kinds = scene_->kinds.size();
  if (q < kinds) return block * block_ + first_[q];
  const std::size_t j = q - kinds;
  return block * block_ + first_.back() + j * replicas_;
}

MemberPlan::Position MemberPlan::position(std::size_t index) const {
  const Scene& scene = *scene_;
  Position at{};
  std::size_t rest = index / block_;
  const std::size_t within = index % block_, kinds = scene.kinds.size();
  if (within < first_.back()) {
    at.kind = std::size_t(std::upper_bound(first_.begin(), first_.end(), within) - first_.begin()) - 1;
    at.replica = within - first_[at.kind];
    at.point = at.kind;
  } else {
    const std::size_t j = within - first_.back(), segment = noisy_kinds_.size() * replicas_;
    at.start = 1 + j / segment;
    const std::size_t k = (j % segment) / replicas_;
    at.kind = noisy_kinds_[k];
    at.replica = j % replicas_;
    at.point = kinds + (at.start - 1) * noisy_kinds_.size() + k;
  }
  at.point += rest * points_per_block();
  at.g = rest % scene.g_values.size();
  rest /= scene.g_values.size();
  at.A = rest % scene.A_values.size();
  at.variant = rest / scene.A_values.size();
  return at;
}

std::array<std::size_t, 8> MemberPlan::axis_position(std::size_t index) const {
  const Position at = position(index);
  const std::size_t tolerances = scene_->rtol_values.size(), offsets = scene_->offset_values.size();
  return {at.variant / tolerances, at.variant % tolerances, at.A,    at.g,
          at.start / offsets,      at.start % offsets,      at.kind, at.replica};
}

Member MemberPlan::operator[](std::size_t index) const {
  const Scene& scene = *scene_;
  const Position at = position(index);
  const Variant& variant = variants_[at.variant];
  const std::size_t offsets = scene.offset_values.size();
  return {index,
          at.replica,
          at.point,
          scene.A_values[at.A],
          scene.g_values[at.g],
          scene.kinds[at.kind],
          int(at.replica),
          at.variant,
          variant.rows,
          variant.rtol,
          variant.atol,
          scene.noise_values[at.start / offsets],
          scene.offset_values[at.start % offsets],
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
