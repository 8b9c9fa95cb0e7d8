// The entry point of the GPU tests: where no GPU can run them it says why and exits 77, which
// ctest reports as skipped; otherwise Catch2 runs them.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>
#include <cstdio>

#include "ensemble/gpu/gpu_backend.hpp"

int main(int argc, char* argv[]) {
  const auto& gpu = rotorsweep::ensemble::gpu_info();
  if (!gpu.available) {
    std::printf("skipped: the GPU tests need a CUDA GPU: %s\n", gpu.why.c_str());
    return 77;
  }
  std::printf("GPU: %s, %d multiprocessors, %.1f GiB\n", gpu.name.c_str(), gpu.multiprocessors,
              gpu.memory_gib);
  return Catch::Session().run(argc, argv);
}
