// `rotorsweep bench host` (apps/bench_host.cpp): its six steps each with a finite positive rate, the
// result file it writes removed afterwards and when a signal stops it; bad options and a read-only scratch
// directory as exit code 2. No timing is asserted.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "support/cli.hpp"
#include "support/scene_text.hpp"

using namespace rotorsweep::testing;

TEST_CASE("bench host times the fill, the summaries and the file writes and leaves no file",
          "[apps][bench]") {
  const auto dir = scratch_directory("bench-host");
  const auto scratch = dir / "scratch";
  std::filesystem::create_directory(scratch);
  const auto run = run_cli(
      "bench host --rows 4,6 --members 600 --repeats 1 --threads 2 --scratch " + scratch.string(), dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("600 members per chunk, 2 host threads"));
  for (const std::string rows : {"4", "6"})
    for (const std::string step : {"fill (one thread)", "summaries", "summaries and file writes",
                                   "rows packed for the file (one thread)", "file writes alone (one thread)",
                                   "file writes alone, rows scattered (one thread)"}) {
      INFO("N = " << rows << ": " << step);
      const std::string cell = "| " + rows + " | " + step + " |";
      const auto at = run.output.find(cell);
      REQUIRE(at != std::string::npos);
      std::istringstream cells(run.output.substr(at + cell.size()));
      double seconds = 0, micro = 0;
      char bar = 0;
      cells >> seconds >> bar >> micro;
      CHECK(std::isfinite(micro));
      CHECK(micro > 0);
    }
  CHECK(std::filesystem::is_empty(scratch));
}

TEST_CASE("bench host refuses bad options", "[apps][bench]") {
  const auto dir = scratch_directory("bench-host-bad");
  for (const char* options : {"--members 0", "--rows 1", "--repeats 0", "--scratch /nonexistent/dir"}) {
    const auto run = run_cli(std::string("bench host ") + options, dir);
    INFO(options << "\n" << run.output);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains("--members") || Catch::Contains("--rows") ||
                               Catch::Contains("--repeats") || Catch::Contains("--scratch"));
  }
}

TEST_CASE("bench host stopped by a signal removes its scratch file; a read-only scratch is refused",
          "[apps][bench][files]") {
  const auto dir = scratch_directory("bench-host-signal");
  const auto scratch = dir / "scratch";
  std::filesystem::create_directory(scratch);
  // signalled once its scratch file exists (an event, not a clock): a run of 100 repeats is mid-way then
  const auto log = dir / "cli-output.txt";
  const auto stopped = detail::run_logged(
      std::string(ROTORSWEEP_EXECUTABLE) + " bench host --rows 16 --members 100000 --repeats 100 --threads 1 " +
          "--scratch '" + scratch.string() + "' > '" + log.string() + "' 2>&1 & pid=$!; until [ -n \"$(ls '" +
          scratch.string() + "')\" ] || ! kill -0 $pid 2>/dev/null; do sleep 0.01; done; kill -INT $pid; wait $pid",
      log);
  INFO(stopped.output);
  CHECK(stopped.exit_code == 130);
  CHECK_THAT(stopped.output, Catch::Contains("stopped by SIGINT"));
  CHECK(std::filesystem::is_empty(scratch));

  // a read-only file system (a private read-only tmpfs, where this machine can mount one)
  const auto mount = private_tmpfs(dir / "read-only", "1m");
  if (mount.empty()) return;
  const auto refused = detail::run_logged(
      "unshare -rm sh -c \"mount -t tmpfs -o ro,size=1m tmpfs '" + (dir / "read-only").string() + "' && " +
          std::string(ROTORSWEEP_EXECUTABLE) + " bench host --rows 4 --members 10 --repeats 1 --scratch '" +
          (dir / "read-only").string() + "' > '" + log.string() + "' 2>&1\"",
      log);
  INFO(refused.output);
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.output, Catch::Contains("error: --scratch") && Catch::Contains("cannot be written there"));
  CHECK(refused.output.find("filesystem") == std::string::npos);
}
