// `rotorsweep slider SCENE`: the experiment's many-body slider over a scan of layer separations
// (docs/model.md §9), streamed into OUT.h5.partial as members finish, like `run`: a progress line,
// SIGINT or SIGTERM keeps the finished members (exit 130 or 143), --resume, --shard and `merge`.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <string>

#include "build_info.hpp"
#include "commands.hpp"
#include "ensemble/engine/instruction_set.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "io/member_stream.hpp"
#include "io/output_target.hpp"
#include "io/slider_result_file.hpp"
#include "io/slider_scene_parser.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "progress_line.hpp"
#include "run_needs.hpp"
#include "run_support.hpp"
#include "streamed_run.hpp"

namespace rotorsweep::apps {

void print_slider_header(const SliderOptions& options, const ensemble::SliderScene& scene, int threads,
                         const std::optional<io::ShardLabel>& shard) {
  const auto [closest, farthest] = std::minmax_element(scene.separations.begin(), scene.separations.end());
  char text[160];
  std::string sizes;
  for (const auto& size : scene.sizes)
    sizes += (sizes.empty() ? "" : ", ") + std::to_string(size.columns) + " × " + std::to_string(size.rows);
  if (shard) std::fputs(shard_line(*shard).c_str(), stderr);
  std::snprintf(text, sizeof text, "%d threads × %zu lanes", threads, ensemble::slider_thread_lanes(scene));
  const std::string where =
      scene.device == ensemble::Device::gpu ? ensemble::slider_device_label(scene) : text;
  // the speed and damping axes where they have more than one value
  std::string axes;
  if (scene.speeds.size() > 1) {
    const auto [slowest, fastest] = std::minmax_element(scene.speeds.begin(), scene.speeds.end());
    std::snprintf(text, sizeof text, " × %zu speeds v = %g … %g mm/s", scene.speeds.size(), *slowest * 1e3,
                  *fastest * 1e3);
    axes += text;
  }
  if (scene.dampings.size() > 1) {
    const auto [least, most] = std::minmax_element(scene.dampings.begin(), scene.dampings.end());
    std::snprintf(text, sizeof text, " × %zu dampings γ = %g … %g kg m²/s", scene.dampings.size(), *least,
                  *most);
    axes += text;
  }
  const std::string substrate = scene.substrate_infinite ? "an infinite lattice"
                                                         : std::to_string(scene.substrate_columns) + " × " +
                                                               std::to_string(scene.substrate_rows);
  // the stage solves: dense LDLᵀ, conjugate gradients (matrix-free), or each where its sizes take it
  std::size_t free = 0;
  for (const auto& size : scene.sizes) free += ensemble::matrix_free(scene, size) ? 1 : 0;
  const char* solves = free == 0 ? "dense" : free == scene.sizes.size() ? "krylov" : "dense and krylov";
  // "1 separation h = 9 mm", "33 separations h = 5 … 13 mm"
  if (scene.separations.size() == 1)
    std::snprintf(text, sizeof text, "1 separation h = %g mm", *closest * 1e3);
  else
    std::snprintf(text, sizeof text, "%zu separations h = %g … %g mm", scene.separations.size(),
                  *closest * 1e3, *farthest * 1e3);
  const std::string separations = text;
  std::fprintf(stderr,
               "rotorsweep slider %s: %zu members (%zu sizes%s × %s × %zu replicas), "
               "rotors %s over %s, %s, %s rtol %g (%s stage solves), %s\n",
               options.scene.c_str(), scene.member_count(), scene.sizes.size(), axes.c_str(),
               separations.c_str(), scene.replicas, sizes.c_str(), substrate.c_str(),
               scene.overdamped ? "overdamped" : "inertial", kernels::stepper_names[scene.stepper].data(),
               scene.rtol, solves, where.c_str());
}

namespace {

/// Members that did not finish, by status, and the mean step attempts, read from the written file.
void report_slider_outcome(const io::Hdf5Location& file, std::string& steps) {
  const auto members = file.open_group("members");
  const auto status = members.read_strings("status");
  const auto accepted = members.read_doubles("steps_accepted"),
             rejected = members.read_doubles("steps_rejected");
  double attempts = 0;
  std::map<std::string, std::size_t> failures;
  for (std::size_t m = 0; m < status.size(); ++m) {
    attempts += accepted[m] + rejected[m];
    if (status[m] != "ok") ++failures[status[m]];
  }
  char text[64];
  std::snprintf(text, sizeof text, "%.0f step attempts per member", attempts / double(status.size()));
  steps = status.empty() ? "no members run" : text;
  if (failures.empty()) return;
  std::fprintf(stderr, "warning: members that stopped early (their friction is NaN):");
  for (const auto& [name, count] : failures) std::fprintf(stderr, " %s %zu", name.c_str(), count);
  std::fprintf(stderr, "; see /members/status\n");
}

}  // namespace

int run_slider(const SliderOptions& options) {
  ensemble::SliderScene scene;
  try {
    scene = io::parse_slider_scene_file(options.scene);
    if (!options.device.empty()) {
      scene.device = options.device == "gpu" ? ensemble::Device::gpu : ensemble::Device::cpu;
      io::check_slider_device(scene);
    }
    if (scene.device == ensemble::Device::gpu) ensemble::slider_device_label(scene);  // reads the launch
  } catch (const io::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const ensemble::GpuLaunchError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  if (refused(gpu_refusal(scene.device))) return 2;
  int threads = 0;
  std::optional<io::ShardLabel> shard;
  try {
    threads = ensemble::thread_count(options.threads);
    shard = parse_shard(options.shard, scene.member_count());
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  if (refused(scan_memory_refusal(scene, threads))) return 2;
#if ROTORSWEEP_HAVE_MPI
  if (launched_by_mpi()) return run_slider_mpi(options, scene, threads);
#endif
  const std::string path = output_path(options, scene.output_path, shard);
  const StopOnSignals signals;  // from here on: a signal during the set-up stops the scan before it starts
  std::optional<io::OutputTarget> target;
  if (!open_resumable_target(options, options.resume, path, target)) return 2;
  const std::string partial = target->temporary();
  const std::size_t shard_members =
      shard ? (scene.member_count() + shard->count - shard->index) / shard->count : scene.member_count();
  if (!options.resume && refused(scan_disk_refusal(scene, shard_members, shard.has_value(), partial))) return 2;
  if (options.resume &&
      !fits_on_disk(io::SliderResultFile::finishing_bytes(scene, shard.has_value()),
                    "the curve written at the end", partial, "Free some space there first")) {
    target->keep();  // the partial file stays as it is
    return 2;
  }

  std::optional<io::SliderResultFile> file;
  std::vector<std::size_t> to_run;  // plan indices
  std::size_t done_before = 0;
  double earlier_seconds = 0;
  try {
    if (options.resume) {
      to_run = reopen_partial(
          file, *target, scene, shard,
          io::Provenance{options.scene, version, revision, ensemble::slider_device_label(scene),
                         ensemble::instruction_set().name},
          done_before, earlier_seconds);
    } else {
      file.emplace(partial, scene,
                   io::Provenance{options.scene, version, revision, ensemble::slider_device_label(scene),
                                  ensemble::instruction_set().name},
                   shard);
      target->claim_temporary();
      for (std::size_t row = 0; row < file->rows(); ++row) to_run.push_back(file->plan_index_of(row));
    }
  } catch (const std::exception& e) {
    std::cerr << "error: " << (options.resume ? "" : "creating " + partial + " failed: ") << e.what() << "\n";
    if (options.resume) target->keep();  // the file is not touched
    return options.resume ? 2 : 1;
  }
  const std::size_t rows = file->rows();
  print_slider_header(options, scene, threads, shard);
  if (options.resume)
    std::fprintf(stderr, "resuming from %s: %zu members done, %zu to run\n", partial.c_str(), done_before,
                 to_run.size());

  ProgressLine progress(to_run.size(), !options.quiet, "members", "samples taken");
  std::atomic<std::size_t> samples{0};
  bool stopped = false;
  StreamedSweep streamed;
  const auto start = std::chrono::steady_clock::now();
  {
    io::SliderMemberStream stream(*file, [&signals] { signals.stop(); });
    streamed = stream_sweep(stream, signals, [&] {
      stopped = ensemble::run_slider_members(
                    scene, to_run,
                    {.threads = threads,
                     .progress = [&](std::size_t done) { progress.update(done, samples.load()); },
                     .stop = [&] { return signals.stopped(); },
                     .stops = &samples},
                    [&stream](std::vector<ensemble::SliderMember>&& block) { stream.add(std::move(block)); },
                    ensemble::device_for(scene.device))
                    .interrupted;
    });
    done_before += stream.written();
  }
  progress.finish();
  const double seconds =
      earlier_seconds + std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string resume = resume_command("slider", options, options.shard);

  if (const auto code = end_unfinished_run(
          *target, streamed, stopped, "the scan",
          [&] {
            file->keep_partial(done_before, seconds, threads);
            file->close();
          },
          done_before, rows, resume))
    return *code;
  std::string steps;
  if (!finish_streamed_run(
          *target,
          [&] {
            file->finish(seconds, threads);
            file->close();
            report_slider_outcome(io::Hdf5Location::open_file(partial), steps);
          },
          path, rows, resume))
    return 1;
  std::fprintf(stderr, "wrote %s%s: %zu members in %s (%s)\n", path.c_str(),
               target->replaced() ? " (replacing the previous file)" : "", rows,
               format_duration(seconds).c_str(), steps.c_str());
  return 0;
}

}  // namespace rotorsweep::apps
