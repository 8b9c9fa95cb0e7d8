// `rotorsweep run SCENE.toml`: validate the scene, plan its members, sweep them on lane
// blocks, and write the HDF5 result file (complete = TRUE only once everything is in).
#include <omp.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
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
#include "io/result_reader.hpp"
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

/// SIGINT and SIGTERM raise the sweep's stop flag while an instance lives (the previous handlers
/// come back after it); signal() names the signal that came, 0 for none.
class StopOnSignals {
 public:
  StopOnSignals() {
    stop_ = false;
    signal_ = 0;
    previous_int_ = std::signal(SIGINT, &StopOnSignals::handle);
    previous_term_ = std::signal(SIGTERM, &StopOnSignals::handle);
  }
  ~StopOnSignals() {
    std::signal(SIGINT, previous_int_);
    std::signal(SIGTERM, previous_term_);
  }
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;
  const std::atomic<bool>* flag() const { return &stop_; }
  int signal() const { return signal_; }

 private:
  static void handle(int number) {
    signal_ = number;
    stop_ = true;
  }
  static inline std::atomic<bool> stop_{false};
  static inline volatile std::sig_atomic_t signal_ = 0;
  void (*previous_int_)(int) = SIG_DFL;
  void (*previous_term_)(int) = SIG_DFL;
};

/// The members an interrupted run left in `partial`, put at their positions in `plan`; the
/// partial file must come from the same scene text and the same program.
double read_partial(const std::string& partial, const ensemble::Scene& scene,
                    const std::vector<ensemble::Member>& plan, std::vector<ensemble::MemberResult>& results,
                    std::vector<char>& done) {
  if (!std::filesystem::exists(partial))
    throw std::runtime_error("--resume: there is no '" + partial +
                             "' to resume (an interrupted run leaves it)");
  const auto file = io::Hdf5Location::open_file(partial);
  if (!file.has_attribute("members_done") || file.attribute_flag("complete"))
    throw std::runtime_error("--resume: '" + partial + "' is not the partial file of an interrupted run");
  if (file.attribute_string("scene") != scene.text)
    throw std::runtime_error("--resume: '" + partial +
                             "' was made from a different scene; run without --resume to start afresh");
  if (io::written_by(file) != program_identity())
    throw std::runtime_error("--resume: '" + partial + "' was written by rotorsweep " + io::written_by(file) +
                             ", this is " + program_identity());
  auto stored = io::read_member_results(file, scene, plan);
  for (std::size_t i = 0; i < stored.plan_index.size(); ++i) {
    results[stored.plan_index[i]] = std::move(stored.results[i]);
    done[stored.plan_index[i]] = 1;
  }
  return file.attribute_double("wall_seconds");
}

/// After SIGINT or SIGTERM: the finished members go to `partial` (replacing an older one), and
/// the exit code is 128 + the signal's number.
int keep_partial(const ensemble::Scene& scene, const RunOptions& options,
                 const std::vector<ensemble::Member>& members, const ensemble::SweepOutcome& outcome,
                 const std::vector<char>& done, const std::string& partial, int signal_number) {
  std::vector<ensemble::Member> kept;
  std::vector<ensemble::MemberResult> kept_results;
  for (std::size_t i = 0; i < members.size(); ++i)
    if (done[i]) {
      kept.push_back(members[i]);
      kept_results.push_back(outcome.results[i]);
    }
  const char* name = signal_number == SIGTERM ? "SIGTERM" : "SIGINT";
  try {
    io::OutputTarget target(partial, {options.scene}, io::Replaceable::hdf5, true);
    io::ResultFile file(target.temporary(), scene, io::Provenance{options.scene, version, revision});
    file.write_partial(scene, kept, kept_results, members.size(), outcome.statistics);
    file.close();
    target.commit();
  } catch (const std::exception& e) {
    std::cerr << "\nstopped by " << name << "; keeping the finished members failed: " << e.what() << "\n";
    return 128 + (signal_number ? signal_number : SIGINT);
  }
  std::fprintf(stderr,
               "\nstopped by %s: %zu of %zu members done, kept in %s (not a result: complete = FALSE).\n"
               "resume with: rotorsweep run %s%s%s --resume\n",
               name, kept.size(), members.size(), partial.c_str(), options.scene.c_str(),
               options.output.empty() ? "" : " -o ", options.output.c_str());
  return 128 + (signal_number ? signal_number : SIGINT);
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

  if (shard && options.resume) {
    std::cerr << "error: --resume continues a whole run; an interrupted shard is run again (--shard without "
                 "--resume)\n";
    return 2;
  }
  const std::string path = output_path(options, scene, shard);
  const std::string partial = path + ".partial";
  const auto members =
      shard ? ensemble::shard_members(ensemble::plan_members(scene), shard->index, shard->count)
            : ensemble::plan_members(scene);
  std::vector<ensemble::MemberResult> results(members.size());
  std::vector<char> done(members.size(), 0);
  double earlier_seconds = 0;
  if (options.resume) {
    try {
      earlier_seconds = read_partial(partial, scene, members, results, done);
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << "\n";
      return 2;
    }
  }
  std::vector<ensemble::Member> to_run;
  for (std::size_t i = 0; i < members.size(); ++i)
    if (!done[i]) to_run.push_back(members[i]);

  std::optional<io::OutputTarget> target;
  std::optional<io::ResultFile> file;
  try {
    target.emplace(path, std::vector<std::string>{options.scene}, io::Replaceable::hdf5, options.force);
    file.emplace(target->temporary(), scene, io::Provenance{options.scene, version, revision});
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << " (-o or output.path)\n";
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
  if (options.resume)
    std::fprintf(stderr, "resuming from %s: %zu members done, %zu to run\n", partial.c_str(),
                 members.size() - to_run.size(), to_run.size());
  ProgressLine progress(to_run.size(), !options.quiet);
  ensemble::SweepOutcome outcome;
  int signal_number = 0;
  {
    const StopOnSignals signals;
    outcome = ensemble::run_sweep(
        scene, to_run, threads, [&](std::size_t count) { progress.update(count); }, signals.flag());
    signal_number = signals.signal();
  }
  progress.finish();
  for (std::size_t i = 0, k = 0; i < members.size(); ++i) {
    if (done[i]) continue;
    done[i] = outcome.finished[k];
    if (done[i]) results[i] = std::move(outcome.results[k]);
    ++k;
  }
  outcome.results = std::move(results);
  outcome.statistics.wall_seconds += earlier_seconds;
  if (outcome.interrupted)
    return keep_partial(scene, options, members, outcome, done, partial, signal_number);

  try {
    if (shard)
      file->write_shard(scene, members, outcome, *shard);
    else
      file->write_sweep(scene, members, outcome);
    file->close();
    target->commit();
    if (std::filesystem::exists(partial)) std::filesystem::remove(partial);
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
