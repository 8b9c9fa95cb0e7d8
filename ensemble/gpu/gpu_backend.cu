// The GPU backend's entry points in a CUDA build: the device probe and the dispatch by the variant's plan
// to a register kernel's unit (gpu_sweep_registers.cu.in), else from the scene's stepper to its family's
// unit (gpu_sweep_family.cu.in), or at T > 0 to the Langevin one.
#include <cuda_runtime.h>

#include <cstddef>
#include <stdexcept>
#include <string>

#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/gpu/gpu_register_shapes.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

namespace gpu {
template <kernels::StepperFamily family>
SweepOutcome run_stepper_family(const Scene&, const VariantRange&, const GpuPlan&, const RunControl&,
                                const ResultSink&);
SweepOutcome run_langevin(const Scene&, const VariantRange&, const GpuPlan&, const RunControl&, const ResultSink&);
template <std::size_t L, std::size_t R, bool PerRow, std::size_t S, unsigned B, bool Q>
SweepOutcome run_in_registers(const Scene&, const VariantRange&, const GpuPlan&, const RunControl&,
                              const ResultSink&);

/// run_in_registers for the plan's shape, the i-th compiled shape or a later one.
template <std::size_t i = 0>
SweepOutcome run_registers(const Scene& scene, const VariantRange& range, const GpuPlan& plan,
                           const RunControl& control, const ResultSink& sink) {
  if constexpr (i < compiled_register_shapes.size()) {
    constexpr RegisterShape compiled = compiled_register_shapes[i];
    if (*plan.shape == compiled)
      return run_in_registers<compiled.lanes, compiled.slots, compiled.disordered, compiled.stages,
                              compiled.blocks, compiled.every_quadrature>(scene, range, plan, control, sink);
    return run_registers<i + 1>(scene, range, plan, control, sink);
  } else {
    throw std::logic_error("no register kernel of this shape was compiled");
  }
}
}  // namespace gpu

const GpuInfo& gpu_info() {
  static const GpuInfo info = [] {
    GpuInfo out;
    int count = 0;
    const cudaError_t status = cudaGetDeviceCount(&count);
    if (status != cudaSuccess || count == 0) {
      out.why = std::string("no CUDA GPU found (") +
                (status != cudaSuccess ? cudaGetErrorString(status) : "no devices") + ")";
      return out;
    }
    out.devices = count;
    try {
      out.index = gpu_device_index(count);
    } catch (const GpuLaunchError& e) {
      out.why = e.what();
      return out;
    }
    cudaDeviceProp properties{};
    if (cudaGetDeviceProperties(&properties, out.index) != cudaSuccess) {
      out.why = "the CUDA GPU could not be queried";
      return out;
    }
    if (properties.major < 6) {
      out.why = std::string(properties.name) + " is older than compute capability 6.0";
      return out;
    }
    out.available = true;
    out.name = properties.name;
    out.multiprocessors = properties.multiProcessorCount;
    out.memory_gib = double(properties.totalGlobalMem) / double(1ull << 30);
    return out;
  }();
  return info;
}

void use_gpu() {
  if (cudaSetDevice(gpu_info().index) != cudaSuccess)
    throw std::runtime_error("cannot use CUDA device " + std::to_string(gpu_info().index));
}

SweepOutcome GpuExecutor::run_variant(const Scene& scene, const VariantRange& range, const RunControl& control,
                                      const ResultSink& sink) const {
  const GpuPlan plan = this->plan(scene, range.source->at(range.begin).rows);
  if (scene.thermal.on()) return gpu::run_langevin(scene, range, plan, control, sink);
  if (plan.mapping == GpuMapping::registers) return gpu::run_registers(scene, range, plan, control, sink);
  return kernels::with_stepper_family(scene.stepper, [&]<kernels::StepperFamily family>() {
    return gpu::run_stepper_family<family>(scene, range, plan, control, sink);
  });
}

}  // namespace rotorsweep::ensemble
