// `rotorsweep slider SCENE`: the experiment's many-body slider over a scan of layer separations
// (docs/model.md §9); one HDF5 file put in place only when complete, a progress line, a summary;
// SIGINT or SIGTERM stops it before the next lane block with nothing written (exit 130 or 143).

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include "build_info.hpp"
#include "commands.hpp"
#include "ensemble/engine/instruction_set.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "io/output_target.hpp"
#include "io/slider_result_file.hpp"
#include "io/slider_scene_parser.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "progress_line.hpp"
#include "run_support.hpp"

namespace rotorsweep::apps {

int run_slider(const SceneCommandOptions& options) {
  ensemble::SliderScene scene;
  try {
    scene = io::parse_slider_scene_file(options.scene);
  } catch (const io::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  int threads = 0;
  try {
    threads = ensemble::thread_count(options.threads);
  } catch (const ensemble::ThreadCountError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  const std::string path = options.output.empty() ? scene.output_path : options.output;
  std::optional<io::OutputTarget> target;
  try {
    target.emplace(path, std::vector<std::string>{options.scene}, io::Replaceable::hdf5, options.force);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << " (-o or output.path)\n";
    return 2;
  }
  const auto [closest, farthest] = std::minmax_element(scene.separations.begin(), scene.separations.end());
  std::string sizes;
  for (const auto& size : scene.sizes)
    sizes += (sizes.empty() ? "" : ", ") + std::to_string(size.columns) + " × " + std::to_string(size.rows);
  std::fprintf(
      stderr,
      "rotorsweep slider %s: %zu members (%zu sizes × %zu separations h = %g … %g mm × %zu replicas), rotors "
      "%s over %zu × %zu, %s, %s rtol %g, %d threads × %zu lanes\n",
      options.scene.c_str(), scene.member_count(), scene.sizes.size(), scene.separations.size(),
      *closest * 1e3, *farthest * 1e3, scene.replicas, sizes.c_str(), scene.substrate_columns,
      scene.substrate_rows, scene.overdamped ? "overdamped" : "inertial",
      kernels::stepper_names[scene.stepper].data(), scene.rtol, threads,
      kernels::lane_width<kernels::simd_lane>);
  ProgressLine progress(scene.member_count(), !options.quiet);
  const StopOnSignals signals;
  const auto result = ensemble::run_slider_scan(
      scene, threads, [&](std::size_t done, std::size_t) { progress.update(done); },
      [&] { return signals.flag()->load(); });
  progress.finish();
  if (result.stopped) {
    const int number = signals.signal() ? signals.signal() : SIGINT;
    std::fprintf(stderr, "stopped by %s: nothing written (a slider scan does not resume; run it again)\n",
                 number == SIGTERM ? "SIGTERM" : "SIGINT");
    return 128 + number;
  }
  try {
    io::write_slider_result(
        target->temporary(), scene, result,
        io::Provenance{options.scene, version, revision, "cpu", ensemble::instruction_set().name}, threads);
    target->commit();
  } catch (const std::exception& e) {
    std::cerr << "error: writing " << path << " failed: " << e.what() << "; no file was written\n";
    return 1;
  }
  const auto failed = std::count_if(result.members.begin(), result.members.end(),
                                    [](const ensemble::SliderMember& m) { return m.status != "ok"; });
  double steps = 0;
  for (const auto& m : result.members) steps += m.steps_accepted + m.steps_rejected;
  std::fprintf(stderr, "wrote %s%s: %zu members in %s (%.0f step attempts per member)\n", path.c_str(),
               target->replaced() ? " (replacing the previous file)" : "", result.members.size(),
               format_duration(result.seconds).c_str(), steps / double(result.members.size()));
  if (failed)
    std::fprintf(stderr, "warning: %ld members stopped early; see /members/status (their friction is NaN)\n",
                 long(failed));
  return 0;
}

}  // namespace rotorsweep::apps
