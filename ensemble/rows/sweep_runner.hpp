// The compile-time side of run_members: picks the lane type and the row model a scene needs, and
// runs lane schedulers of that instantiation on OpenMP threads.
#pragma once

#include <optional>
#include <type_traits>

#include "ensemble/engine/compile_time_choice.hpp"
#include "ensemble/engine/lane_groups.hpp"
#include "ensemble/engine/lane_scheduler.hpp"
#include "ensemble/rows/row_models.hpp"
#include "ensemble/rows/row_problem.hpp"
#include "ensemble/rows/row_setup.hpp"
#include "ensemble/rows/sweep.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

/// Runs the members of `range` (one variant) on the control's threads, a lane scheduler each
/// (run_lane_groups: positions through the control's claim or one shared counter, an exception in
/// one thread, an allocation that fails, stops the others).
template <class Model, class Integrator, class Setup>
SweepOutcome run_lane_schedulers(const Scene& scene, const VariantRange& range, const Setup& setup,
                                 const RunControl& control, const ResultSink& sink) {
  const Member variant = range.source->at(range.begin);
  SweepOutcome outcome;
  static_cast<RunOutcome&>(outcome) = run_lane_groups(
      {{range.begin, range.end}}, control, kernels::lane_width<typename Model::lane_type>,
      [&](std::size_t, const auto& next, const auto& retired, const auto& stopped, const auto& stop_closed) {
        LaneScheduler<RowProblem<Model, Integrator, Setup>> scheduler(scene, variant, setup);
        scheduler.run(
            [&]() -> std::optional<Member> {
              const auto k = next();
              if (!k) return std::nullopt;
              return range.source->at(*k);
            },
            [&](MemberResult&& result) {
              sink(std::move(result));
              retired();
            },
            stopped, stop_closed);
        return LaneSteps{scheduler.lane_steps_busy(), scheduler.lane_steps_total()};
      });
  return outcome;
}

/// Calls f.template operator()<Model>() with the scene's model (row_models.hpp) among the models with
/// `form`: on SIMD lanes where the scene asks for them and the model has them, else on the double lane.
/// The quadratures its observables need are chosen at run time (RowSetup::model_arguments).
template <RowModelForm form = RowModelForm::lanes, class F>
decltype(auto) with_row_model(const Scene& scene, F&& f) {
  return with_row_model_entry<form>(scene.model, [&]<class Entry>() -> decltype(auto) {
    if constexpr (Entry::traits.simd_lanes)
      return with_flag(scene.lanes == LaneKind::simd, [&]<bool simd>() -> decltype(auto) {
        using V = std::conditional_t<simd, kernels::simd_lane, double>;
        return f.template operator()<typename Entry::template model<V>>();
      });
    else
      return f.template operator()<typename Entry::template model<double>>();
  });
}

/// One variant's members on the row model with the scene's stepper, of family `family` (its tableau
/// is data: RowProblem's integrator settings).
template <kernels::StepperFamily family>
SweepOutcome run_row_sweep(const Scene& scene, const VariantRange& range, const RunControl& control,
                           const ResultSink& sink) {
  constexpr RowModelForm form =
      family == kernels::StepperFamily::rosenbrock ? RowModelForm::lanes : RowModelForm::explicit_lanes;
  return with_row_model<form>(scene, [&]<class Model>() {
    using Stepper = kernels::family_stepper<family, Model>;
    return run_lane_schedulers<Model, kernels::AdaptiveIntegrator<Model, Stepper>>(
        scene, range, RowSetup<Model>(&scene), control, sink);
  });
}

}  // namespace rotorsweep::ensemble
