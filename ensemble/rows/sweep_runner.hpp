// The compile-time side of run_members: picks the lane type and the row model a scene needs, and
// runs lane schedulers of that instantiation on OpenMP threads.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
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

/// Whether the scene's members run on SIMD lanes: where the scene asks for them and its row model has them;
/// else on the double lane.
inline bool on_simd_lanes(const Scene& scene) {
  return scene.lanes == LaneKind::simd && row_model_traits(scene.model).simd_lanes;
}

/// Calls f.template operator()<Model>() with the scene's model (row_models.hpp) among the models with
/// `form`, on SIMD lanes where on_simd_lanes(scene), else on the double lane. The quadratures its
/// observables need are chosen at run time (RowSetup::model_arguments).
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

/// f.template operator()<Model>() (of result R) with the scene's model on SIMD lanes, among the models with
/// `form`; on_simd_lanes(scene) holds.
template <RowModelForm form, class R, class F>
R with_simd_lane_model(const Scene& scene, F&& f) {
  return with_row_model_entry<form>(scene.model, [&]<class Entry>() -> R {
    if constexpr (Entry::traits.simd_lanes)
      return f.template operator()<typename Entry::template model<kernels::simd_lane>>();
    else
      throw std::logic_error(std::string("with_simd_lane_model: ") + row_model_description(scene.model) +
                             " has no SIMD lanes");
  });
}

/// The row models a stepper family's sweep may run: every model for the linearly implicit steppers, those
/// with the explicit form for the explicit ones.
template <kernels::StepperFamily family>
constexpr RowModelForm family_form =
    family == kernels::StepperFamily::rosenbrock ? RowModelForm::lanes : RowModelForm::explicit_lanes;

/// One variant's members on Model with the scene's stepper, of family `family` (its tableau is data:
/// RowProblem's integrator settings).
template <kernels::StepperFamily family, class Model>
SweepOutcome run_family_on(const Scene& scene, const VariantRange& range, const RunControl& control,
                           const ResultSink& sink) {
  using Stepper = kernels::family_stepper<family, Model>;
  return run_lane_schedulers<Model, kernels::AdaptiveIntegrator<Model, Stepper>>(
      scene, range, RowSetup<Model>(&scene), control, sink);
}

/// One variant's members on the double lane (the scene's `lanes = "scalar"`, or a model without SIMD
/// lanes), with a stepper of family `family` or the Langevin stepper. These instantiations hold no SIMD
/// lane: they are compiled once, without an instruction set's flags, into rotorsweep_ensemble_core
/// (sweep_family_double_lane.cpp.in, sweep_langevin_double_lane.cpp) for every instruction set's sweeps.
template <kernels::StepperFamily family>
SweepOutcome run_double_lane_row_sweep(const Scene& scene, const VariantRange& range, const RunControl& control,
                                       const ResultSink& sink);
SweepOutcome run_double_lane_thermal_row_sweep(const Scene& scene, const VariantRange& range,
                                               const RunControl& control, const ResultSink& sink);

/// One variant's members on the row model with the scene's stepper, of family `family`: on this
/// instruction set's SIMD lanes, or on the double lane (run_double_lane_row_sweep).
template <kernels::StepperFamily family>
SweepOutcome run_row_sweep(const Scene& scene, const VariantRange& range, const RunControl& control,
                           const ResultSink& sink) {
  if (!on_simd_lanes(scene)) return run_double_lane_row_sweep<family>(scene, range, control, sink);
  return with_simd_lane_model<family_form<family>, SweepOutcome>(scene, [&]<class Model>() {
    return run_family_on<family, Model>(scene, range, control, sink);
  });
}

}  // namespace rotorsweep::ensemble
