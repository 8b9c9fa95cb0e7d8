// Where a scene's members run (docs/architecture.md "Backends"): the CPU's lanes, or a CUDA GPU
// (ensemble/gpu/gpu_backend.hpp), for row scenes and slider scenes alike.
#pragma once

namespace rotorsweep::ensemble {

/// Where members run: CPU lanes, or a CUDA GPU (a member per thread or per team of threads).
enum class Device { cpu, gpu };

}  // namespace rotorsweep::ensemble
