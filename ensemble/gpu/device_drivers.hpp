// Which DeviceMember a row scene runs on the device (docs/architecture.md "Backends"): the row model
// on the double lane (nearest neighbours, or a coupling table), its integrator (a stepper, or Langevin)
// and a stepper's team form (docs/architecture.md "Teams").
#pragma once

#include <type_traits>

#include "ensemble/rows/device_member.hpp"
#include "ensemble/rows/row_models.hpp"
#include "ensemble/rows/scene.hpp"
#include "kernels/models/rows/row_models_on_teams.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/leimkuhler_matthews.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "kernels/steppers/team_rosenbrock.hpp"

namespace rotorsweep::ensemble {

/// The adaptive integrator of the steppers of `family` on Model.
template <kernels::StepperFamily family, class Model>
using DeviceAdaptiveIntegrator = kernels::AdaptiveIntegrator<Model, kernels::family_stepper<family, Model>>;

/// The steppers of `family` on a team of Model (TeamRosenbrock), or void for the explicit family, which
/// has no team form.
template <kernels::StepperFamily family, class Team, class Model>
using DeviceTeamStepper = std::conditional_t<family == kernels::StepperFamily::rosenbrock,
                                             kernels::TeamRosenbrock<Team, Model>, void>;

/// Calls f.template operator()<Model>() with the scene's model (row_models.hpp) on the double lane, among
/// the models with a GPU form (a member per thread and per team; `form`: with the Langevin stepper too).
template <RowModelForm form = RowModelForm::device, class F>
decltype(auto) with_device_model(const Scene& scene, F&& f) {
  return with_double_lane_model<form>(scene.model, std::forward<F>(f));
}

/// Calls f.template operator()<Model, Integrator>() with the scene's model and integrator: the
/// Langevin stepper at T > 0, else the adaptive integrator of the scene's stepper.
template <class F>
decltype(auto) with_device_driver(const Scene& scene, F&& f) {
  if (scene.thermal.on())
    return with_device_model<RowModelForm::device_langevin>(
        scene, [&]<class Model>() { return f.template operator()<Model, kernels::LeimkuhlerMatthews<Model>>(); });
  return with_device_model(scene, [&]<class Model>() {
    return kernels::with_stepper_family(scene.stepper, [&]<kernels::StepperFamily family>() {
      return f.template operator()<Model, DeviceAdaptiveIntegrator<family, Model>>();
    });
  });
}

/// The first-step scale a variant's schedule carries (computed on the host: a GPU's pow may round
/// differently); 0 for the Langevin stepper, which has none.
template <class Integrator>
double device_first_step_scale(const Scene& scene, const Member& variant) {
  if constexpr (Integrator::stochastic)
    return 0.0;
  else
    return Integrator::first_step_scale({variant.rtol, variant.atol},
                                        kernels::stepper_method<typename Integrator::Method>(scene.stepper));
}

}  // namespace rotorsweep::ensemble
