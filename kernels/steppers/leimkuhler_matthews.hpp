// Overdamped Langevin dynamics of a block of lanes at temperature T (docs/model.md §7, docs/numerics.md
// "Temperature"): the Leimkuhler–Matthews scheme (LangevinSteps) over LaneMemberForm, a member per lane.
#pragma once

#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/lane_member_form.hpp"
#include "kernels/steppers/langevin_steps.hpp"
#include "kernels/steppers/model_concept.hpp"

namespace rotorsweep::kernels {

/// LangevinSteps for a block of lanes: attempt(model, state), start_lane(lane, key, g, κ).
template <LaneModel Model>
class LeimkuhlerMatthews : public LangevinSteps<LaneMemberForm<Model>> {
 public:
  using V = typename Model::lane_type;

  ROTORSWEEP_HD LeimkuhlerMatthews(const Model& model, LangevinSettings settings, LaneArena<V>& arena)
      : LangevinSteps<LaneMemberForm<Model>>(model.dimension(), settings, arena, model) {}
};

}  // namespace rotorsweep::kernels
