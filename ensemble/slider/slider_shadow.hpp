// A slider member's shadow run (docs/model.md §9 "Observables"): the member again at tolerances × s,
// whose friction gives friction's error, as a row member's shadow gives D's (docs/numerics.md).
#pragma once

#include <cmath>
#include <limits>

#include "ensemble/engine/shadow_estimate.hpp"
#include "ensemble/slider/slider_sweep.hpp"

namespace rotorsweep::ensemble {

/// Whether a finished member runs its shadow: shadow runs are on and it finished.
inline bool needs_slider_shadow(const SliderScene& scene, const SliderMember& member) {
  return scene.shadow_runs && member.status == "ok";
}

/// The scene a member's shadow runs in: tolerances × shadow_tolerance_scale.
inline SliderScene slider_shadow_scene(SliderScene scene) {
  scene.rtol *= shadow_tolerance_scale;
  scene.atol *= shadow_tolerance_scale;
  return scene;
}

/// Gives `primary` its shadow's friction and friction_error = shadow_error(F, F'): Richardson's estimate
/// for a global error proportional to the tolerance, with a margin; infinite where the shadow failed.
inline void take_slider_shadow(SliderMember& primary, const SliderMember& shadow) {
  const bool finished = shadow.status == "ok";
  primary.friction_shadow = finished ? shadow.friction : std::numeric_limits<double>::quiet_NaN();
  primary.friction_error =
      finished ? shadow_error(primary.friction, shadow.friction) : std::numeric_limits<double>::infinity();
}

}  // namespace rotorsweep::ensemble
