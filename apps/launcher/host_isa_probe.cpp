// Configure-time probe (cmake/InstructionSets.cmake): prints the instruction sets the building
// machine runs, as a CMake list, so the tests and the Python module are built for the widest.
#include <cstdio>

#include "apps/launcher/cpu_isas.hpp"

int main() {
  const auto runnable = rotorsweep::launcher::runnable_isas();
  for (std::size_t i = 0; i < runnable.size(); ++i) std::printf("%s%s", i ? ";" : "", runnable[i].c_str());
  std::printf("\n");
}
