// `rotorsweep run SCENE.toml`: validate the scene, plan its members, sweep them on lane blocks
// streaming finished members into OUT.h5.partial, and put the complete file in place at the end.

#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "build_info.hpp"
#include "commands.hpp"
#include "ensemble/engine/instruction_set.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/gpu/gpu_launch.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "ensemble/rows/working_set.hpp"
#include "io/member_flags.hpp"
#include "io/member_stream.hpp"
#include "io/output_target.hpp"
#include "io/result_file.hpp"
#include "io/result_reader.hpp"
#include "io/run_description.hpp"
#include "io/scene_parser.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "progress_line.hpp"
#include "rank_files.hpp"
#include "run_needs.hpp"
#include "run_support.hpp"
#include "streamed_run.hpp"

namespace rotorsweep::apps {

/// -o, else output.path, else SCENE's stem + ".h5" in the working directory; a shard without -o
/// gets ".shard-I-of-N" before the extension, so that shards do not overwrite each other.
std::string output_path(const SceneCommandOptions& options, const std::string& scene_output_path,
                        const std::optional<io::ShardLabel>& shard) {
  if (!options.output.empty()) return options.output;
  std::filesystem::path path =
      scene_output_path.empty()
          ? std::filesystem::path(std::filesystem::path(options.scene).stem().string() + ".h5")
          : std::filesystem::path(scene_output_path);
  if (shard) {
    const std::string tag = ".shard-" + std::to_string(shard->index) + "-of-" + std::to_string(shard->count);
    path.replace_filename(path.stem().string() + tag + path.extension().string());
  }
  return path.string();
}

std::optional<io::ShardLabel> parse_shard(const std::string& text, std::size_t plan_members) {
  if (text.empty()) return std::nullopt;
  // digits only (no sign, space or exponent), each part at most max_shards
  constexpr std::size_t max_shards = 1000000000;
  const auto part = [&](std::size_t begin, std::size_t end) -> std::size_t {
    if (begin == end || end - begin > 10 || text.find_first_not_of("0123456789", begin) < end) return 0;
    const std::size_t value = std::stoull(text.substr(begin, end - begin));
    return value <= max_shards ? value : 0;
  };
  const std::size_t slash = text.find('/');
  const std::size_t index = slash == std::string::npos ? 0 : part(0, slash),
                    count = slash == std::string::npos ? 0 : part(slash + 1, text.size());
  if (index < 1 || count < 1 || index > count)
    throw std::invalid_argument("--shard '" + text + "': must be I/N with 1 <= I <= N <= " +
                                std::to_string(max_shards) + " (e.g. 2/8)");
  return io::ShardLabel{index, count, plan_members};
}

/// Members that did not finish, by status, and finished members whose D is not resolved, for each
/// reason apart, read from the written file a block at a time.
void report_outcome(const io::Hdf5Location& file, const ensemble::Scene& scene) {
  const auto counts = io::count_member_flags(file.open_group("members"));
  if (!counts.failures.empty()) {
    std::fprintf(stderr, "warning: members that did not finish (their observables are NaN):");
    for (const auto& [name, count] : counts.failures) std::fprintf(stderr, " %s %zu", name.c_str(), count);
    std::fprintf(stderr, "; see /members/status\n");
  }
  if (counts.unresolved > 0)
    std::fprintf(stderr,
                 "warning: %zu members whose D is not resolved (dissipation_error >= 0.1 |D|); %s; see "
                 "/members/dissipation_resolved\n",
                 counts.unresolved,
                 scene.thermal.on() ? "at T > 0 this is the statistical error: average more periods"
                                    : "tighten numerics.rtol and atol");
  if (counts.symmetry_limited > 0)
    std::fprintf(
        stderr,
        "warning: %zu members whose D an asymmetry of the rows below rtol decides (symmetry-limited, %zu "
        "of them held on a symmetric set without slipping: their symmetry probe at rtol reached another "
        "attractor or moved D beyond its error, so no error bounds D; not counted as resolved); a tighter "
        "rtol does not help: give the scene disorder (e.g. [disorder] A = 1e-6) or a temperature above "
        "rtol (docs/regimes.md); see /members/symmetry_limited\n",
        counts.symmetry_limited, counts.symmetry_held);
  if (counts.shadow_departed > 0)
    std::fprintf(
        stderr,
        "warning: %zu members whose shadow run reached another attractor (another regime, slips per period "
        "or domain walls), so it estimates no error (dissipation_error infinite); a tighter rtol does not "
        "help: break the symmetry physically with disorder (e.g. [disorder] A = 1e-6) or a temperature "
        "above rtol; see /members/shadow_departed\n",
        counts.shadow_departed);
  if (counts.untold > 0)
    std::fprintf(
        stderr,
        "warning: %zu CP members whose slips could not be told jumps or smooth (their slower rerun at "
        "g/10 did not finish): slip_jumps and slip_smooth are NaN; see /members/slip_jumps\n",
        counts.untold);
}

std::vector<char> check_partial(const std::string& partial, const std::string& scene_text,
                                const std::optional<io::ShardLabel>& shard, double& earlier_seconds,
                                const std::function<void(const io::Hdf5Location&)>& check_file) {
  if (!std::filesystem::exists(partial))
    throw std::runtime_error("--resume: there is no '" + partial +
                             "' to resume (a run that stops early leaves it)");
  const auto file = io::Hdf5Location::open_file(partial);
  if (!file.has("members") || !file.open_group("members").has("done") || file.attribute_flag("complete"))
    throw std::runtime_error("--resume: '" + partial + "' is not the partial file of an unfinished run");
  if (file.attribute_string("scene") != scene_text)
    throw std::runtime_error("--resume: '" + partial +
                             "' was made from a different scene; run without --resume to start afresh");
  if (io::written_by(file) != program_identity())
    throw std::runtime_error("--resume: '" + partial + "' was written by rotorsweep " + io::written_by(file) +
                             ", this is " + program_identity());
  try {
    check_file(file);
  } catch (const std::exception& e) {
    throw std::runtime_error("--resume: " + std::string(e.what()) + " (edited?); start afresh with --force");
  }
  const auto part = [](std::size_t index, std::size_t count) {
    return std::to_string(index) + "/" + std::to_string(count);
  };
  const auto stated = io::MemberTableFile::shard_label(file);
  const std::string theirs = stated ? part(stated->index, stated->count) : "";
  const std::string ours = shard ? part(shard->index, shard->count) : "";
  if (theirs != ours)
    throw std::runtime_error("--resume: '" + partial + "' holds " +
                             (theirs.empty() ? "the whole plan" : "shard " + theirs) + ", not " +
                             (ours.empty() ? "the whole plan" : "shard " + ours));
  earlier_seconds = file.has_attribute("wall_seconds") ? file.attribute_double("wall_seconds") : 0.0;
  return io::read_done(file);
}

std::string shard_line(const io::ShardLabel& shard) {
  const std::string label = "shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) + ": ";
  std::string members;
  std::size_t listed = 0;
  for (std::size_t m = shard.index - 1; m < shard.plan_members && listed < 3; m += shard.count, ++listed)
    members += (members.empty() ? "" : ", ") + std::to_string(m);
  if (listed == 0) return label + "no members (the plan has " + std::to_string(shard.plan_members) + ")\n";
  const bool more = shard.index - 1 + 3 * shard.count < shard.plan_members;
  return label + (listed == 1 ? "member " : "members ") + members + (more ? ", ..." : "") + " of the plan's " +
         std::to_string(shard.plan_members) + "\n";
}

bool fits_on_disk(double needed, const std::string& what, const std::string& partial,
                  const std::string& advice) {
  return !refused(disk_refusal(needed, what, partial, advice));
}

bool refused(const std::optional<std::string>& refusal) {
  if (refusal) std::fprintf(stderr, "error: %s\n", refusal->c_str());
  return refusal.has_value();
}

/// The description of the run on stderr.
void print_header(const RunOptions& options, const ensemble::Scene& scene, std::size_t members, int threads,
                  const std::optional<io::ShardLabel>& shard) {
  if (shard) std::fputs(shard_line(*shard).c_str(), stderr);
  std::fputs(
      io::run_description(scene, options.scene, members, threads, ensemble::instruction_set().lanes).c_str(),
      stderr);
}

bool open_resumable_target(const SceneCommandOptions& options, bool resume, const std::string& path,
                           std::optional<io::OutputTarget>& target) {
  try {
    target.emplace(path, std::vector<std::string>{options.scene}, io::Replaceable::hdf5, options.force, true);
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << " (-o or output.path)\n";
    return false;
  }
  const auto ranks = rank_files(target->temporary());
  if (options.force && !resume)  // a fresh start: an earlier mpirun's rank files go with its partial file
    for (const auto& rank : ranks) std::filesystem::remove(rank);
  if (resume || options.force) return true;
  if (std::filesystem::exists(target->temporary()))
    std::cerr
        << "error: " << target->temporary()
        << " holds the finished members of an earlier run that stopped early: continue it with --resume, "
           "or start afresh with --force\n";
  else if (!ranks.empty())
    std::cerr
        << "error: " << ranks.front()
        << (ranks.size() > 1 ? " and " + std::to_string(ranks.size() - 1) + " more" : "")
        << " hold the finished members of an mpirun run that stopped before its ranks were joined: continue "
           "it with --resume (one process or mpirun), or start afresh with --force\n";
  else
    return true;
  target->keep();
  return false;
}

std::string resume_command(const std::string& command, const SceneCommandOptions& options,
                           const std::string& shard) {
  std::string line = "rotorsweep " + command + " " + options.scene;
  if (!options.output.empty()) line += " -o " + options.output;
  if (!shard.empty()) line += " --shard " + shard;
  return line + " --resume";
}

int run_sweep_command(const RunOptions& options) {
  ensemble::Scene scene;
  try {
    scene = io::parse_scene_file(options.scene);
    if (!options.device.empty()) {
      scene.device = options.device == "gpu" ? ensemble::Device::gpu : ensemble::Device::cpu;
      io::check_device(scene);
    }
  } catch (const io::SceneError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const ensemble::GpuLaunchError& e) {  // the GPU's launch from the environment, read by the check
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  if (refused(gpu_refusal(scene.device))) return 2;
  int threads = 0;
  try {
    threads = ensemble::thread_count(options.threads);
  } catch (const ensemble::ThreadCountError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  if (refused(sweep_memory_refusal(scene, threads))) return 2;
#if ROTORSWEEP_HAVE_MPI
  if (launched_by_mpi()) return run_sweep_mpi(options, scene, threads);
#endif
  std::optional<io::ShardLabel> shard;
  try {
    shard = parse_shard(options.shard, scene.member_count());
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  }
  const std::string path = output_path(options, scene.output_path, shard);
  std::optional<io::OutputTarget> target;
  const StopOnSignals signals;  // from here on: a signal during the set-up stops the run before it starts
  if (!open_resumable_target(options, options.resume, path, target)) return 2;
  const std::string partial = target->temporary();

  if (!options.resume &&
      refused(sweep_disk_refusal(
          scene,
          shard ? (scene.member_count() + shard->count - shard->index) / shard->count : scene.member_count(),
          shard.has_value(), partial)))
    return 2;
  if (options.resume &&
      !fits_on_disk(io::ResultFile::finishing_bytes(scene, shard.has_value()),
                    "the curves written at the end", partial, "Free some space there first")) {
    target->keep();  // the partial file stays as it is
    return 2;
  }

  // the members to run, as plan indices: all of the plan or the shard, less those done before
  const ensemble::MemberPlan plan(scene);
  std::optional<io::ResultFile> file;
  std::vector<std::size_t> remaining;  // resume only: plan indices of the rows not done
  std::size_t done_before = 0;
  double earlier_seconds = 0;
  if (options.resume) {
    try {
      remaining =
          reopen_partial(file, *target, scene, shard,
                         io::Provenance{options.scene, version, revision, ensemble::device_label(scene),
                                        ensemble::instruction_set().name},
                         done_before, earlier_seconds);
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << "\n";
      target->keep();  // the file is not touched
      return 2;
    }
  } else {
    try {
      file.emplace(partial, scene,
                   io::Provenance{options.scene, version, revision, ensemble::device_label(scene),
                                  ensemble::instruction_set().name},
                   shard);
      target->claim_temporary();
    } catch (const std::exception& e) {
      std::cerr << "error: creating " << partial << " failed: " << e.what() << "; "
                << (target->replaced() ? "the previous file is unchanged" : "no file was written") << "\n";
      return 1;
    }
  }
  const std::size_t rows = file->rows();
  const std::size_t to_run = options.resume ? remaining.size() : rows;
  const ensemble::MemberSource source{
      to_run, [&](std::size_t k) { return plan[options.resume ? remaining[k] : file->plan_index_of(k)]; }};

  print_header(options, scene, rows, threads, shard);
  if (options.resume)
    std::fprintf(stderr, "resuming from %s: %zu members done, %zu to run\n", partial.c_str(), done_before,
                 to_run);
  ProgressLine progress(to_run, !options.quiet);
  std::atomic<std::size_t> periods{0};
  ensemble::SweepOutcome outcome;
  StreamedSweep streamed;
  {
    io::MemberStream stream(*file, plan, {options.flush_seconds, options.flush_members},
                            [&signals] { signals.stop(); });
    streamed = stream_sweep(stream, signals, [&] {
      outcome = ensemble::run_members(
          scene, source,
          {.threads = threads,
           .progress =
               [&](std::size_t count) { progress.update(count, periods.load(std::memory_order_relaxed)); },
           .stop = [&] { return signals.stopped(); },
           .stops = &periods},
          [&stream](ensemble::MemberResult&& result) { stream.add(std::move(result)); },
          ensemble::device_for(scene.device));
    });
    done_before += stream.written();
  }
  progress.finish();
  auto& stats = outcome.statistics;
  const bool all_done_before = options.resume && to_run == 0;
  if (all_done_before)  // a resume with every member done: the earlier run's figures stand
    stats = file->recorded_statistics(threads, ensemble::instruction_set().lanes);
  else
    stats.wall_seconds += earlier_seconds;

  const std::string resume = resume_command("run", options, options.shard);
  if (const auto code = end_unfinished_run(
          *target, streamed, outcome.interrupted, "the sweep",
          [&] {
            file->keep_partial(done_before, stats);
            file->close();
          },
          done_before, rows, resume))
    return *code;
  if (!finish_streamed_run(
          *target,
          [&] {
            file->finish(stats);
            file->close();
            report_outcome(io::Hdf5Location::open_file(partial), scene);
          },
          path, rows, resume))
    return 1;
  if (all_done_before)
    std::fprintf(stderr, "wrote %s%s: %zu members, all run before this resume%s\n", path.c_str(),
                 target->replaced() ? " (replacing the previous file)" : "", rows,
                 stats.wall_seconds > 0 ? (" (in " + format_duration(stats.wall_seconds) + ")").c_str()
                                        : " (their run time was not recorded)");
  else
    std::fprintf(stderr, "wrote %s%s: %zu members in %s (%s, lane occupancy %.1f %%)\n", path.c_str(),
                 target->replaced() ? " (replacing the previous file)" : "", rows,
                 format_duration(stats.wall_seconds).c_str(),
                 members_per_second(double(to_run), stats.wall_seconds - earlier_seconds).c_str(),
                 100 * stats.occupancy());
  return 0;
}

}  // namespace rotorsweep::apps
