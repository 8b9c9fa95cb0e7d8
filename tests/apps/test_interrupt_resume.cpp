// Interrupting `rotorsweep run` (SIGINT, SIGTERM) and `--resume`: exit codes 130 and 143, the
// finished members kept in OUT.partial, resumed twice to a file whose datasets equal an
// uninterrupted run's byte for byte; a changed scene or a missing partial file is exit code 2.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "io/hdf5_file.hpp"
#include "support/cli.hpp"
#include "support/result_datasets.hpp"
#include "support/scene_text.hpp"

using rotorsweep::io::Hdf5Location;
using namespace rotorsweep::testing;
namespace fs = std::filesystem;

namespace {

/// 2000 members that take a few seconds on two cores.
const char* long_scene =
    "[model]\nrows = 20\n[drive]\ng = [0.0011]\n[sweep]\nA = { from = 0.5, to = 12.0, count = 200 }\n"
    "[initial]\nkinds = [\"AFM\", \"random\"]\nreplicas = 5\n[schedule]\nrelax_periods = 10\naverage_periods "
    "= 10\n";

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST_CASE("an interrupted run resumes to the uninterrupted run's datasets", "[apps][run][resume]") {
  const auto dir = scratch_directory("interrupt-resume");
  const auto scene = dir / "long.toml";
  write_text(scene, long_scene);
  const std::string base = "run '" + scene.string() + "' -q -o '" + (dir / "out.h5").string() + "'";
  REQUIRE(
      run_cli("run '" + scene.string() + "' -q -o '" + (dir / "whole.h5").string() + "'", dir).exit_code ==
      0);
  const auto partial = dir / "out.h5.partial";

  CHECK(run_cli(base + " --resume", dir).exit_code == 2);  // nothing to resume yet

  const auto first = run_cli_signalled(base, dir, "INT", "0.5");
  INFO(first.output);
  REQUIRE(first.exit_code == 130);
  CHECK_THAT(first.output, Catch::Contains("stopped by SIGINT") && Catch::Contains("--resume"));
  REQUIRE(fs::exists(partial));
  CHECK_FALSE(fs::exists(dir / "out.h5"));
  {
    const auto file = Hdf5Location::open_file(partial.string());
    CHECK_FALSE(file.attribute_flag("complete"));
    const double kept = file.attribute_double("members_done");
    CHECK(kept > 0);
    CHECK(kept < 2000);
  }

  // a changed scene does not resume and leaves the partial file as it is
  const std::string before = bytes_of(partial);
  write_text(scene, std::string(long_scene) + "[numerics]\nrtol = 1e-7\n");
  const auto changed = run_cli(base + " --resume", dir);
  CHECK(changed.exit_code == 2);
  CHECK_THAT(changed.output, Catch::Contains("different scene"));
  CHECK(bytes_of(partial) == before);
  write_text(scene, long_scene);

  const auto second = run_cli_signalled(base + " --resume", dir, "TERM", "0.5");
  INFO(second.output);
  REQUIRE(second.exit_code == 143);
  CHECK_THAT(second.output, Catch::Contains("resuming from") && Catch::Contains("stopped by SIGTERM"));

  const auto last = run_cli(base + " --resume", dir);
  INFO(last.output);
  REQUIRE(last.exit_code == 0);
  CHECK_FALSE(fs::exists(partial));
  const auto whole = Hdf5Location::open_file((dir / "whole.h5").string());
  const auto resumed = Hdf5Location::open_file((dir / "out.h5").string());
  const auto paths = dataset_paths(whole);
  CHECK(paths == dataset_paths(resumed));
  for (const auto& path : paths) {
    INFO(path);
    CHECK(whole.read_bytes(path) == resumed.read_bytes(path));
  }
  CHECK(resumed.attribute_flag("complete"));
}
