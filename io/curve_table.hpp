// /curves of a result file (README "Output file"): per-point statistics computed from the file's
// own /members, a block of points at a time, so that memory does not grow with the plan.
#pragma once

#include <functional>

#include "ensemble/rows/scene.hpp"
#include "io/hdf5_file.hpp"

namespace rotorsweep::io {

/// Writes /curves (and /curves/attractors) of a file whose /members holds the whole plan of `scene`.
/// Before anything is written, reserve(bytes) is called with the size of the curves' data (it may
/// throw to stop here, with the file untouched).
void write_curves_from_members(const Hdf5Location& file, const ensemble::Scene& scene,
                               const std::function<void(double bytes)>& reserve);

}  // namespace rotorsweep::io
