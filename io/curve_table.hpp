// /curves of a result file (README "Output file"): per-point statistics computed from the file's
// own /members, a block of points at a time, so that memory does not grow with the plan.
#pragma once

#include "ensemble/scene.hpp"
#include "io/hdf5_file.hpp"

namespace rotorsweep::io {

/// Writes /curves (and /curves/attractors) of a file whose /members holds the whole plan of `scene`.
void write_curves_from_members(const Hdf5Location& file, const ensemble::Scene& scene);

}  // namespace rotorsweep::io
