// Shards (`run --shard I/N`) and `merge`: three shards merged give the unsharded file's datasets
// byte for byte (period series, estimators, row profiles, random starts included); missing, doubled or
// foreign shards and bad --shard values exit with code 2 and write nothing.
#include <catch2/catch.hpp>
#include <filesystem>

#include "io/hdf5_file.hpp"
#include "support/cli.hpp"
#include "support/result_datasets.hpp"
#include "support/scene_text.hpp"

using rotorsweep::io::Hdf5Location;
using namespace rotorsweep::testing;

namespace {

const char* shard_scene =
    "[model]\nrows = [4, 10]\n[drive]\ng = [0.001, 0.01]\n[sweep]\nA = { from = 0.5, to = 12, count = 12 }\n"
    "[initial]\nkinds = [\"AFM\", \"random\"]\nreplicas = 3\n[observables]\nperiod_series = true\n"
    "estimators = true\nrow_profiles = true\n[schedule]\nsteady_tol = 1e-3\nmax_periods = 12\n";

std::string quoted(const std::filesystem::path& path) {
  std::string text(1, '\'');  // built piecewise: GCC 12 warns falsely (-Wrestrict) on "'" + s + "'"
  text += path.string();
  text += '\'';
  return text;
}

}  // namespace

TEST_CASE("three shards merged equal the unsharded run, byte for byte", "[apps][merge]") {
  const auto dir = scratch_directory("merge-shards");
  const auto scene = quoted(write_text(dir / "scene.toml", shard_scene));
  REQUIRE(run_cli("run " + scene + " -q -o " + quoted(dir / "whole.h5"), dir).exit_code == 0);
  std::string shards;
  for (int i = 1; i <= 3; ++i) {
    const auto shard = dir / ("part" + std::to_string(i) + ".h5");
    const auto result =
        run_cli("run " + scene + " -q --shard " + std::to_string(i) + "/3 -o " + quoted(shard), dir);
    REQUIRE(result.exit_code == 0);
    shards = quoted(shard) + " " + shards;  // merge takes them in any order
  }
  const auto shard = Hdf5Location::open_file((dir / "part2.h5").string());
  CHECK(shard.open_group("members").read_integers("plan_index").front() == 1);
  CHECK_FALSE(shard.has("curves"));

  const auto merged = run_cli("merge " + shards + "-o " + quoted(dir / "merged.h5"), dir);
  REQUIRE(merged.exit_code == 0);
  CHECK_THAT(merged.output, Catch::Contains("from 3 shards"));
  const auto whole = Hdf5Location::open_file((dir / "whole.h5").string());
  const auto joined = Hdf5Location::open_file((dir / "merged.h5").string());
  const auto paths = dataset_paths(whole);
  CHECK(paths == dataset_paths(joined));
  CHECK(paths.size() > 60);
  for (const auto& path : paths) {
    INFO(path);
    CHECK(whole.read_bytes(path) == joined.read_bytes(path));
  }
  CHECK(joined.attribute_flag("complete"));
  CHECK(joined.attribute_string("scene") == whole.attribute_string("scene"));
  // -q: nothing printed, the same file
  const auto quiet = run_cli("merge -q " + shards + "-o " + quoted(dir / "quiet.h5"), dir);
  REQUIRE(quiet.exit_code == 0);
  CHECK(quiet.output.empty());
  CHECK(Hdf5Location::open_file((dir / "quiet.h5").string()).attribute_flag("complete"));
}

TEST_CASE("shards that do not make one plan are refused", "[apps][merge]") {
  const auto dir = scratch_directory("merge-refused");
  const auto scene = quoted(write_text(dir / "scene.toml", shard_scene));
  const auto other =
      quoted(write_text(dir / "other.toml", std::string(shard_scene) + "[numerics]\nrtol = 1e-7\n"));
  for (int i = 1; i <= 2; ++i)
    REQUIRE(run_cli("run " + scene + " -q --shard " + std::to_string(i) + "/2 -o " +
                        quoted(dir / ("s" + std::to_string(i) + ".h5")),
                    dir)
                .exit_code == 0);
  REQUIRE(run_cli("run " + other + " -q --shard 2/2 -o " + quoted(dir / "foreign.h5"), dir).exit_code == 0);
  REQUIRE(run_cli("run " + scene + " -q -o " + quoted(dir / "whole.h5"), dir).exit_code == 0);
  // shard 2 edited: one row not done (complete still TRUE); and a shard index beyond the count
  std::filesystem::copy_file(dir / "s2.h5", dir / "edited.h5");
  std::filesystem::copy_file(dir / "s2.h5", dir / "seventh.h5");
  {
    const auto edited = rotorsweep::io::Hdf5Location::open_file_for_writing((dir / "edited.h5").string());
    const signed char not_done = 0;
    edited.open_group("members").write_rows("done", {1}, &not_done);
    rotorsweep::io::Hdf5Location::open_file_for_writing((dir / "seventh.h5").string())
        .set_attribute("shard_index", std::int64_t(7));
  }
  const auto out = " -o " + quoted(dir / "out.h5");
  const auto s1 = quoted(dir / "s1.h5"), s2 = quoted(dir / "s2.h5");
  const struct {
    std::string shards, message;
  } cases[] = {
      {s1, "shard 2 of 2 missing"},
      {s1 + " " + s1 + " " + s2, "both shard 1/2"},
      {s1 + " " + quoted(dir / "foreign.h5"), "differ in their scene"},
      {quoted(dir / "whole.h5"), "not a shard file"},
      {s1 + " " + quoted(dir / "absent.h5"), "does not exist"},
      {s1 + " " + quoted(dir / "edited.h5"), "row 1 is not marked done"},
      {s1 + " " + quoted(dir / "seventh.h5"), "shard index 7 is outside 1 … 2"},
  };
  for (const auto& c : cases) {
    INFO(c.shards);
    const auto result = run_cli("merge " + c.shards + out, dir);
    CHECK(result.exit_code == 2);
    CHECK_THAT(result.output, Catch::Contains(c.message));
    CHECK_FALSE(std::filesystem::exists(dir / "out.h5"));
  }
  for (const char* bad : {"0/2", "3/2", "1/0", "a/2", "1/2x", "1"}) {
    INFO(bad);
    const auto result = run_cli("run " + scene + " -q --shard " + bad + " -o " + quoted(dir / "bad.h5"), dir);
    CHECK(result.exit_code == 2);
    CHECK_THAT(result.output, Catch::Contains("--shard"));
    CHECK_FALSE(std::filesystem::exists(dir / "bad.h5"));
  }
}

TEST_CASE("a shard without -o does not overwrite the scene's output or another shard", "[apps][merge]") {
  const auto dir = scratch_directory("merge-default-path");
  const auto scene = quoted(write_text(dir / "curve.toml", std::string(shard_scene) + "[output]\npath = \"" +
                                                               (dir / "r" / "curve.h5").string() + "\"\n"));
  REQUIRE(run_cli("run " + scene + " -q --shard 1/2", dir).exit_code == 0);
  CHECK(std::filesystem::exists(dir / "r" / "curve.shard-1-of-2.h5"));
  CHECK_FALSE(std::filesystem::exists(dir / "r" / "curve.h5"));
}
