// Shards (`run --shard I/N`) and `merge`: three shards merged give the unsharded file's datasets
// byte for byte (period series, estimators, row profiles, random starts included); missing, doubled or
// foreign shards, shards whose datasets or attributes do not fit their scene (partial files too, on
// --resume), unreadable shards and bad --shard values exit with code 2 and write nothing.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdlib>
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
  std::filesystem::copy_file(dir / "s2.h5", dir / "stopped.h5");
  {
    rotorsweep::io::Hdf5Location::open_file_for_writing((dir / "stopped.h5").string())
        .set_flag("complete", false);
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
      {s1 + " " + quoted(dir / "seventh.h5"), "shard_index 7 and shard_count 2 do not name a shard"},
      {s1 + " " + quoted(dir / "stopped.h5"), "is incomplete: its run stopped early; finish it with rotorsweep "
                                              "run '" + (dir / "scene.toml").string() + "' --shard 2/2 -o OUT.h5 --resume"},
  };
  for (const auto& c : cases) {
    INFO(c.shards);
    const auto result = run_cli("merge " + c.shards + out, dir);
    CHECK(result.exit_code == 2);
    CHECK_THAT(result.output, Catch::Contains(c.message));
    CHECK_FALSE(std::filesystem::exists(dir / "out.h5"));
  }
  // the header names a shard's first members, or says it has none
  const auto one = run_cli("run " + scene + " --shard 288/289 -o " + quoted(dir / "one.h5"), dir);
  CHECK_THAT(one.output, Catch::Contains("shard 288/289: member 287 of the plan's 288\n"));
  const auto none = run_cli("run " + scene + " --shard 289/289 -o " + quoted(dir / "none.h5"), dir);
  CHECK_THAT(none.output, Catch::Contains("shard 289/289: no members (the plan has 288)\n"));
  const auto many = run_cli("run " + scene + " --shard 2/100 -o " + quoted(dir / "many.h5"), dir);
  CHECK_THAT(many.output, Catch::Contains("shard 2/100: members 1, 101, 201 of the plan's 288\n"));
  const auto more = run_cli("run " + scene + " --shard 2/80 -o " + quoted(dir / "more.h5"), dir);
  CHECK_THAT(more.output, Catch::Contains("shard 2/80: members 1, 81, 161, ... of the plan's 288\n"));
  for (const char* bad : {"0/2", "3/2", "1/0", "a/2", "1/2x", "1", "1/99999999999999999999", "1/-1", "-1/2",
                          "+1/2", " 1/2", "1/1e3", "1/2000000000"}) {
    INFO(bad);
    const auto result =
        run_cli("run " + scene + " -q --shard '" + bad + "' -o " + quoted(dir / "bad.h5"), dir);
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

TEST_CASE(
    "shards and partial files whose datasets or attributes do not fit their scene are refused, naming them",
    "[apps][merge][resume]") {
  namespace fs = std::filesystem;
  const auto dir = scratch_directory("merge-shapes");
  const auto rows = quoted(
      write_text(dir / "rows.toml", "[model]\nrows = 4\n[drive]\ng = 0.01\n[sweep]\nA = [1, 2, 3, 4]\n"));
  const auto slider = quoted(write_text(
      dir / "slider.toml",
      "[slider]\ncolumns = 2\nrows = 1\n[substrate]\ncolumns = 5\nrows = 5\n[drive]\nrest = 0.1\nend = 2.1\n"
      "[sweep]\nseparation = [8e-3, 9e-3]\n[observables]\nsamples_per_period = 10\n"));
  for (const char* i : {"1", "2"}) {
    REQUIRE(run_cli("run " + rows + " -q --shard " + std::string(i) + "/2 -o " +
                        quoted(dir / ("r" + std::string(i) + ".h5")),
                    dir)
                .exit_code == 0);
    REQUIRE(run_cli("slider " + slider + " -q --shard " + std::string(i) + "/2 -o " +
                        quoted(dir / ("s" + std::string(i) + ".h5")),
                    dir)
                .exit_code == 0);
  }
  // an edited copy of shard 2 of each kind: a dataset of another shape or type, or an attribute changed
  const auto edited = [&](const std::string& from, const std::string& name, const auto& edit) {
    fs::copy_file(dir / from, dir / name);
    edit(dir / name);
    return quoted(dir / name);
  };
  const auto attribute = [](const char* key, auto value) {
    return [=](const fs::path& path) {
      Hdf5Location::open_file_for_writing(path.string()).set_attribute(key, value);
    };
  };
  const auto reshaped = [](const char* dataset, std::vector<hsize_t> dims) {
    return [=](const fs::path& path) { replace_dataset(path, dataset, dims); };
  };
  const struct {
    std::string first, other, message;
  } cases[] = {
      {"r1.h5", edited("r2.h5", "theta.h5", reshaped("members/theta_final", {2, 2})),
       "dataset /members/theta_final has shape (2, 2) where its scene gives (2, 4)"},
      {"r1.h5", edited("r2.h5", "status.h5", reshaped("members/status", {2})),
       "dataset /members/status does not hold fixed-length text"},
      {"r1.h5", edited("r2.h5", "kind.h5", attribute("kind", std::string("rows"))), "says kind = 'rows'"},
      {"r1.h5", edited("r2.h5", "plan.h5", attribute("plan_members", std::int64_t(95))), "plan_members"},
      {"s1.h5", edited("s2.h5", "series.h5", reshaped("series/friction", {1, 5})),
       "dataset /series/friction has shape (1, 5) where its scene gives (1, "},
      {"s1.h5", edited("s2.h5", "period.h5", reshaped("members/period_friction", {1})),
       "dataset /members/period_friction has shape (1,) where its scene gives (1, 1)"},
      {"s1.h5", edited("s2.h5", "slider_kind.h5", attribute("kind", std::string("rows"))),
       "says kind = 'rows'"},
  };
  for (const auto& c : cases) {
    INFO(c.other);
    const auto result =
        run_cli("merge " + quoted(dir / c.first) + " " + c.other + " -o " + quoted(dir / "out.h5"), dir);
    CHECK(result.exit_code == 2);
    CHECK_THAT(result.output, Catch::Contains(c.message));
    CHECK_FALSE(fs::exists(dir / "out.h5"));
  }
  // the same edits to a partial file: --resume refuses it and leaves it as it is
  REQUIRE(run_cli("run " + rows + " -q -o " + quoted(dir / "whole.h5"), dir).exit_code == 0);
  REQUIRE(run_cli("slider " + slider + " -q -o " + quoted(dir / "scan.h5"), dir).exit_code == 0);
  const struct {
    std::string command, whole, dataset;
    std::vector<hsize_t> dims;
    std::string message;
  } partials[] = {
      {"run " + rows, "whole.h5", "members/theta_final", {4, 2}, "/members/theta_final has shape (4, 2)"},
      {"slider " + slider, "scan.h5", "series/friction", {2, 5}, "/series/friction has shape (2, 5)"},
      {"run " + rows, "whole.h5", "", {}, "plan_members"},
      {"slider " + slider, "scan.h5", "", {}, "says kind = 'rows'"},
  };
  for (const auto& p : partials) {
    INFO(p.command << " " << p.message);
    const auto partial = dir / "out.h5.partial";
    fs::copy_file(dir / p.whole, partial, fs::copy_options::overwrite_existing);
    {
      const auto file = Hdf5Location::open_file_for_writing(partial.string());
      file.set_flag("complete", false);
      if (p.whole == "whole.h5" && p.dataset.empty()) file.set_attribute("plan_members", std::int64_t(95));
      if (p.whole == "scan.h5" && p.dataset.empty()) file.set_attribute("kind", std::string("rows"));
    }
    if (!p.dataset.empty()) replace_dataset(partial, p.dataset, p.dims);
    const auto before = Hdf5Location::open_file(partial.string()).read_bytes("members/done");
    const auto result = run_cli(p.command + " -q -o " + quoted(dir / "out.h5") + " --resume", dir);
    CHECK(result.exit_code == 2);
    CHECK_THAT(result.output, Catch::Contains(p.message) && Catch::Contains("--resume"));
    CHECK_FALSE(fs::exists(dir / "out.h5"));
    CHECK(Hdf5Location::open_file(partial.string()).read_bytes("members/done") == before);
  }
}

TEST_CASE("a shard that cannot be read is named with the system's reason", "[apps][merge]") {
  namespace fs = std::filesystem;
  const auto dir = scratch_directory("merge-unreadable");
  const auto scene =
      quoted(write_text(dir / "tiny.toml", "[model]\nrows = 4\n[drive]\ng = 0.01\n[sweep]\nA = [1, 2]\n"));
  for (const char* i : {"1", "2"})
    REQUIRE(run_cli("run " + scene + " -q --shard " + std::string(i) + "/2 -o " +
                        quoted(dir / ("s" + std::string(i) + ".h5")),
                    dir)
                .exit_code == 0);
  // root reads any file: the merge then runs as nobody, for whom shard 2 is unreadable
  std::string as_user;
  if (::geteuid() == 0) {
    as_user = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
    if (std::system((as_user + "true 2>/dev/null").c_str()) != 0) {
      WARN("skipped: running as root, and setpriv cannot drop to nobody here");
      return;
    }
  }
  fs::permissions(dir, fs::perms::all);
  fs::permissions(dir / "s1.h5", fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  fs::permissions(dir / "s2.h5", fs::perms::none);
  const auto result = run_cli(
      "merge " + quoted(dir / "s1.h5") + " " + quoted(dir / "s2.h5") + " -o " + quoted(dir / "out.h5"), dir,
      as_user);
  fs::permissions(dir / "s2.h5", fs::perms::owner_read | fs::perms::owner_write);
  INFO(result.output);
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.output, Catch::Contains("s2.h5': Permission denied"));
  CHECK_FALSE(fs::exists(dir / "out.h5"));
}
