// The instruction set this copy of the SIMD sweeps was compiled for (one per rotorsweep-<isa>
// binary), as `rotorsweep --version` and the result file's attribute "isa" report it.
#pragma once

#include <cstddef>
#include <string>

namespace rotorsweep::ensemble {

struct InstructionSet {
  std::string name;   ///< "sse2", "avx2", "avx512" (portable builds) or "native"
  std::string simd;   ///< the SIMD architecture of the lanes (xsimd's name, e.g. "avx512bw")
  std::size_t lanes;  ///< doubles per SIMD lane
};

InstructionSet instruction_set();

}  // namespace rotorsweep::ensemble
