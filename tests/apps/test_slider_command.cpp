// `rotorsweep slider` end to end (docs/slider.md "The experiment's slider"): scene in, complete HDF5
// file out with its datasets and units, `info` on it; bad keys, the wrong kind of scene and what the GPU
// does not run as exit code 2, no file written;
// SIGINT, SIGTERM and a full disk keep the finished members for --resume, also while substrate tables are
// built; shards
// merge to the single-process file; sample points, axes and memory bounded before any work.
#include <catch2/catch.hpp>
#include <filesystem>

#include "ensemble/gpu/gpu_backend.hpp"
#include "io/hdf5_file.hpp"
#include "support/cli.hpp"
#include "support/full_disk.hpp"
#include "support/result_datasets.hpp"
#include "support/scene_text.hpp"
#include "test_paths.hpp"

using namespace rotorsweep::testing;

namespace {

const std::string small_slider =
    "[slider]\ncolumns = 3\nrows = 2\n[substrate]\ncolumns = 9\nrows = 9\n[drive]\nrest = 0.5\nend = 2.5\n"
    "[sweep]\nseparation = { from = 7e-3, to = 9e-3, count = 3 }\n[observables]\nangles = true\n";

/// A 4 × 4 slider over one period of sliding at `separations` separations, members of some 9
/// CPU-milliseconds (384: about 2 s on two cores, 3.5 s on one); no shadow runs (the sweep's tests
/// run them through stops and claims).
std::string short_slider(int separations) {
  return "[slider]\ncolumns = 4\nrows = 4\n[drive]\nend = 2.5\n"
         "[sweep]\nseparation = { from = 5e-3, to = 13e-3, count = " +
         std::to_string(separations) + " }\n[numerics]\nglobal_error = \"local\"\n";
}

}  // namespace

TEST_CASE("slider writes a complete result file that info summarises", "[apps][slider]") {
  const auto dir = scratch_directory("slider");
  const auto scene = write_text(dir / "slider.toml", small_slider);
  const auto out = dir / "slider.h5";
  const auto run = run_cli("slider -q '" + scene.string() + "' -o '" + out.string() + "'", dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("3 members (1 sizes × 3 separations h = 7 … 9 mm"));
  const auto file = rotorsweep::io::Hdf5Location::open_file(out.string());
  CHECK(file.attribute_flag("complete"));
  CHECK(file.attribute_string("kind") == "slider");
  CHECK(file.attribute_double("period") == Catch::Detail::Approx(2.0));
  const auto members = file.open_group("members");
  CHECK(members.read_doubles("friction").size() == 3);
  CHECK(members.read_integers("columns") == std::vector<std::int64_t>{3, 3, 3});
  CHECK(members.shape("period_friction") == std::pair<hsize_t, hsize_t>{3, 1});
  CHECK(members.read_strings("status") == std::vector<std::string>{"ok", "ok", "ok"});
  std::vector<hsize_t> dims;
  file.open_group("series").read_doubles("angles", &dims);
  CHECK(dims == std::vector<hsize_t>{3, 64, 6});  // t = 0, 12 more during the rest, 51 while sliding
  CHECK(file.open_group("curve").read_doubles("A_paper").size() == 3);

  const auto info = run_cli("info '" + out.string() + "'", dir);
  CHECK(info.exit_code == 0);
  CHECK_THAT(info.output, Catch::Contains("kind         slider") && Catch::Contains("status       ok 3") &&
                              Catch::Contains("peak at h = ") && Catch::Contains("v (mm/s)     8\n"));
  CHECK(info.output.find("# scene") == std::string::npos);
  const auto with_scene = run_cli("info '" + out.string() + "' --scene", dir);
  CHECK(with_scene.exit_code == 0);
  CHECK_THAT(with_scene.output, Catch::Contains("# scene") && Catch::Contains("columns = 3"));
}

TEST_CASE("slider refuses bad scenes with exit code 2 and writes nothing", "[apps][slider]") {
  const auto dir = scratch_directory("slider-bad");
  const auto out = dir / "never.h5";
  const auto expect_refusal = [&](const std::string& command, const std::string& text,
                                  const std::string& key) {
    const auto scene = write_text(dir / "scene.toml", text);
    const auto run = run_cli(command + " -q '" + scene.string() + "' -o '" + out.string() + "'", dir);
    INFO(run.output);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains(key));
    CHECK_FALSE(std::filesystem::exists(out));
  };
  expect_refusal("slider", small_slider + "[numerics]\nrtol = 0.5\n", "numerics.rtol");
  const std::string one_h = "[sweep]\nseparation = [8e-3]\n";
  expect_refusal("slider", one_h + "[drive]\nspeed = [4e-3, 8e-3]\n", "drive.periods");
  expect_refusal("slider", one_h + "[drive]\nspeed = [4e-3, 8e-3]\nend = 30.0\n", "drive.end");
  expect_refusal("slider", one_h + "[drive]\nspeed = [4e-3, 0.0]\nperiods = 2\n", "drive.speed");
  expect_refusal("slider", one_h + "[drive]\nperiods = 0\n", "drive.periods");
  expect_refusal("slider", one_h + "[slider]\ndamping = [2.5e-6, -1.0]\n", "slider.damping");
  expect_refusal("slider", "[slider]\nspeed = 1.0\n[sweep]\nseparation = [8e-3]\n", "slider.speed");
  expect_refusal("slider", "[sweep]\nseparation = [8e-3]\n[substrate]\nangle = 4\n", "substrate.angle");
  expect_refusal("slider", "[slider]\ntilt = -3.5\n[sweep]\nseparation = [8e-3]\n", "slider.tilt");
  expect_refusal("slider", "[sweep]\nseparation = [8e-3]\n[observables]\nseries = false\nforces = true\n",
                 "observables.forces");
  expect_refusal("slider", one_h + "[numerics]\ndevice = \"gpu\"\nstepper = \"dopri5\"\n",
                 "numerics.stepper");
  if (!rotorsweep::ensemble::gpu_info().available)
    expect_refusal("slider --device gpu", small_slider, "run with --device cpu");
  expect_refusal("slider", "[model]\nrows = 20\n", "unknown; the scene sections are");
  expect_refusal("run", small_slider, "run them with `rotorsweep slider FILE`");
}

TEST_CASE("an interrupted slider scan keeps its finished members and resumes to the whole scan's datasets",
          "[apps][slider][resume]") {
  // the runs to be interrupted run on one thread and are signalled after 10 to 20 % of the whole scan's
  // wall time on two (random_delay)
  const std::size_t members = 384;
  const auto dir = scratch_directory("slider-resume");
  const auto scene = write_text(dir / "long.toml", short_slider(int(members)));
  const auto whole = dir / "whole.h5", out = dir / "out.h5";
  const auto whole_run = run_cli("slider -q '" + scene.string() + "' -o '" + whole.string() + "'", dir);
  REQUIRE(whole_run.exit_code == 0);
  const std::string base = "slider -q --threads 1 '" + scene.string() + "' -o '" + out.string() + "'";
  const auto partial = dir / "out.h5.partial";
  CHECK(run_cli(base + " --resume", dir).exit_code == 2);  // nothing to resume yet
  std::size_t kept = 0;
  bool resume = false;  // the second stop resumes the first's file, whether or not a member was done
  for (const auto& [signal, code] : {std::pair<std::string, int>{"INT", 130}, {"TERM", 143}}) {
    const std::string delay = random_delay(whole_run.seconds);
    INFO("whole scan " << whole_run.seconds << " s, SIG" << signal << " after " << delay << " s");
    const auto run = run_cli_signalled(base + (resume ? " --resume" : ""), dir, signal, delay);
    INFO(run.output);
    REQUIRE(run.exit_code == code);
    CHECK_THAT(run.output, Catch::Contains("stopped by SIG" + signal) && Catch::Contains("--resume"));
    CHECK_FALSE(std::filesystem::exists(out));
    REQUIRE(std::filesystem::exists(partial));
    const auto file = rotorsweep::io::Hdf5Location::open_file(partial.string());
    CHECK_FALSE(file.attribute_flag("complete"));
    std::size_t done = 0;
    for (const auto flag : file.open_group("members").read_flags("done")) done += flag != 0;
    CHECK(std::size_t(file.attribute_double("members_done")) == done);
    CHECK(done >= kept);
    CHECK(done < members);
    kept = done;
    resume = true;
  }
  const auto fresh = run_cli(base, dir);  // a fresh scan does not overwrite the partial file
  CHECK(fresh.exit_code == 2);
  CHECK_THAT(fresh.output, Catch::Contains("--resume") && Catch::Contains("--force"));
  const auto last = run_cli(base + " --resume", dir);
  INFO(last.output);
  REQUIRE(last.exit_code == 0);
  CHECK_THAT(last.output, Catch::Contains("resuming from"));
  CHECK_FALSE(std::filesystem::exists(partial));
  check_same_datasets(whole, out);
}

TEST_CASE("a disk that fills up mid-scan keeps the slider's finished members for --resume",
          "[apps][slider][resume][files]") {
  const auto dir = scratch_directory("slider-disk-fills-up");
  const auto scene = write_text(dir / "long.toml", short_slider(192));  // a 0.5 MB file
  check_full_disk_resumes("slider", scene, "", 192, dir);
}

TEST_CASE("slider shards merge to the single-process file", "[apps][slider][merge]") {
  const auto dir = scratch_directory("slider-shards");
  const auto scene = write_text(dir / "slider.toml", small_slider + "[initial]\nreplicas = 3\n");
  const auto whole = dir / "whole.h5";
  REQUIRE(run_cli("slider -q '" + scene.string() + "' -o '" + whole.string() + "'", dir).exit_code == 0);
  std::string shards;
  for (const int i : {1, 2, 3}) {
    const auto part = dir / ("part-" + std::to_string(i) + ".h5");
    const auto run = run_cli(
        "slider -q '" + scene.string() + "' --shard " + std::to_string(i) + "/3 -o '" + part.string() + "'",
        dir);
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    CHECK_THAT(run.output, Catch::Contains("shard " + std::to_string(i) + "/3"));
    shards = "'" + part.string() + "' " + shards;  // in reverse order
  }
  const auto two = run_cli(
      "merge " + shards.substr(0, shards.rfind(" '")) + " -o '" + (dir / "two.h5").string() + "'", dir);
  CHECK(two.exit_code == 2);  // a shard missing
  const auto merged = run_cli("merge " + shards + "-o '" + (dir / "merged.h5").string() + "'", dir);
  INFO(merged.output);
  REQUIRE(merged.exit_code == 0);
  check_same_datasets(whole, dir / "merged.h5");
  CHECK(rotorsweep::io::Hdf5Location::open_file((dir / "merged.h5").string()).attribute_string("kind") ==
        "slider");
}

TEST_CASE("slider bounds its sample points, axes and memory before any work, each refusal naming its key",
          "[apps][slider]") {
  const auto dir = scratch_directory("slider-bounds");
  const auto out = dir / "never.h5";
  const auto refused = [&](const std::string& text, const std::string& key, const std::string& prefix = "") {
    const auto scene = write_text(dir / "scene.toml", text);
    const auto run = run_cli("slider -q '" + scene.string() + "' -o '" + out.string() + "'", dir, prefix);
    INFO(text << "\n" << run.output);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains(key));
    CHECK(run.output.size() < 600);  // one message, no 300-digit number
    for (const char* left : {"never.h5", "never.h5.partial", ".never.h5.lock"})
      CHECK_FALSE(std::filesystem::exists(dir / left));
    return run.output;
  };
  const std::string small = "[slider]\ncolumns = 2\nrows = 2\n[sweep]\nseparation = 8e-3\n";
  // rest and sample points: bounded where the scene is read, not by the memory they would take
  refused(small + "[drive]\nrest = 1e9\nperiods = 1\n", "'drive.rest'");
  refused(small + "[drive]\nrest = 1e300\nperiods = 1\n", "'drive.rest'");
  refused(
      "[slider]\ncolumns = 2\nrows = 2\nspacing = 1e-12\n[sweep]\nseparation = 8e-3\n[drive]\nperiods = 1\n",
      "slider.spacing");
  refused(
      "[sweep]\nseparation = 8e-3\n[drive]\nperiods = 10000\n[observables]\nsamples_per_period = 100000\n"
      "angles = true\n",
      "'observables.samples_per_period'");
  CHECK_THAT(refused(small + "[drive]\nspeed = 1e-300\n", "'drive.end'"), Catch::Contains("1.6e+298 s"));
  // an axis's values differ, as sizes do; the plan's largest axis is named
  refused("[sweep]\nseparation = 8e-3\n[drive]\nspeed = [8e-3, 8e-3]\nperiods = 1\n", "'drive.speed'");
  refused("[sweep]\nseparation = [8e-3, 9e-3, 8e-3]\n",
          "'sweep.separation': has the value 0.008 more than once");
  refused("[sweep]\nseparation = { from = 8e-3, to = 8e-3, count = 3 }\n", "'sweep.separation'");
  refused("[sweep]\nseparation = 8e-3\n[slider]\ndamping = [2.5e-6, 2.5e-6]\n", "'slider.damping'");
  refused(
      "[sweep]\nseparation = { from = 5e-3, to = 12e-3, count = 3000000 }\n[drive]\nspeed = [1e-3, 2e-3, "
      "4e-3, 8e-3]\nperiods = 1\n",
      "'sweep.separation': the plan has 1.2e+07 members");
  // magnets: 10⁸ at most (box sums), 10⁶ under a turned slider (direct sums); none given with no edges
  refused("[sweep]\nseparation = 8e-3\n[substrate]\ncolumns = 10001\nrows = 10001\n", "'substrate.columns'");
  refused("[sweep]\nseparation = 8e-3\n[slider]\ntilt = 0.2\n[substrate]\ncolumns = 2000\nrows = 2000\n",
          "'substrate.columns'");
  refused("[sweep]\nseparation = 8e-3\n[substrate]\nextent = \"infinite\"\nrows = 30\n", "'substrate.rows'");
  refused("[sweep]\nseparation = 8e-3\n[substrate]\nextent = \"half\"\n", "'substrate.extent'");
  refused("[sweep]\nseparation = 8e-3\n[numerics]\nlinear_solver = \"lu\"\n", "'numerics.linear_solver'");
  refused("[sweep]\nseparation = 8e-3\n[slider]\ncolumns = 1025\n", "'slider.columns'");
  // memory: a 100 × 100 slider's dense lane blocks, refused before the partial file exists
  CHECK_THAT(refused("[slider]\ncolumns = 100\nrows = 100\n[sweep]\nseparation = 8e-3\n[numerics]\n"
                     "linear_solver = \"dense\"\n",
                     "GiB to work in", "ulimit -v 2000000; "),
             Catch::Contains("ulimit -v"));
  // matrix-free members need O(n), but a 1024 × 1024 slider's substrate tables alone are gigabytes
  refused("[slider]\ncolumns = 1024\nrows = 1024\n[sweep]\nseparation = 8e-3\n", "GiB to work in",
          "ulimit -v 2000000; ");
  // an empty shard runs no member and prints no NaN
  const auto scene = write_text(dir / "small.toml", small_slider);
  const auto empty =
      run_cli("slider -q '" + scene.string() + "' --shard 4/4 -o '" + (dir / "e.h5").string() + "'", dir);
  INFO(empty.output);
  CHECK(empty.exit_code == 0);
  CHECK_THAT(empty.output, Catch::Contains("no members run"));
  CHECK(empty.output.find("nan") == std::string::npos);
}

TEST_CASE("a slider scan stops on SIGINT and SIGTERM while its substrate tables are built",
          "[apps][slider][resume]") {
  // a million substrate magnets under a turned slider: every table node sums over all of them directly
  // (seconds per table)
  const auto dir = scratch_directory("slider-table-signal");
  const auto scene = write_text(dir / "big.toml",
                                "[slider]\ntilt = 0.1\n[substrate]\ncolumns = 1000\nrows = 1000\n[sweep]\n"
                                "separation = [8e-3, 9e-3]\n");
  for (const auto& [signal, code] : {std::pair<std::string, int>{"INT", 130}, {"TERM", 143}}) {
    const auto log = dir / "log.txt";
    // in the background of a shell without job control SIGINT starts out ignored: the scan must take it
    const auto result =
        detail::run_logged(std::string(ROTORSWEEP_EXECUTABLE) + " slider -q '" + scene.string() +
                               "' --force -o '" + (dir / "out.h5").string() + "' > '" + log.string() +
                               "' 2>&1 & pid=$!; sleep 1; kill -" + signal + " $pid; wait $pid",
                           log);
    INFO(result.output);
    CHECK(result.exit_code == code);
    CHECK_THAT(result.output,
               Catch::Contains("stopped by SIG" + signal) && Catch::Contains("0 of 2 members"));
    CHECK_FALSE(std::filesystem::exists(dir / ".out.h5.lock"));
  }
}
