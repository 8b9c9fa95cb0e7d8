// /curves of a result file (docs/output.md "Output file"): per-point statistics computed from the file's
// own /members, a block of points at a time, so that memory does not grow with the plan.
#pragma once

#include <functional>

#include "ensemble/rows/scene.hpp"
#include "io/hdf5_file.hpp"

namespace rotorsweep::io {

/// Attractor labels assumed before a sweep has run (their count is known only at its end), to estimate
/// the size of /curves up front.
inline constexpr std::size_t assumed_attractor_labels = 32, assumed_label_length = 32;

/// Bytes of /curves' data for `scene` with `labels` attractor labels of at most `label_length` bytes.
double curves_data_bytes(const ensemble::Scene& scene, std::size_t labels, std::size_t label_length);

/// Writes /curves (and /curves/attractors) of a file whose /members holds the whole plan of `scene`.
/// Before anything is written, reserve(bytes) is called with the size of the curves' data (it may
/// throw to stop here, with the file untouched).
void write_curves_from_members(const Hdf5Location& file, const ensemble::Scene& scene,
                               const std::function<void(double bytes)>& reserve);

}  // namespace rotorsweep::io
