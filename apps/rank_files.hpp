// The rank files of a run under mpirun (PARTIAL.rank-R beside its partial file): each rank streams its
// members into one, rank 0 joins them at the end, and --resume joins those a killed run left
// (docs/scale.md "MPI").
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ensemble/rows/scene.hpp"
#include "ensemble/slider/slider_scene.hpp"
#include "io/result_file.hpp"
#include "io/slider_result_file.hpp"

namespace rotorsweep::apps {

/// The file rank `rank` streams its members into, beside the run's partial file.
inline std::string rank_file(const std::string& partial, int rank) {
  return partial + ".rank-" + std::to_string(rank);
}

/// The rank files beside `partial` (PARTIAL.rank-R, R digits), in rank order.
std::vector<std::string> rank_files(const std::string& partial);

/// The rows rank file `path` marks done, written into `out` (the run's or the slider's file); returns how
/// many, and removes the rank file.
std::size_t join_rank_file(const io::ResultFile& out, const ensemble::Scene& scene, const std::string& path);
std::size_t join_rank_file(const io::SliderResultFile& out, const ensemble::SliderScene& scene,
                           const std::string& path);

/// Keeps `out` partial with the members its /members/done marks (after joins, whatever was there).
void keep_joined(const io::ResultFile& out);
void keep_joined(const io::SliderResultFile& out);

}  // namespace rotorsweep::apps
