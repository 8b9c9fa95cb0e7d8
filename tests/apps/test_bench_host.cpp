// `rotorsweep bench host` (apps/bench_host.cpp): its five steps each with a finite positive rate, the
// result file it writes removed afterwards; bad options as exit code 2. No timing is asserted.
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
                                   "file writes alone (one thread)", "file writes alone, rows scattered (one thread)"}) {
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
