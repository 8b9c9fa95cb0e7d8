// The parts of the GPU backend every build has: the result file's device label, the row limit
// from the per-thread scratch, and the launch shape from the environment.
#include "ensemble/gpu/gpu_backend.hpp"

#include <cstdlib>
#include <stdexcept>

#include "ensemble/gpu/device_drivers.hpp"

namespace rotorsweep::ensemble {

std::string device_label(const Scene& scene) {
  if (scene.device == Device::cpu) return "cpu";
  return "gpu (" + gpu_info().name + ")";
}

std::size_t gpu_max_rows(const Scene& scene) {
  return with_device_driver(scene, [&]<class Model, class Integrator>() {
    SlotSchedule s;  // what the scratch depends on: rows, quadratures, row profiles
    s.quadratures = scene.observables.quadratures();
    s.row_profiles = scene.row_profiles;
    const auto fits = [&](std::size_t rows) {
      s.rows = rows;
      return DeviceMember<Model, Integrator>::storage_size(s) <= gpu_thread_scratch;
    };
    std::size_t n = 2;
    while (fits(n + 1)) ++n;
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
