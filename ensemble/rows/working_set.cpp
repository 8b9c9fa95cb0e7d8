// lane_block_bytes: the integration loop of the scene's stepper and row model, counted for the
// lane type this unit is compiled for (kernels::counted_storage; docs/architecture.md "Lanes").
#include "ensemble/rows/working_set.hpp"

#include <tuple>

#include "ensemble/engine/integration_loop.hpp"
#include "ensemble/rows/row_setup.hpp"
#include "ensemble/rows/sweep_runner.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

double lane_block_bytes(const Scene& scene) {
  const std::size_t rows = scene.max_rows();
  return kernels::with_stepper_family(scene.stepper, [&]<kernels::StepperFamily family>() {
    return with_row_model(scene, [&]<class Model>() {
      using Integrator = kernels::AdaptiveIntegrator<Model, kernels::family_stepper<family, Model>>;
      using Loop = IntegrationLoop<Model, Integrator>;
      const RowSetup<Model> setup(&scene);
      typename Loop::Settings settings{};
      settings.method = kernels::stepper_method<typename Integrator::Method>(scene.stepper);
      const std::size_t values = std::apply(
          [&](const auto&... arguments) { return Loop::storage_size(rows, settings, arguments...); },
          setup.model_arguments());
      return double(values) * double(sizeof(typename Model::lane_type));
    });
  });
}

}  // namespace rotorsweep::ensemble
