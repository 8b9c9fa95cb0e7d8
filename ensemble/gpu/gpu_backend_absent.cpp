// The GPU backend's entry points in a build without CUDA: no device, and a clear error for a
// scene that asks for one.
#include <stdexcept>

#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/gpu/gpu_executor.hpp"

namespace rotorsweep::ensemble {

const GpuInfo& gpu_info() {
  static const GpuInfo info = [] {
    GpuInfo none;
    none.why = "this rotorsweep was built without the GPU backend (ROTORSWEEP_CUDA=OFF, or no nvcc)";
    return none;
  }();
  return info;
}

void use_gpu() { throw std::runtime_error("numerics.device = \"gpu\": " + gpu_info().why); }

SweepOutcome GpuExecutor::run_variant(const Scene&, const VariantRange&, const RunControl&,
                                      const ResultSink&) const {
  throw std::runtime_error("numerics.device = \"gpu\": " + gpu_info().why);
}

RunOutcome GpuExecutor::run_members(const SliderScene&, const std::vector<std::size_t>&, const RunControl&,
                                    const std::function<void(std::vector<SliderMember>&&)>&,
                                    const SliderTableBuilder&) const {
  throw std::runtime_error("numerics.device = \"gpu\": " + gpu_info().why);
}

}  // namespace rotorsweep::ensemble
