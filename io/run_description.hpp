// The description of a row sweep before it starts (docs/cli.md "Running a sweep"): members and axes, the
// integrator that runs them, threads and lanes, the device and the couplings; `run` and Python print it.
#pragma once

#include <cstddef>
#include <string>

#include "ensemble/rows/scene.hpp"

namespace rotorsweep::io {

/// "rotorsweep run NAME: M members (…), N = …, <integrator>, T threads × L lanes" and, where they
/// apply, a device line and a couplings line; every line ends in a newline. `simd_lanes`: the width of
/// the binary's SIMD lanes (ensemble::instruction_set().lanes).
std::string run_description(const ensemble::Scene& scene, const std::string& name, std::size_t members,
                            int threads, std::size_t simd_lanes);

}  // namespace rotorsweep::io
