// `rotorsweep couplings`: the printed and written table (docs/model.md §8), bad options as exit code 2
// naming the option, files replaced only when they are its own tables (or with --force), and a long
// table stopped at once by SIGINT or SIGTERM (in `landscape … --range` too).
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "io/hdf5_file.hpp"
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

TEST_CASE("couplings and table -o replace only a table they wrote themselves, unless --force",
          "[apps][couplings][files]") {
  namespace fs = std::filesystem;
  const auto dir = scratch_directory("couplings-replace");
  const auto read = [](const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string{std::istreambuf_iterator<char>(in), {}};
  };
  auto result = rotorsweep::io::Hdf5Location::create_file((dir / "result.h5").string());
  result.set_attribute("marker", 1.0);
  result.close();
  const auto before = read(dir / "result.h5");
  write_text(dir / "scene.toml", "[model]\nrows = 4\n");
  write_text(dir / "notes.csv", "my notes\n");
  for (const char* other : {"result.h5", "scene.toml", "notes.csv"})
    for (const std::string command : {"couplings --range 2", "table --replicas 1"}) {
      INFO(command << " -o " << other);
      const auto refused = run_cli(command + " -o '" + (dir / other).string() + "'", dir);
      CHECK(refused.exit_code == 2);
      CHECK_THAT(refused.output,
                 Catch::Contains("not a table this command wrote") && Catch::Contains("--force"));
    }
  CHECK(read(dir / "result.h5") == before);
  CHECK(read(dir / "scene.toml") == "[model]\nrows = 4\n");
  CHECK(read(dir / "notes.csv") == "my notes\n");
  // its own table again, and another file with --force
  const auto table = dir / "table.csv";
  REQUIRE(run_cli("couplings --range 2 -o '" + table.string() + "'", dir).exit_code == 0);
  const auto again = run_cli("couplings --range 3 -o '" + table.string() + "'", dir);
  CHECK(again.exit_code == 0);
  CHECK_THAT(again.output, Catch::Contains("(replaced)"));
  CHECK_THAT(read(table), Catch::Contains("range 3"));
  CHECK(run_cli("couplings --range 2 --force -o '" + (dir / "notes.csv").string() + "'", dir).exit_code == 0);
  CHECK_THAT(read(dir / "notes.csv"), Catch::StartsWith("# point-dipole couplings"));
}

TEST_CASE("a long coupling table stops at once on SIGINT and SIGTERM, in couplings and landscape",
          "[apps][couplings][landscape]") {
  const auto dir = scratch_directory("couplings-signal");
  const std::string long_table = " --range 100000 --row-length 100000";
  for (const auto& [signal, code] : {std::pair<std::string, int>{"INT", 130}, {"TERM", 143}})
    for (const auto& command :
         {"couplings" + long_table + " -o '" + (dir / "t.csv").string() + "'",
          "landscape chambers -q" + long_table + " -o '" + (dir / "c.h5").string() + "'"}) {
      // run_cli_signalled starts it in the background of a shell, where SIGINT starts out ignored
      const auto run = run_cli_signalled(command, dir, signal, "0.5");
      INFO(command << ": " << run.output);
      CHECK(run.exit_code == code);
      CHECK_THAT(run.output, Catch::Contains("stopped by SIG" + signal + ": nothing written"));
      for (const auto& entry : std::filesystem::directory_iterator(dir))
        CHECK(entry.path().filename() == "cli-output.txt");
    }
}
