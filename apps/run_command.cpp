// `rotorsweep run SCENE.toml`: validate the scene, plan its members, sweep them on lane
// blocks, and write the HDF5 result file (complete = TRUE only once everything is in).
#include <omp.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>

#include "build_info.hpp"
#include "commands.hpp"
#include "ensemble/curves.hpp"
#include "ensemble/member_plan.hpp"
#include "ensemble/sweep.hpp"
#include "io/result_file.hpp"
#include "io/scene_parser.hpp"
#include "kernels/lane.hpp"
#include "kernels/stepper_list.hpp"
#include "progress_line.hpp"

namespace rotorsweep::apps {

namespace {

/// -o, else output.path, else SCENE's stem + ".h5" in the working directory.
std::string output_path(const RunOptions& options, const ensemble::Scene& scene) {
  if (!options.output.empty()) return options.output;
  if (!scene.output_path.empty()) return scene.output_path;
  return std::filesystem::path(options.scene).stem().string() + ".h5";
}

void report_failures(const std::vector<ensemble::MemberResult>& results) {
  std::map<std::string_view, std::size_t> failures;
  for (const auto& r : results)
    if (r.status != kernels::LaneStatus::ok) ++failures[kernels::status_name(r.status)];
  if (failures.empty()) return;
  std::fprintf(stderr, "warning: members that did not finish (their observables are NaN):");
  for (const auto& [name, count] : failures) std::fprintf(stderr, " %s %zu", name.data(), count);
  std::fprintf(stderr, "; see /members/status\n");
}

}  // namespace

int run_sweep_command(const RunOptions& options) {
  ensemble::Scene scene;
  try {
    scene = io::parse_scene_file(options.scene);
  } catch (const io::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  const std::string path = output_path(options, scene);
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  const auto members = ensemble::plan_members(scene);

  std::optional<io::ResultFile> file;
  try {
    const auto parent = std::filesystem::path(path).parent_path();
    if (!parent.empty()) std::filesystem::create_directories(parent);
    file.emplace(path, scene, io::Provenance{options.scene, version, revision});
  } catch (const std::exception& e) {
    std::cerr << "error: output path '" << path << "' (-o or output.path): " << e.what() << "\n";
    return 2;
  }

  const std::size_t lanes =
      scene.lanes == ensemble::LaneKind::simd ? kernels::lane_width<kernels::simd_lane> : 1;
  std::string rows, tolerances;
  for (std::size_t n : scene.row_counts) {
    if (!rows.empty()) rows += ",";
    rows += std::to_string(n);
  }
  for (double r : scene.rtol_values) {
    char text[32];
    std::snprintf(text, sizeof text, "%s%g", tolerances.empty() ? "" : ",", r);
    tolerances += text;
  }
  std::fprintf(stderr,
               "rotorsweep run %s: %zu members (%zu N × %zu rtol × %zu A × %zu g × %zu kinds × %d replicas), "
               "N = %s, %s rtol %s, %d threads × %zu lanes\n",
               options.scene.c_str(), members.size(), scene.row_counts.size(), scene.rtol_values.size(),
               scene.A_values.size(), scene.g_values.size(), scene.kinds.size(), scene.replicas, rows.c_str(),
               kernels::stepper_names[std::size_t(scene.stepper)].data(), tolerances.c_str(), threads, lanes);
  ProgressLine progress(members.size(), !options.quiet);
  const auto outcome =
      ensemble::run_sweep(scene, members, threads, [&](std::size_t done) { progress.update(done); });
  progress.finish();

  try {
    file->write_members(scene, members, outcome.results);
    file->write_curves(scene, ensemble::aggregate_curves(members, outcome.results, scene.replicas));
    file->finish(outcome.statistics);
  } catch (const std::exception& e) {
    std::cerr << "error: writing " << path << " failed (the file says complete = FALSE): " << e.what()
              << "\n";
    return 1;
  }
  report_failures(outcome.results);
  const auto& stats = outcome.statistics;
  std::fprintf(stderr, "wrote %s: %zu members in %s (%.1f members/s, lane occupancy %.1f %%)\n", path.c_str(),
               members.size(), format_duration(stats.wall_seconds).c_str(),
               double(members.size()) / stats.wall_seconds, 100 * stats.occupancy());
  return 0;
}

}  // namespace rotorsweep::apps
