// The slider scan's HDF5 result file (README "Slider scans"): per member its separation, mean friction,
// per-period friction and energy balance, order parameters and time series, all in SI units.
#pragma once

#include <string>

#include "ensemble/slider/slider_scene.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "io/result_file.hpp"

namespace rotorsweep::io {

/// Writes the whole file at `path` (a temporary file the caller renames into place).
void write_slider_result(const std::string& path, const ensemble::SliderScene& scene,
                         const ensemble::SliderResult& result, const Provenance& provenance, int threads);

}  // namespace rotorsweep::io
