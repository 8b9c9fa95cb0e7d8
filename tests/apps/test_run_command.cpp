// `rotorsweep run` end to end: the paper's table and regime labels read back from the HDF5
// file, identical dataset bytes for 1 and 2 threads, and exit code 2 for every bad scene.
#include <catch2/catch.hpp>
#include <cmath>

#include "io/hdf5_file.hpp"
#include "support/cli.hpp"
#include "support/scene_text.hpp"

using rotorsweep::io::Hdf5Location;
using namespace rotorsweep::testing;

namespace {

/// Names of every dataset under /members, /members/periods and /curves.
std::vector<std::string> dataset_paths(const Hdf5Location& file) {
  std::vector<std::string> paths;
  for (const std::string group : {"members", "members/periods", "curves"}) {
    if (!file.has(group)) continue;
    const auto location = file.open_group(group);
    for (const auto& name : location.members())
      if (name != "periods") paths.push_back(group + "/" + name);
  }
  return paths;
}

}  // namespace

TEST_CASE("the paper's table read back from the result file", "[apps][run]") {
  const auto dir = scratch_directory("run-table");
  const std::string scene = paper_scene("[1, 4, 6, 8, 11]", "[\"FM\", \"AFM\"]", 1e-9);
  write_text(dir / "table.toml", scene);
  const auto run =
      run_cli("run '" + (dir / "table.toml").string() + "' -o '" + (dir / "table.h5").string() + "'", dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("wrote " + (dir / "table.h5").string()));

  const auto file = Hdf5Location::open_file((dir / "table.h5").string());
  CHECK(file.attribute_flag("complete"));
  CHECK(file.attribute_string("scene") == scene);
  const auto members = file.open_group("members");
  const auto D = members.read_doubles("dissipation");
  const auto regime = members.read_strings("regime");
  REQUIRE(D.size() == 10);  // A × kinds: (1, FM), (1, AFM), (4, FM), (4, AFM), ...
  // the paper's R column; FM and AFM regimes to 6 digits whatever the noise draw
  CHECK(D[0] == Approx(2.018948e-3).epsilon(2e-6));
  CHECK(D[1] == Approx(7.184589e-4).epsilon(2e-6));
  CHECK(D[3] == Approx(2.296052e-2).epsilon(2e-6));
  CHECK(D[8] == Approx(1.654868e-1).epsilon(2e-6));
  CHECK(D[9] == Approx(1.654868e-1).epsilon(2e-6));
  // CP: percent level, as the paper's own estimators spread there
  CHECK(D[4] == Approx(34.1).epsilon(0.02));
  CHECK(D[5] == Approx(34.1).epsilon(0.02));
  CHECK(D[6] == Approx(5.75).epsilon(0.025));
  CHECK(D[7] == Approx(5.75).epsilon(0.025));

  CHECK(regime[1] == "AFM");  // A = 1, AFM start
  CHECK(regime[4] == "CP");
  CHECK(regime[5] == "CP");
  CHECK(regime[6] == "CP");
  CHECK(regime[7] == "CP");
  CHECK(regime[8] == "FM");
  CHECK(regime[9] == "FM");
  CHECK(members.read_strings("status") == std::vector<std::string>(10, "ok"));
  // the drawn starts: member 1 is A = 1 with an AFM start of noise 0.01 around (0, π, 0, π, …)
  std::vector<hsize_t> dims;
  const auto start = members.read_doubles("theta_initial", &dims);
  REQUIRE(dims == std::vector<hsize_t>{10, 20});
  for (int j = 0; j < 20; ++j) CHECK(std::fabs(start[20 + j] - (j % 2) * M_PI) <= 0.01);

  const auto curves = file.open_group("curves");
  CHECK(curves.read_doubles("dissipation_mean") == D);  // one replica per point
  CHECK(curves.read_doubles("fraction_CP")[4] == 1.0);
}

TEST_CASE("one and two threads write identical datasets", "[apps][run]") {
  const auto dir = scratch_directory("run-threads");
  write_text(
      dir / "curve.toml",
      "[model]\nrows = 10\n[drive]\ng = [0.001, 0.01]\n[sweep]\nA = { from = 0.5, to = 12, count = 24 }\n"
      "[initial]\nkinds = [\"AFM\", \"random\"]\nreplicas = 2\n[observables]\nperiod_series = true\n");
  const std::string scene = "'" + (dir / "curve.toml").string() + "'";
  REQUIRE(run_cli("run " + scene + " --threads 1 -o '" + (dir / "one.h5").string() + "'", dir).exit_code ==
          0);
  REQUIRE(run_cli("run " + scene + " --threads 2 -o '" + (dir / "two.h5").string() + "'", dir).exit_code ==
          0);
  const auto one = Hdf5Location::open_file((dir / "one.h5").string());
  const auto two = Hdf5Location::open_file((dir / "two.h5").string());
  const auto paths = dataset_paths(one);
  CHECK(paths == dataset_paths(two));
  CHECK(paths.size() > 25);
  for (const auto& path : paths) {
    INFO(path);
    CHECK(one.read_bytes(path) == two.read_bytes(path));
  }
}

TEST_CASE("bad scenes exit with code 2 and name the key and leave no file", "[apps][run]") {
  const auto dir = scratch_directory("run-bad");
  const std::string good = "[model]\nrows = 20\n[drive]\ng = [0.001]\n[sweep]\nA = [1]\n";
  const struct {
    const char* what;
    std::string text;
    const char* key;
  } cases[] = {
      {"missing key", "[model]\nrows = 20\n[drive]\ng = [0.001]\n", "sweep.A"},
      {"bad type", good + "[numerics]\nrtol = \"tight\"\n", "numerics.rtol"},
      {"out of range", good + "[initial]\nnoise = -1\n", "initial.noise"},
      {"unknown key", good + "[schedule]\nrelax = 3\n", "schedule.relax"},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    write_text(dir / "bad.toml", c.text);
    const auto out = dir / "bad.h5";
    const auto run = run_cli("run '" + (dir / "bad.toml").string() + "' -o '" + out.string() + "'", dir);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains(std::string("'") + c.key + "'"));
    CHECK_FALSE(std::filesystem::exists(out));
  }
  const auto unreadable = run_cli("run '" + (dir / "absent.toml").string() + "'", dir);
  CHECK(unreadable.exit_code == 2);
  CHECK_THAT(unreadable.output, Catch::Contains("absent.toml"));
  write_text(dir / "good.toml", good);
  const auto unwritable = run_cli("run '" + (dir / "good.toml").string() + "' -o /proc/none/out.h5", dir);
  CHECK(unwritable.exit_code == 2);
  CHECK_THAT(unwritable.output, Catch::Contains("/proc/none/out.h5"));
  const auto bad_option = run_cli("run '" + (dir / "good.toml").string() + "' --threads 0", dir);
  CHECK(bad_option.exit_code == 2);
}
