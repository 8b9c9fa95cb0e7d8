// Interrupting `rotorsweep run` (SIGINT, SIGTERM, SIGKILL, a disk that fills up) and `--resume`:
// the finished members stay in OUT.h5.partial, and resuming ends in datasets equal to an
// uninterrupted run's byte for byte; a changed scene or a missing partial file is exit code 2.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/hdf5_file.hpp"
#include "io/result_file.hpp"
#include "io/scene_parser.hpp"
#include "support/cli.hpp"
#include "support/full_disk.hpp"
#include "support/result_datasets.hpp"
#include "support/scene_text.hpp"
#include "test_paths.hpp"

using rotorsweep::io::Hdf5Location;
using namespace rotorsweep::testing;
namespace fs = std::filesystem;

namespace {

/// 800 members of some 3.5 CPU-milliseconds each (about 1.5 s on two cores, 2.8 s on one): the runs to
/// be interrupted run on one thread and are signalled after 10 to 20 % of the whole run's wall time on
/// two (random_delay), when some of their members are written and most are not.
const char* long_scene =
    "[model]\nrows = 20\n[drive]\ng = [0.0011]\n[sweep]\nA = { from = 0.5, to = 12.0, count = 80 }\n"
    "[initial]\nkinds = [\"AFM\", \"random\"]\nreplicas = 5\n[schedule]\nrelax_periods = 2\naverage_periods "
    "= 2\n";
const std::size_t long_scene_members = 800;

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::size_t rows_done(const fs::path& path) {
  std::size_t count = 0;
  for (auto flag : Hdf5Location::open_file(path.string()).open_group("members").read_flags("done"))
    count += flag != 0;
  return count;
}

}  // namespace

TEST_CASE("an interrupted run resumes to the uninterrupted run's datasets", "[apps][run][resume]") {
  const auto dir = scratch_directory("interrupt-resume");
  const auto scene = dir / "long.toml";
  write_text(scene, long_scene);
  // the interrupted runs on one thread (the whole run's bits on any number)
  const std::string base =
      "run '" + scene.string() + "' -q --threads 1 -o '" + (dir / "out.h5").string() + "'";
  const auto whole = run_cli("run '" + scene.string() + "' -q -o '" + (dir / "whole.h5").string() + "'", dir);
  REQUIRE(whole.exit_code == 0);
  const auto partial = dir / "out.h5.partial";

  CHECK(run_cli(base + " --resume", dir).exit_code == 2);  // nothing to resume yet

  const std::string delay = random_delay(whole.seconds);
  INFO("whole run " << whole.seconds << " s, first signal after " << delay << " s");
  const auto first = run_cli_signalled(base, dir, "INT", delay);
  INFO(first.output);
  REQUIRE(first.exit_code == 130);
  CHECK_THAT(first.output, Catch::Contains("stopped by SIGINT") && Catch::Contains("--resume"));
  REQUIRE(fs::exists(partial));
  CHECK_FALSE(fs::exists(dir / "out.h5"));
  std::size_t kept = 0;
  {
    const auto file = Hdf5Location::open_file(partial.string());
    CHECK_FALSE(file.attribute_flag("complete"));
    kept = std::size_t(file.attribute_double("members_done"));
    CHECK(kept == rows_done(partial));
    CHECK(kept > 0);
    CHECK(kept < long_scene_members);
  }

  // a changed scene does not resume and leaves the partial file as it is; nor does a fresh run
  const std::string before = bytes_of(partial);
  write_text(scene, std::string(long_scene) + "[numerics]\nrtol = 1e-7\n");
  const auto changed = run_cli(base + " --resume", dir);
  CHECK(changed.exit_code == 2);
  CHECK_THAT(changed.output, Catch::Contains("different scene"));
  CHECK(bytes_of(partial) == before);
  write_text(scene, long_scene);
  const auto fresh = run_cli(base, dir);
  CHECK(fresh.exit_code == 2);
  CHECK_THAT(fresh.output, Catch::Contains("--resume") && Catch::Contains("--force"));
  CHECK(bytes_of(partial) == before);

  const std::string second_delay = random_delay(whole.seconds);
  INFO("second signal after " << second_delay << " s");
  const auto second = run_cli_signalled(base + " --resume", dir, "TERM", second_delay);
  INFO(second.output);
  REQUIRE(second.exit_code == 143);
  CHECK_THAT(second.output, Catch::Contains("resuming from") && Catch::Contains("stopped by SIGTERM"));
  CHECK(rows_done(partial) > kept);
  kept = rows_done(partial);

  // SIGKILL: no handler runs; the batches flushed before it are in the file, which stays readable
  const std::string third_delay = random_delay(whole.seconds);
  INFO("third signal after " << third_delay << " s");
  const auto third = run_cli_signalled(base + " --resume --flush-seconds 0.1", dir, "KILL", third_delay);
  INFO(third.output);
  REQUIRE(third.exit_code == 137);
  CHECK(rows_done(partial) > kept);
  CHECK(rows_done(partial) < long_scene_members);

  const auto last = run_cli(base + " --resume", dir);
  INFO(last.output);
  REQUIRE(last.exit_code == 0);
  CHECK_FALSE(fs::exists(partial));
  check_same_datasets(dir / "whole.h5", dir / "out.h5");
}

TEST_CASE("an allocation that fails in a worker thread is one message, exit 1, and the run resumes",
          "[apps][run][resume]") {
  // N = 20 first (a lane block of some 80 kB with 8 lanes), then N = 2000, whose lane block (about 1 MB per
  // lane: 2 MB with SSE2's 2 lanes, 8 MB with AVX-512's 8) the preloaded posix_memalign refuses
  const auto dir = scratch_directory("worker-allocation");
  const auto scene = dir / "two_sizes.toml";
  write_text(scene,
             "[model]\nrows = [20, 2000]\n[drive]\ng = [0.05]\n[sweep]\nA = [1.0]\n"
             "[schedule]\nrelax_periods = 0\naverage_periods = 1\n");
  const std::string base = "run '" + scene.string() + "' -q -o '" + (dir / "out.h5").string() + "'";
  REQUIRE(
      run_cli("run '" + scene.string() + "' -q -o '" + (dir / "whole.h5").string() + "'", dir).exit_code ==
      0);
  const auto failed = run_cli(base, dir,
                              "export LD_PRELOAD='" ROTORSWEEP_FAILING_ALLOCATION
                              "' ROTORSWEEP_TEST_ALLOCATION_LIMIT=1000000; ");
  INFO(failed.output);
  CHECK(failed.exit_code == 1);
  CHECK_THAT(failed.output, Catch::Contains("out of memory") && Catch::Contains("--resume"));
  CHECK_THAT(failed.output, !Catch::Contains("terminate") && !Catch::Contains("Aborted"));
  const auto partial = dir / "out.h5.partial";
  REQUIRE(fs::exists(partial));
  CHECK_FALSE(fs::exists(dir / "out.h5"));
  CHECK(rows_done(partial) == 1);  // the N = 20 member, written before the failure
  const auto resumed = run_cli(base + " --resume", dir);
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  check_same_datasets(dir / "whole.h5", dir / "out.h5");
}

TEST_CASE("a killed shard resumes and merges to the unsharded file", "[apps][run][resume][merge]") {
  const auto dir = scratch_directory("kill-shard");
  const auto scene = dir / "long.toml";
  write_text(scene, long_scene);
  const auto run = [&](const std::string& arguments) {
    return "run '" + scene.string() + "' -q " + arguments;
  };
  const auto whole = run_cli(run("-o '" + (dir / "whole.h5").string() + "'"), dir);
  REQUIRE(whole.exit_code == 0);
  const std::string shard = "--shard 1/2 -o '" + (dir / "one.h5").string() + "'";
  const std::string delay = random_delay(whole.seconds);
  INFO("whole run " << whole.seconds << " s, signal after " << delay << " s");
  const auto killed = run_cli_signalled(run(shard + " --threads 1 --flush-seconds 0.1"), dir, "KILL", delay);
  REQUIRE(killed.exit_code == 137);
  REQUIRE(fs::exists(dir / "one.h5.partial"));
  CHECK(run_cli(run("--shard 2/2 -o '" + (dir / "one.h5").string() + "' --resume"), dir).exit_code == 2);
  const auto resumed = run_cli(run(shard + " --resume"), dir);
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  REQUIRE(run_cli(run("--shard 2/2 -o '" + (dir / "two.h5").string() + "'"), dir).exit_code == 0);
  REQUIRE(run_cli("merge '" + (dir / "one.h5").string() + "' '" + (dir / "two.h5").string() + "' -o '" +
                      (dir / "merged.h5").string() + "'",
                  dir)
              .exit_code == 0);
  check_same_datasets(dir / "whole.h5", dir / "merged.h5");
}

TEST_CASE("a resume with every member done keeps the run's figures and says so", "[apps][run][resume]") {
  const auto dir = scratch_directory("resume-all-done");
  // the members' own error only: this checks the file's bookkeeping, not the shadow runs' resume
  const auto scene_path =
      write_text(dir / "small.toml", std::string(long_scene) + "[numerics]\nglobal_error = \"local\"\n");
  const auto whole = run_cli("run '" + scene_path.string() + "' -q -o '" + (dir / "whole.h5").string() + "'", dir);
  REQUIRE(whole.exit_code == 0);
  const auto written = Hdf5Location::open_file((dir / "whole.h5").string());
  // a run killed after its last members reached the file, before it recorded its statistics: every row done
  const auto scene = rotorsweep::io::parse_scene_file(scene_path.string());
  {
    const rotorsweep::io::ResultFile file(
        (dir / "out.h5.partial").string(), scene,
        rotorsweep::io::Provenance{scene_path.string(), written.attribute_string("version"),
                                   written.attribute_string("revision"), "cpu", written.attribute_string("isa")});
    const rotorsweep::ensemble::MemberPlan plan(scene);
    std::vector<rotorsweep::ensemble::MemberResult> results;
    rotorsweep::ensemble::run_members(
        scene, {plan.size(), [&](std::size_t k) { return plan[k]; }}, {.threads = 1},
        [&](rotorsweep::ensemble::MemberResult&& result) { results.push_back(std::move(result)); });
    file.write_results(plan, std::move(results));
  }
  REQUIRE(rows_done(dir / "out.h5.partial") == long_scene_members);
  const auto resumed =
      run_cli("run '" + scene_path.string() + "' -o '" + (dir / "out.h5").string() + "' --resume", dir);
  INFO(resumed.output);
  REQUIRE(resumed.exit_code == 0);
  CHECK_THAT(resumed.output, Catch::Contains("800 members done, 0 to run") &&
                                 Catch::Contains("800 members, all run before this resume (their run time was "
                                                 "not recorded)"));
  CHECK(resumed.output.find("no members run") == std::string::npos);
  check_same_datasets(dir / "whole.h5", dir / "out.h5");
  const auto out = Hdf5Location::open_file((dir / "out.h5").string());
  CHECK(out.attribute_double("lane_width") == written.attribute_double("lane_width"));  // not 1
}

TEST_CASE("a disk that fills up mid-run keeps the finished members for --resume",
          "[apps][run][resume][files]") {
  const auto dir = scratch_directory("disk-fills-up");
  const auto scene = dir / "long.toml";
  write_text(scene, long_scene);
  // a batch of 100 members written every eighth of the way
  check_full_disk_resumes("run", scene, "--flush-members 100", long_scene_members, dir);
}

TEST_CASE("a second writer of a running run's output is refused and the first run is untouched",
          "[apps][run][lock]") {
  const auto dir = scratch_directory("second-writer");
  const auto scene = dir / "long.toml";
  write_text(scene, long_scene);
  const auto slider = write_text(dir / "slider.toml", "[sweep]\nseparation = 8e-3\n");
  const auto log = dir / "log.txt";
  const std::string exe = ROTORSWEEP_EXECUTABLE, out = "'" + (dir / "out.h5").string() + "'";
  // the first run in the background (on one thread: some 3 s); while it runs, every way of writing there:
  // each must exit 2
  const std::string second = exe + " run '" + scene.string() + "' -q -o " + out;
  const std::string command =
      "cd '" + dir.string() + "'; " + second + " --threads 1 2> first.txt & pid=$!; " +
      "until [ -e out.h5.partial ] || ! kill -0 $pid 2>/dev/null; do sleep 0.01; done; " +  //
      "for extra in '' --force --resume '--shard 1/2'; do " + second +
      " $extra 2>> refused.txt; echo \"run $extra: $?\"; done; " +  //
      exe + " slider -q '" + slider.string() + "' -o " + out + " 2>> refused.txt; echo \"slider: $?\"; " +
      exe + " merge part.h5 -o " + out + " 2>> refused.txt; echo \"merge: $?\"; " +
      "wait $pid; echo \"first: $?\"; cat refused.txt";
  const auto result = detail::run_logged("(" + command + ") > '" + log.string() + "' 2>&1", log);
  INFO(result.output);
  for (const char* line : {"run : 2", "run --force: 2", "run --resume: 2", "run --shard 1/2: 2", "slider: 2"})
    CHECK_THAT(result.output, Catch::Contains(line));
  CHECK_THAT(result.output, Catch::Contains("first: 0"));
  CHECK_THAT(result.output, Catch::Contains("being written by another process (PID "));
  const auto file = Hdf5Location::open_file((dir / "out.h5").string());
  CHECK(file.attribute_flag("complete"));
  CHECK(rows_done(dir / "out.h5") == long_scene_members);
  CHECK_FALSE(fs::exists(dir / ".out.h5.lock"));
}

TEST_CASE("no writer takes a running run's partial, temporary or lock file, and the run keeps its own file",
          "[apps][run][lock]") {
  const auto dir = scratch_directory("covered-writers");
  const auto scene = dir / "long.toml";
  // ten times the long scene: it runs while every other writer tries its files, then it is stopped
  write_text(
      scene,
      std::string(long_scene).replace(std::string(long_scene).find("replicas = 5"), 12, "replicas = 50"));
  const auto log = dir / "log.txt";
  const std::string exe = ROTORSWEEP_EXECUTABLE;
  const auto at = [&](const std::string& name) { return " -o '" + (dir / name).string() + "'"; };
  // shards that merge, and a slider scene: refused for the output alone
  const auto tiny =
      write_text(dir / "tiny.toml", "[model]\nrows = 4\n[drive]\ng = 0.01\n[sweep]\nA = [1, 2]\n");
  const auto slider = write_text(dir / "slider.toml", "[sweep]\nseparation = 8e-3\n");
  for (const char* i : {"1", "2"})
    REQUIRE(run_cli("run '" + tiny.string() + "' -q --shard " + std::string(i) + "/2" +
                        at("s" + std::string(i) + ".h5"),
                    dir)
                .exit_code == 0);
  const std::vector<std::pair<std::string, std::string>> writers = {
      {"run partial", "run '" + scene.string() + "' -q --force" + at("out.h5.partial")},
      {"run shard", "run '" + scene.string() + "' -q --shard 1/2" + at("out.h5.partial")},
      {"merge",
       "merge '" + (dir / "s1.h5").string() + "' '" + (dir / "s2.h5").string() + "'" + at("out.h5.partial")},
      {"landscape partial", "landscape curves -q --samples 10 --force" + at("out.h5.partial")},
      {"landscape temporary", "landscape curves -q --samples 10 --force" + at(".out.h5.12345.part")},
      {"couplings partial", "couplings --range 1 --force" + at("out.h5.partial")},
      {"couplings lock", "couplings --range 1 --force" + at(".out.h5.lock")},
      {"table partial", "table --replicas 1 --force" + at("out.h5.partial")},
      {"slider partial", "slider '" + slider.string() + "' -q --force" + at("out.h5.partial")},
  };
  std::string command = "cd '" + dir.string() + "'; " + exe + " run '" + scene.string() + "' -q" +
                        at("out.h5") + " 2> first.txt & pid=$!; " +
                        "until [ -e out.h5.partial ] || ! kill -0 $pid 2>/dev/null; do sleep 0.01; done; ";
  for (const auto& [name, arguments] : writers)
    command += exe + " " + arguments + " > /dev/null 2>> refused.txt; echo \"" + name + ": $?\"; ";
  command += "kill -INT $pid; wait $pid; echo \"first: $?\"; cat first.txt refused.txt";
  const auto result = detail::run_logged("(" + command + ") > '" + log.string() + "' 2>&1", log);
  INFO(result.output);
  for (const auto& [name, arguments] : writers) CHECK_THAT(result.output, Catch::Contains(name + ": 2\n"));
  std::size_t refusals = 0;
  for (std::size_t at = 0; (at = result.output.find("error: output path", at)) != std::string::npos; ++at)
    ++refusals;
  CHECK(refusals == writers.size());
  // the run stopped with its own partial file, whose rows it counts
  CHECK_THAT(result.output, Catch::Contains("first: 130") && Catch::Contains("kept in"));
  const auto partial = dir / "out.h5.partial";
  REQUIRE(fs::exists(partial));
  CHECK(std::size_t(Hdf5Location::open_file(partial.string()).attribute_double("members_done")) ==
        rows_done(partial));
  CHECK(Hdf5Location::open_file(partial.string()).open_group("members").shape("done").first == 10 * long_scene_members);
  for (const auto& entry : fs::directory_iterator(dir)) {
    const auto name = entry.path().filename().string();
    CHECK((name.ends_with(".toml") || name == "out.h5.partial" || name == "s1.h5" || name == "s2.h5" ||
           name.ends_with(".txt")));
  }
}

TEST_CASE("a small result on a nearly full disk is refused up front, also by --resume and merge",
          "[apps][run][resume][merge][files]") {
  const auto dir = scratch_directory("disk-nearly-full");
  const auto small = dir / "small";
  // a 1 MiB file system of our own: room for the members' rows, not for the space the curves reserve
  const std::string mount = private_tmpfs(small, "1m");
  if (mount.empty()) {
    WARN("skipped: no private tmpfs mount here (unshare -rm and mount -t tmpfs must work)");
    return;
  }
  const auto scene =
      write_text(dir / "tiny.toml", "[model]\nrows = 4\n[drive]\ng = 0.01\n[sweep]\nA = [1, 2]\n");
  const std::string exe = ROTORSWEEP_EXECUTABLE, run = exe + " run '" + scene.string() + "' -q";
  for (const char* i : {"1", "2"})
    REQUIRE(run_cli("run '" + scene.string() + "' -q --shard " + std::string(i) + "/2 -o '" +
                        (dir / ("s" + std::string(i) + ".h5")).string() + "'",
                    dir)
                .exit_code == 0);
  // a stopped run's partial file: the whole run's file, not complete
  REQUIRE(
      run_cli("run '" + scene.string() + "' -q -o '" + (dir / "whole.h5").string() + "'", dir).exit_code ==
      0);
  fs::copy_file(dir / "whole.h5", dir / "out.h5.partial");
  Hdf5Location::open_file_for_writing((dir / "out.h5.partial").string()).set_flag("complete", false);
  const auto log = dir / "log.txt";
  const std::string out = (small / "out.h5").string();
  const std::string commands = run + " -o '" + out + "'; echo \\\"run: \\$?\\\"; ls '" + small.string() +
                               "'; cp '" + (dir / "out.h5.partial").string() + "' '" + small.string() +
                               "/'; " + run + " -o '" + out + "' --resume; echo \\\"resume: \\$?\\\"; " +
                               exe + " merge '" + (dir / "s1.h5").string() + "' '" +
                               (dir / "s2.h5").string() + "' -o '" + (small / "merged.h5").string() +
                               "'; echo \\\"merge: \\$?\\\"; ls '" + small.string() + "'";
  const int status = std::system((mount + commands + "\" > '" + log.string() + "' 2>&1").c_str());
  std::ifstream in(log);
  const std::string output{std::istreambuf_iterator<char>(in), {}};
  INFO(output);
  CHECK(WEXITSTATUS(status) == 0);
  for (const char* refused : {"run: 2", "resume: 2", "merge: 2"})
    CHECK_THAT(output, Catch::Contains(refused));
  CHECK_THAT(output,
             Catch::Contains("the curves written at the end need about") && Catch::Contains("MiB on disk"));
  // nothing made but the partial file copied in, which is kept as it was
  CHECK_THAT(output, Catch::EndsWith("out.h5.partial\n"));
  CHECK_THAT(output, !Catch::Contains("merged.h5") && !Catch::Contains("out.h5\n"));
}
