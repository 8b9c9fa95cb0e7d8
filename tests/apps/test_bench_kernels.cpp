// `rotorsweep bench kernels` (apps/bench_kernels.cpp): every stepper's line with its share of the
// sincos bound for the right-hand side evaluations an attempt takes; bad options as exit code 2.
// No timing is asserted.
#include <catch2/catch.hpp>
#include <string>
#include <utility>

#include "support/cli.hpp"
#include "support/scene_text.hpp"

using namespace rotorsweep::testing;

TEST_CASE("bench kernels reports every stepper against the bound of its evaluations", "[apps][bench]") {
  const auto dir = scratch_directory("bench-kernels");
  const auto run = run_cli("bench kernels --rows 4 --repeats 1", dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("N = 4 rows") && Catch::Contains("bare SIMD sincos") &&
                             Catch::Contains("stage RHS SIMD (displaced)"));
  // the evaluations per attempt: Rosenbrock stages (the linearisation is the first), dopri5's stages
  const auto line_of = [&](const std::string& stepper) {
    const auto start = run.output.find("steps " + stepper + " ");
    return start == std::string::npos ? std::string()
                                      : run.output.substr(start, run.output.find('\n', start) - start);
  };
  for (const auto& [stepper, evaluations] : {std::pair<std::string, int>{"rodas4", 6},
                                             {"rodas4p2", 6},
                                             {"rodas5p", 8},
                                             {"ros2", 2},
                                             {"dopri5", 7}}) {
    INFO(stepper);
    CHECK_THAT(line_of(stepper),
               Catch::Contains("member-steps/s") &&
                   Catch::EndsWith("of the bound for " + std::to_string(evaluations) + " RHS)"));
  }
}

TEST_CASE("bench kernels refuses bad options", "[apps][bench]") {
  const auto dir = scratch_directory("bench-kernels-bad");
  for (const char* options : {"--rows 1", "--rows 5000", "--repeats 0", "--rows x"}) {
    const auto run = run_cli(std::string("bench kernels ") + options, dir);
    INFO(options << "\n" << run.output);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains("--rows") || Catch::Contains("--repeats"));
  }
}
