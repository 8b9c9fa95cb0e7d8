// `rotorsweep run SCENE.toml`: validate the scene, plan its members, sweep them on lane
// blocks, and write the HDF5 result file (complete = TRUE only once everything is in).
#include <omp.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "build_info.hpp"
#include "commands.hpp"
#include "ensemble/member_plan.hpp"
#include "ensemble/sweep.hpp"
#include "io/output_target.hpp"
#include "io/result_file.hpp"
#include "io/scene_parser.hpp"
#include "kernels/lane.hpp"
#include "kernels/stepper_list.hpp"
#include "progress_line.hpp"

namespace rotorsweep::apps {

namespace {

/// -o, else output.path, else SCENE's stem + ".h5" in the working directory; a shard without -o
/// gets ".shard-I-of-N" before the extension, so that shards do not overwrite each other.
std::string output_path(const RunOptions& options, const ensemble::Scene& scene,
                        const std::optional<io::ShardLabel>& shard) {
  if (!options.output.empty()) return options.output;
  std::filesystem::path path =
      scene.output_path.empty()
          ? std::filesystem::path(std::filesystem::path(options.scene).stem().string() + ".h5")
          : std::filesystem::path(scene.output_path);
  if (shard) {
    const std::string tag = ".shard-" + std::to_string(shard->index) + "-of-" + std::to_string(shard->count);
    path.replace_filename(path.stem().string() + tag + path.extension().string());
  }
  return path.string();
}

/// "I/N" with 1 ≤ I ≤ N; nothing for an empty text; throws std::invalid_argument otherwise.
std::optional<io::ShardLabel> parse_shard(const std::string& text, std::size_t plan_members) {
  if (text.empty()) return std::nullopt;
  std::size_t index = 0, count = 0;
  int used = 0;
  if (std::sscanf(text.c_str(), "%zu/%zu%n", &index, &count, &used) != 2 || used != int(text.size()) ||
      index < 1 || index > count)
    throw std::invalid_argument("--shard '" + text + "': must be I/N with 1 <= I <= N (e.g. 2/8)");
  return io::ShardLabel{index, count, plan_members};
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

/// Whether the plan's results fit in this machine's memory; says how much it needs when not.
bool fits_in_memory(const ensemble::Scene& scene) {
  const double needed = ensemble::plan_memory_bytes(scene);
  const double available = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  if (available <= 0 || needed <= 0.8 * available) return true;
  std::fprintf(stderr,
               "error: the plan's %.3g members need about %.3g GiB of memory for their results; this machine "
               "has %.3g GiB. Split the sweep (fewer A, g, replicas per scene)%s.\n",
               double(scene.member_count()), needed / 0x1p30, available / 0x1p30,
               scene.period_series ? " or switch off observables.period_series" : "");
  return false;
}

void report_unresolved(const ensemble::Scene& scene, const std::vector<ensemble::MemberResult>& results) {
  if (!scene.has(ensemble::Observable::dissipation)) return;
  std::size_t unresolved = 0;
  for (const auto& r : results)
    unresolved += r.status == kernels::LaneStatus::ok && !r.dissipation_resolved();
  if (unresolved > 0)
    std::fprintf(stderr,
                 "warning: %zu members whose D is not resolved (dissipation_error >= 0.1 |D|); %s; see "
                 "/members/dissipation_resolved\n",
                 unresolved,
                 scene.thermal.on() ? "at T > 0 this is the statistical error: average more periods"
                                    : "tighten numerics.rtol and atol");
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
  if (!fits_in_memory(scene)) return 2;
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  std::optional<io::ShardLabel> shard;
  try {
    shard = parse_shard(options.shard, scene.member_count());
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }

  std::optional<io::OutputTarget> target;
  std::optional<io::ResultFile> file;
  const std::string path = output_path(options, scene, shard);
  try {
    target.emplace(path, std::vector<std::string>{options.scene}, io::Replaceable::hdf5, options.force);
    file.emplace(target->temporary(), scene, io::Provenance{options.scene, version, revision});
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << " (-o or output.path)\n";
    return 2;
  }
  const auto members =
      shard ? ensemble::shard_members(ensemble::plan_members(scene), shard->index, shard->count)
            : ensemble::plan_members(scene);

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
  if (shard)
    std::fprintf(stderr, "shard %zu/%zu: members %zu, %zu, %zu, ... of the plan's %zu\n", shard->index,
                 shard->count, shard->index - 1, shard->index - 1 + shard->count,
                 shard->index - 1 + 2 * shard->count, shard->plan_members);
  std::fprintf(stderr,
               "rotorsweep run %s: %zu members (%zu N × %zu rtol × %zu A × %zu g × %zu noise × %zu offset × "
               "%zu kinds × %d "
               "replicas), "
               "N = %s, %s rtol %s, %d threads × %zu lanes\n",
               options.scene.c_str(), members.size(), scene.row_counts.size(), scene.rtol_values.size(),
               scene.A_values.size(), scene.g_values.size(), scene.noise_values.size(),
               scene.offset_values.size(), scene.kinds.size(), scene.replicas, rows.c_str(),
               kernels::stepper_names[std::size_t(scene.stepper)].data(), tolerances.c_str(), threads, lanes);
  ProgressLine progress(members.size(), !options.quiet);
  const auto outcome =
      ensemble::run_sweep(scene, members, threads, [&](std::size_t done) { progress.update(done); });
  progress.finish();

  try {
    if (shard)
      file->write_shard(scene, members, outcome, *shard);
    else
      file->write_sweep(scene, members, outcome);
    file->close();
    target->commit();
  } catch (const std::exception& e) {
    std::cerr << "error: writing " << path << " failed: " << e.what() << "; "
              << (target->replaced() ? "the previous file is unchanged" : "no file was written") << "\n";
    return 1;
  }
  report_failures(outcome.results);
  report_unresolved(scene, outcome.results);
  const auto& stats = outcome.statistics;
  std::fprintf(stderr, "wrote %s%s: %zu members in %s (%.1f members/s, lane occupancy %.1f %%)\n",
               path.c_str(), target->replaced() ? " (replacing the previous file)" : "", members.size(),
               format_duration(stats.wall_seconds).c_str(), double(members.size()) / stats.wall_seconds,
               100 * stats.occupancy());
  return 0;
}

}  // namespace rotorsweep::apps
