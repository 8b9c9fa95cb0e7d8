// `rotorsweep run` end to end: the paper's table and regime labels read back from the HDF5
// file, identical dataset bytes for 1 and 2 threads, the ragged plan (random starts once), exit
// code 2 for every bad scene and plan,
// and output files that never destroy the scene or a previous result (also on a full disk).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "ensemble/gpu/gpu_backend.hpp"
#include "io/hdf5_file.hpp"
#include "support/cli.hpp"
#include "support/result_datasets.hpp"
#include "support/scene_text.hpp"

using rotorsweep::io::Hdf5Location;
using namespace rotorsweep::testing;

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

TEST_CASE("noise and offset do not multiply random starts: they run once per replica", "[apps][run]") {
  const auto dir = scratch_directory("run-ragged");
  const std::string common =
      "[model]\nrows = 6\n[drive]\ng = 0.01\n[sweep]\nA = [2, 11]\n"
      "[schedule]\nrelax_periods = 1\naverage_periods = 1\n[initial]\nreplicas = 2\n";
  const auto ragged =
      write_text(dir / "ragged.toml", common + "kinds = [\"random\", \"AFM\"]\nnoise = [0.01, 0.3]\n");
  const auto random = write_text(dir / "random.toml", common + "kinds = [\"random\"]\n");
  const auto run = run_cli("run '" + ragged.string() + "' -o '" + (dir / "ragged.h5").string() + "'", dir);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("12 members (1 N × 1 rtol × 2 A × 1 g × AFM: 2 noise × 1 offset × 2 "
                                         "replicas; random: 2 replicas)"));
  REQUIRE(
      run_cli("run '" + random.string() + "' -q -o '" + (dir / "random.h5").string() + "'", dir).exit_code ==
      0);
  const auto file = Hdf5Location::open_file((dir / "ragged.h5").string()).open_group("members");
  const auto alone = Hdf5Location::open_file((dir / "random.h5").string()).open_group("members");
  CHECK(file.read_doubles("dissipation").size() == 12);
  // per A: random × 2, AFM η = 0.01 × 2, AFM η = 0.3 × 2; the random members are those of a random-only run
  const auto D = file.read_doubles("dissipation"), D_random = alone.read_doubles("dissipation");
  CHECK(std::vector<double>{D[0], D[1], D[6], D[7]} == D_random);
  const auto curves = Hdf5Location::open_file((dir / "ragged.h5").string()).open_group("curves");
  CHECK(curves.read_doubles("noise") == std::vector<double>{0.01, 0.01, 0.3, 0.01, 0.01, 0.3});
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

TEST_CASE("a run never destroys the scene or a file it was not asked to replace", "[apps][run][files]") {
  const auto dir = scratch_directory("run-files");
  const std::string scene = "[model]\nrows = 4\n[drive]\ng = [0.01]\n[sweep]\nA = [1, 9]\n";
  const auto path = write_text(dir / "s.toml", scene);
  const auto quoted = [](const std::filesystem::path& p) {
    return std::string(1, '\'').append(p.string()).append("'");
  };
  const auto scene_intact = [&](const std::filesystem::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {}) == scene;
  };

  auto run = run_cli("run " + quoted(path) + " -q -o " + quoted(path), dir);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::Contains("is the input file"));
  CHECK(scene_intact(path));

  std::filesystem::create_symlink(path, dir / "link.h5");
  run = run_cli("run " + quoted(path) + " -q -o " + quoted(dir / "link.h5"), dir);
  CHECK(run.exit_code == 2);
  CHECK(scene_intact(path));

  // a scene named x.h5 writes x.h5 in the working directory by default: itself
  const auto h5_scene = write_text(dir / "x.h5", scene);
  run = run_cli("run x.h5 -q", dir, "cd " + quoted(dir) + " && ");
  CHECK(run.exit_code == 2);
  CHECK(scene_intact(h5_scene));

  write_text(dir / "notes.txt", "keep me\n");
  run = run_cli("run " + quoted(path) + " -q -o " + quoted(dir / "notes.txt"), dir);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::Contains("--force"));
  CHECK(run_cli("run " + quoted(path) + " -q --force -o " + quoted(dir / "notes.txt"), dir).exit_code == 0);
  CHECK(Hdf5Location::open_file((dir / "notes.txt").string()).attribute_flag("complete"));

  run = run_cli("run " + quoted(path) + " -q -o ''", dir);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::Contains("empty"));
  run = run_cli("run " + quoted(path) + " -q -o " + quoted(dir / "newdir") + "/", dir);
  CHECK(run.exit_code == 2);
  CHECK_FALSE(std::filesystem::exists(dir / "newdir"));

  // replacing a result says so
  const auto out = dir / "out.h5";
  CHECK(run_cli("run " + quoted(path) + " -q -o " + quoted(out), dir).exit_code == 0);
  run = run_cli("run " + quoted(path) + " -q -o " + quoted(out), dir);
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.output, Catch::Contains("replacing the previous file"));
}

TEST_CASE("a full disk is a clear error that keeps the previous result", "[apps][run][files]") {
  const auto dir = scratch_directory("run-full-disk");
  const auto scene = write_text(dir / "big.toml",
                                "[model]\nrows = 64\n[drive]\ng = [0.01]\n[sweep]\nA = { from = 1, to = 12, "
                                "count = 200 }\n[observables]\nperiod_series = true\n");
  const auto small =
      write_text(dir / "small.toml", "[model]\nrows = 4\n[drive]\ng = [0.01]\n[sweep]\nA = [1]\n");
  const auto out = dir / "out.h5";
  const std::string limit = "ulimit -f 64; ";  // 64 KiB: the big scene's file needs about 1 MB
  auto run = run_cli("run '" + scene.string() + "' -q -o '" + out.string() + "'", dir, limit);
  CHECK(run.exit_code == 1);
  CHECK_THAT(run.output, Catch::Contains("File too large"));
  CHECK_THAT(run.output, Catch::Contains("no file was written"));
  CHECK_FALSE(std::filesystem::exists(out));
  CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) == 3);

  REQUIRE(run_cli("run '" + small.string() + "' -q -o '" + out.string() + "'", dir).exit_code == 0);
  run = run_cli("run '" + scene.string() + "' -q -o '" + out.string() + "'", dir, limit);
  CHECK(run.exit_code == 1);
  CHECK_THAT(run.output, Catch::Contains("the previous file is unchanged"));
  const auto kept = Hdf5Location::open_file(out.string());
  CHECK(kept.attribute_flag("complete"));
  CHECK(kept.open_group("members").read_doubles("A").size() == 1);

  // in new directories: they go again
  run = run_cli("run '" + scene.string() + "' -q -o '" + (dir / "new" / "deeper" / "out.h5").string() + "'",
                dir, limit);
  CHECK(run.exit_code == 1);
  CHECK_FALSE(std::filesystem::exists(dir / "new"));
}

TEST_CASE("plans too large to count or to hold are refused before any work", "[apps][run]") {
  const auto dir = scratch_directory("run-huge");
  // 10^7 × 10^7 × 2^18 members: the product overflows 64 bits if counted naively
  const auto overflow =
      write_text(dir / "overflow.toml",
                 "[model]\nrows = 4\n[drive]\ng = { from = 0.001, to = 1, count = 10000000 }\n"
                 "[sweep]\nA = { from = 1, to = 2, count = 9000000 }\n"
                 "[initial]\nkinds = [\"random\"]\nreplicas = 262144\n");
  auto run = run_cli("run '" + overflow.string() + "' -q -o '" + (dir / "o.h5").string() + "'", dir);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::Contains("'drive.g'"));
  CHECK_THAT(run.output, Catch::Contains("2.36e+19 members"));
  // within the member limit, but terabytes of results
  const auto memory =
      write_text(dir / "memory.toml",
                 "[model]\nrows = 4096\n[drive]\ng = { from = 0.001, to = 1, count = 10000 }\n"
                 "[sweep]\nA = { from = 1, to = 2, count = 10000 }\n");
  run = run_cli("run '" + memory.string() + "' -q -o '" + (dir / "m.h5").string() + "'", dir);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::Contains("GiB"));
  CHECK_FALSE(std::filesystem::exists(dir / "o.h5"));
  CHECK_FALSE(std::filesystem::exists(dir / "m.h5"));
}

TEST_CASE("a sweep whose lane blocks would not fit in memory is refused before any work", "[apps][run]") {
  const auto dir = scratch_directory("run-working-set");
  // a dense coupling table at N = 20000: tens of GiB per thread for the factors alone
  const auto dense = write_text(dir / "dense.toml",
                                "[model]\nrows = 20000\ncouplings = \"dipolar\"\nrange = \"all\"\n"
                                "[drive]\ng = 0.01\n[sweep]\nA = 1\n");
  auto run = run_cli("run '" + dense.string() + "' -q -o '" + (dir / "d.h5").string() + "'", dir);
  INFO(run.output);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::Contains("GiB to work in") && Catch::Contains("N = 20000"));
  // within the machine's memory, but not within the process's address-space limit
  const auto big = write_text(dir / "big.toml",
                              "[model]\nrows = 4000\ncouplings = \"dipolar\"\nrange = \"all\"\n"
                              "[drive]\ng = 0.01\n[sweep]\nA = 1\n");
  run = run_cli("run '" + big.string() + "' -q --threads 2 -o '" + (dir / "b.h5").string() + "'", dir,
                "ulimit -v 2000000; ");
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output, Catch::Contains("ulimit -v"));
  for (const char* left : {"d.h5", "d.h5.partial", "b.h5", "b.h5.partial"})
    CHECK_FALSE(std::filesystem::exists(dir / left));
}

TEST_CASE("thread counts from OMP_NUM_THREADS and flush intervals obey one rule", "[apps][run]") {
  const auto dir = scratch_directory("run-threads");
  const auto scene = write_text(dir / "small.toml", "[model]\nrows = 4\n[drive]\ng = 0.01\n[sweep]\nA = 1\n");
  const std::string run = "run '" + scene.string() + "' -q -o '" + (dir / "o.h5").string() + "'";
  for (const std::string bad : {"100000", "0", "-3", "many"}) {
    const auto refused = run_cli(run, dir, "OMP_NUM_THREADS=" + bad + " ");
    INFO(bad << ": " << refused.output);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.output,
               Catch::Contains("OMP_NUM_THREADS = '" + bad + "'") && Catch::Contains("1 to 4096"));
  }
  const auto slider = write_text(dir / "slider.toml", "[sweep]\nseparation = 9e-3\n");
  CHECK(run_cli("slider '" + slider.string() + "' -q -o '" + (dir / "s.h5").string() + "'", dir,
                "OMP_NUM_THREADS=100000 ")
            .exit_code == 2);
  const auto nan = run_cli(run + " --flush-seconds nan", dir);
  CHECK(nan.exit_code != 0);
  CHECK_THAT(nan.output, Catch::Contains("--flush-seconds") && Catch::Contains("finite"));
  for (const char* left : {"o.h5", "o.h5.partial", "s.h5"}) CHECK_FALSE(std::filesystem::exists(dir / left));
  CHECK(run_cli(run, dir, "OMP_NUM_THREADS=2,1 ").exit_code == 0);  // a nested list: its first value
}

TEST_CASE("the GPU device: refusals exit 2 naming the key, and no GPU is a clear error", "[apps][run][gpu]") {
  const auto dir = scratch_directory("run-gpu");
  const std::string good = "[model]\nrows = 20\n[drive]\ng = [0.001]\n[sweep]\nA = [1]\n";
  write_text(dir / "large.toml", "[model]\nrows = 100000\n[drive]\ng = [0.001]\n[sweep]\nA = [1]\n");
  const auto out = dir / "out.h5";
  const auto large =
      run_cli("run '" + (dir / "large.toml").string() + "' --device gpu -o '" + out.string() + "'", dir);
  CHECK(large.exit_code == 2);
  CHECK_THAT(large.output, Catch::Contains("'model.rows'"));
  CHECK_FALSE(std::filesystem::exists(out));
  const auto bad_device = run_cli("run '" + (dir / "large.toml").string() + "' --device tpu", dir);
  CHECK(bad_device.exit_code == 2);
  CHECK_THAT(bad_device.output, Catch::Contains("--device"));
  // a bad launch setting in the environment is an exit code 2 naming the variable, with or without a GPU
  write_text(dir / "good.toml", good);
  const auto slider = write_text(dir / "slider.toml", "[sweep]\nseparation = 8e-3\n");
  for (const std::string variable : {"ROTORSWEEP_GPU_TEAM", "ROTORSWEEP_GPU_SCRATCH", "ROTORSWEEP_GPU_BLOCK"})
    for (const auto& command :
         {"run '" + (dir / "good.toml").string() + "'", "slider '" + slider.string() + "'"}) {
      const auto refused =
          run_cli(command + " -q --device gpu -o '" + out.string() + "'", dir, variable + "=garbage ");
      INFO(variable << " " << command << ": " << refused.output);
      CHECK(refused.exit_code == 2);
      CHECK_THAT(refused.output, Catch::Contains(variable));
      CHECK_FALSE(std::filesystem::exists(out));
    }
  if (rotorsweep::ensemble::gpu_info().available) return;  // the rest is about a machine without one
  const auto run =
      run_cli("run '" + (dir / "good.toml").string() + "' --device gpu -o '" + out.string() + "'", dir);
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.output,
             Catch::Contains(rotorsweep::ensemble::gpu_info().why) && Catch::Contains("--device cpu"));
  CHECK_FALSE(std::filesystem::exists(out));
  const auto bench = run_cli("bench gpu", dir);
  CHECK(bench.exit_code == 2);
  CHECK_THAT(bench.output, Catch::Contains(rotorsweep::ensemble::gpu_info().why));
}

TEST_CASE("bench gpu on the CPU reports the curve's members and attempts", "[apps][bench]") {
  const auto dir = scratch_directory("bench-gpu");
  const auto bench = run_cli("bench gpu --device cpu --scale 1e-6 --curve-only", dir);
  REQUIRE(bench.exit_code == 0);
  CHECK_THAT(bench.output, Catch::Contains("rotor-attempts/s") &&
                               Catch::Contains("| 20 | rodas4 | lanes | 1000 |") &&
                               Catch::EndsWith(" | 1000 |\n"));
  const auto two = run_cli("bench gpu --device cpu --scale 1e-6 --no-curve --rows 2", dir);
  REQUIRE(two.exit_code == 0);
  CHECK_THAT(two.output, Catch::Contains("| 2 | rodas4 | lanes | 1000 |") &&
                             Catch::Contains("| 2 | rodas4p2 | lanes | 1000 |") &&
                             !Catch::Contains("| 20 |"));
  for (const char* bad : {"--rows 3", "--teams 3", "--teams 64", "--scratch local"}) {
    INFO(bad);
    const auto refused = run_cli(std::string("bench gpu --device cpu --scale 1e-6 --curve-only ") + bad, dir);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.output, Catch::Contains(std::string(bad).substr(0, std::string(bad).find(' '))));
  }
}

TEST_CASE("CP members whose slips could not be told jumps or smooth are counted in a warning",
          "[apps][run]") {
  const auto dir = scratch_directory("run-slip-kinds");
  // at g = 1e-12 the slower rerun (g/10) does not finish: slip_jumps and slip_smooth stay NaN
  const auto scene = write_text(dir / "tiny_g.toml",
                                "[model]\nrows = 2\n[drive]\ng = 1e-12\n[sweep]\nA = 8\n"
                                "[observables]\nslip_kinds = true\n");
  const auto out = dir / "out.h5";
  const auto run = run_cli("run '" + scene.string() + "' -q -o '" + out.string() + "'", dir);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const auto members = rotorsweep::io::Hdf5Location::open_file(out.string()).open_group("members");
  REQUIRE(members.read_strings("status") == std::vector<std::string>{"ok"});
  REQUIRE(members.read_strings("regime") == std::vector<std::string>{"CP"});
  REQUIRE(std::isnan(members.read_doubles("slip_jumps")[0]));
  CHECK_THAT(run.output,
             Catch::Contains("warning: 1 CP members whose slips could not be told jumps or smooth"));
}
