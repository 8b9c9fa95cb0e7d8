// The parts of the GPU backend every build has: the result file's device label, the row limit
// from the per-thread scratch, and the launch shape from the environment.
#include "ensemble/gpu/gpu_backend.hpp"

#include <cstdlib>
#include <stdexcept>

#include "ensemble/engine/device_member.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

std::string device_label(const Scene& scene) {
  if (scene.device == Device::cpu) return "cpu";
  return "gpu (" + gpu_info().name + ")";
}

std::size_t gpu_max_rows(const Scene& scene) {
  return kernels::with_stepper_id(scene.stepper, [&]<kernels::StepperId id>() {
    using Model = kernels::NearestNeighbourRows<double>;
    using Stepper = typename kernels::stepper_at<id>::type::template type<Model>;
    std::size_t n = 2;
    while (DeviceMember<Model, Stepper>::storage_size(n + 1) <= gpu_thread_scratch) ++n;
    return n - n % 2;  // rows come in even numbers
  });
}

namespace {

int positive_from_environment(const char* name, int fallback) {
  const char* text = std::getenv(name);
  if (!text || !*text) return fallback;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (*end != '\0' || value < 1 || value > (1 << 20))
    throw std::runtime_error(std::string(name) + " = '" + text + "': must be a positive integer");
  return int(value);
}

}  // namespace

GpuLaunch gpu_launch() {
  GpuLaunch launch;
  launch.threads_per_block = positive_from_environment("ROTORSWEEP_GPU_BLOCK", launch.threads_per_block);
  if (launch.threads_per_block > 1024 || launch.threads_per_block % 32 != 0)
    throw std::runtime_error("ROTORSWEEP_GPU_BLOCK: must be a multiple of 32 from 32 to 1024");
  launch.blocks = positive_from_environment("ROTORSWEEP_GPU_BLOCKS", 0);
  return launch;
}

}  // namespace rotorsweep::ensemble
