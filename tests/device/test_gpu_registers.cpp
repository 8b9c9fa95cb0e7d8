// Members in registers on the GPU (ensemble/gpu/gpu_register_sweep.cuh) against the host's emulation
// of the warp (kernels::HostWarp): the same bits for every shape the build compiled.
#include <catch2/catch.hpp>
#include <cstddef>
#include <string>
#include <vector>

#include "ensemble/engine/thread_count.hpp"
#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/gpu/gpu_register_shapes.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/gpu/gpu_plan.hpp"
#include "ensemble/gpu/gpu_registers.hpp"
#include "ensemble/gpu/register_member.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "kernels/lanes/warp.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "support/same_results.hpp"
#include "support/slot_runs.hpp"

using namespace rotorsweep;

namespace {

/// N for a shape: the largest even count it holds (rows come in even numbers), at least its lanes.
constexpr std::size_t rows_for(const ensemble::RegisterShape& shape) {
  const std::size_t n = shape.capacity() - shape.capacity() % 2;
  return n < shape.lanes ? shape.lanes : n;
}

/// The linearly implicit stepper with the most stages a shape holds (rodas5p for 8, rodas4 for 6).
std::string stepper_for(const ensemble::RegisterShape& shape) {
  std::size_t best = 0, best_stages = 0;
  for (std::size_t id = 0; id < kernels::stepper_names.size(); ++id) {
    if (kernels::stepper_family(id) != kernels::StepperFamily::rosenbrock) continue;
    const auto stages = std::size_t(kernels::stepper_method<kernels::RosenbrockTableau>(id).stages);
    if (stages <= shape.stages && stages > best_stages) best = id, best_stages = stages;
  }
  return std::string(kernels::stepper_names[best]);
}

/// AFM, CP and FM members from random and noisy AFM starts, one period each side, rtol 1e-8, the
/// shape's stepper, every quadrature where the shape carries them; no shadow runs (the host's run
/// through one chunk has none; they run the same kernel again).
std::string scene_text(const ensemble::RegisterShape& shape) {
  return "[model]\nrows = " + std::to_string(rows_for(shape)) +
         "\n[drive]\ng = [0.01]\n[sweep]\nA = {from = 0.5, to = 14, count = 8}\n[initial]\nkinds = "
         "[\"random\", \"AFM\"]\nnoise = 0.01\nreplicas = 2\n[schedule]\nrelax_periods = 1\naverage_periods "
         "= 1\n[numerics]\nrtol = 1e-8\natol = 1e-11\nglobal_error = \"local\"\ndevice = \"gpu\"\nstepper = "
         "\"" +
         stepper_for(shape) + "\"\n" +
         (shape.disordered ? "[disorder]\nA = 1e-3\nanisotropy = 1e-3\ncoupling = 1e-3\n" : "") +
         (shape.every_quadrature ? "[observables]\nestimators = true\nenergy = true\nmoments = true\n" : "");
}

template <std::size_t i = 0>
void check_compiled_shapes() {
  if constexpr (i < ensemble::compiled_register_shapes.size()) {
    constexpr ensemble::RegisterShape shape = ensemble::compiled_register_shapes[i];
    const auto scene = io::parse_scene_text(scene_text(shape), "registers");
    const std::size_t rows = rows_for(shape);
    INFO(shape.lanes << " × " << shape.slots << (shape.disordered ? " disordered" : "") << ", "
                     << shape.stages << " stages, " << shape.blocks << " blocks bound"
                     << (shape.every_quadrature ? ", every quadrature" : "") << ", N = " << rows);
    REQUIRE(ensemble::choose_register_shape(ensemble::compiled_register_shapes, scene, rows, {}) == shape);
    const auto members = ensemble::plan_members(scene);
    const ensemble::GpuExecutor executor;
    const auto gpu =
        ensemble::run_sweep(scene, members, {.threads = ensemble::thread_count(0)}, &executor).results;
    using Driver = ensemble::RegisterMember<kernels::HostWarp<shape.lanes>, shape.slots, shape.disordered,
                                            shape.stages, shape.every_quadrature>;
    using Integrator = ensemble::DeviceAdaptiveIntegrator<kernels::StepperFamily::rosenbrock,
                                                          kernels::NearestNeighbourRows<double>>;
    const auto host = testing::through_slots<Integrator>(
        scene,
        [](const ensemble::SlotSchedule& s, const ensemble::SlotViews& v, std::size_t k) {
          Driver::run(s, v, k);
        },
        true);
    std::string first;
    CHECK(testing::count_differences(host, gpu, first) == 0);
    INFO(first);
    CHECK(first.empty());
    check_compiled_shapes<i + 1>();
  }
}

}  // namespace

TEST_CASE("members in registers on the GPU give the host emulation's bits for every compiled shape",
          "[gpu][registers]") {
  check_compiled_shapes();
}
