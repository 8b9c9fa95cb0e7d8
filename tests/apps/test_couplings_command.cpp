// `rotorsweep couplings`: the printed and written table (docs/model.md §8), and bad options as exit
// code 2 naming the option.
#include <catch2/catch.hpp>
#include <fstream>
#include <iterator>

#include "support/cli.hpp"
#include "support/scene_text.hpp"

using namespace rotorsweep::testing;

TEST_CASE("couplings prints and writes the dipolar table", "[apps][couplings]") {
  const auto dir = scratch_directory("couplings");
  const auto csv = dir / "table.csv";
  const auto run = run_cli("couplings --range 2 -o '" + csv.string() + "'", dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("a = 1.8030853547") && Catch::Contains("1.0851925431") &&
                             Catch::Contains("0.9396773000") && Catch::Contains("a_M = "));
  std::ifstream in(csv);
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  CHECK_THAT(text, Catch::Contains("u,b,c\n1,1.0851925") && Catch::Contains("\n2,0.250104"));

  const auto finite = run_cli("couplings --range 1 --row-length 1", dir);
  CHECK(finite.exit_code == 0);
  CHECK_THAT(finite.output, Catch::Contains("a = 0.0000000000") && Catch::Contains("1.0000000000"));
}

TEST_CASE("couplings refuses bad options", "[apps][couplings]") {
  const auto dir = scratch_directory("couplings-bad");
  for (const char* arguments :
       {"--range 0", "--range -3", "--row-length 0", "--row-length ten", "--row-length -2"}) {
    INFO(arguments);
    const auto run = run_cli(std::string("couplings ") + arguments, dir);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output,
               Catch::Contains(std::string(arguments).substr(0, std::string(arguments).find(' '))));
  }
}
