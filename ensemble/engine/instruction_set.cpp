// The instruction set of this build of the sweeps: ROTORSWEEP_ISA_NAME from the build
// (cmake/InstructionSets.cmake) and the SIMD architecture xsimd chose under its -march.
#include "ensemble/engine/instruction_set.hpp"

#include "kernels/lanes/lane.hpp"

namespace rotorsweep::ensemble {

InstructionSet instruction_set() {
  return {ROTORSWEEP_ISA_NAME, kernels::simd_lane::arch_type::name(), kernels::simd_lane::size};
}

}  // namespace rotorsweep::ensemble
