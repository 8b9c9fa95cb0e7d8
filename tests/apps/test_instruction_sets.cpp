// The portable build's binaries: every instruction set this machine runs gives the same result
// file bytes (row model with each stepper, coupled open rows, disorder, temperature); the launcher
// reports and records which one ran, and refuses requests it cannot honour with exit code 2.
#include <catch2/catch.hpp>
#include <filesystem>

#include "apps/launcher/cpu_isas.hpp"
#include "apps/launcher/isa_choice.hpp"
#include "io/hdf5_file.hpp"
#include "support/cli.hpp"
#include "support/result_datasets.hpp"
#include "support/scene_text.hpp"
#include "test_paths.hpp"

using rotorsweep::io::Hdf5Location;
using namespace rotorsweep::testing;
namespace launcher = rotorsweep::launcher;

namespace {

const std::filesystem::path binaries = std::filesystem::path(ROTORSWEEP_EXECUTABLE).parent_path();

/// The sets this build holds that this machine can run.
std::vector<std::string> testable_isas() {
  std::vector<std::string> testable;
  const auto runnable = launcher::runnable_isas();
  for (const auto& isa : launcher::built_isas(binaries))
    if (std::find(runnable.begin(), runnable.end(), isa) != runnable.end()) testable.push_back(isa);
  return testable;
}

/// 12 members of 20 rows at damping g.
std::string small_row_scene(const std::string& g = "0.0011") {
  return "[model]\nrows = 20\n[drive]\ng = [" + g +
         "]\n[sweep]\nA = [1, 6, 11]\n[initial]\nkinds = [\"FM\", \"AFM\"]\nreplicas = 2\n[schedule]\n"
         "relax_periods = 1\naverage_periods = 1\n[observables]\nenergy = true\nperiod_series = true\n";
}

}  // namespace

TEST_CASE("the launcher's choice: auto takes the widest built and runnable set", "[apps][isa]") {
  const std::vector<std::string> all{"sse2", "avx2", "avx512"};
  CHECK(launcher::choose_isa("auto", "ROTORSWEEP_ISA", all, all).isa == "avx512");
  CHECK(launcher::choose_isa("auto", "ROTORSWEEP_ISA", {"sse2", "avx2"}, all).isa == "avx2");
  CHECK(launcher::choose_isa("auto", "ROTORSWEEP_ISA", all, {"sse2"}).isa == "sse2");
  CHECK(launcher::choose_isa("sse2", "--isa", all, all).isa == "sse2");
  const auto none = launcher::choose_isa("auto", "ROTORSWEEP_ISA", {"sse2"}, {"avx2", "avx512"});
  CHECK(none.isa.empty());
  CHECK_THAT(none.error, Catch::Contains("none of the built instruction sets (avx2, avx512)"));
  const auto unknown = launcher::choose_isa("avx1024", "ROTORSWEEP_ISA", all, all);
  CHECK(unknown.isa.empty());
  CHECK_THAT(unknown.error, Catch::Contains("ROTORSWEEP_ISA = 'avx1024'") &&
                                Catch::Contains("allowed: auto, sse2, avx2, avx512"));
  const auto unrunnable = launcher::choose_isa("avx512", "--isa", {"sse2", "avx2"}, all);
  CHECK_THAT(unrunnable.error,
             Catch::Contains("--isa = 'avx512': this CPU cannot execute it (it runs: sse2, avx2)"));
  const auto unbuilt = launcher::choose_isa("avx2", "--isa", all, {"sse2"});
  CHECK_THAT(unbuilt.error, Catch::Contains("no rotorsweep-avx2 (built: sse2)"));
}

TEST_CASE("every instruction set this machine runs writes the same result file bytes", "[apps][isa]") {
  const auto isas = testable_isas();
  if (isas.size() < 2) {
    WARN("this build holds fewer than two runnable instruction sets (" + launcher::joined(isas) + ")");
    return;
  }
  const auto dir = scratch_directory("isa-files");
  const struct {
    const char* name;
    std::string text;
    const char* command = "run";
  } scenes[] = {
      {"rodas4", small_row_scene()},
      {"rodas5p", small_row_scene() + "[numerics]\nstepper = \"rodas5p\"\nrtol = 1e-8\natol = 1e-11\n"},
      // ros2 (order 2) at the looser tolerance it is meant for: 10 times fewer steps than at rtol 1e-6
      {"ros2",
       small_row_scene() + "[numerics]\nstepper = \"ros2\"\ncontroller = \"pi\"\nrtol = 1e-4\natol = 1e-7\n"},
      {"dopri5", small_row_scene() + "[numerics]\nstepper = \"dopri5\"\n"},
      {"dipolar_open",
       "[model]\nrows = 12\ncouplings = \"dipolar\"\nrange = 4\nboundary = \"open\"\n[drive]\ng = [0.0011]\n"
       "[sweep]\nA = [3, 7]\n[initial]\nkinds = [\"AFM\"]\n[schedule]\nrelax_periods = 1\naverage_periods = "
       "1\n"},
      {"disorder", small_row_scene() + "[disorder]\nA = 0.01\nanisotropy = 0.01\nseed = 4\n"},
      // at g = 0.05 the Langevin steps (no longer than g/(2κ)) are 45 times fewer than at g = 0.0011
      {"thermal", small_row_scene("0.05") + "[thermal]\ntemperature = 0.01\nseed = 5\n"},
      {"slider",
       "[slider]\ncolumns = [3, 2]\nrows = 2\n[substrate]\ncolumns = 9\nrows = 9\n[drive]\nrest = 0.5\nend = "
       "2.5\n[sweep]\nseparation = [7e-3, 9e-3]\n[initial]\nreplicas = 5\n",
       "slider"},
  };
  for (const auto& scene : scenes) {
    INFO(scene.name);
    const auto scene_path = write_text(dir / (std::string(scene.name) + ".toml"), scene.text);
    std::vector<std::filesystem::path> files;
    for (const auto& isa : isas) {
      files.push_back(dir / (std::string(scene.name) + "-" + isa + ".h5"));
      const auto run = run_cli(
          std::string(scene.command) + " -q '" + scene_path.string() + "' -o '" + files.back().string() + "'",
          dir, "ROTORSWEEP_ISA=" + isa + " ");
      INFO(run.output);
      REQUIRE(run.exit_code == 0);
      CHECK(Hdf5Location::open_file(files.back().string()).attribute_string("isa") == isa);
    }
    const auto reference = Hdf5Location::open_file(files.front().string());
    const auto paths = dataset_paths(reference);
    CHECK(paths.size() > 15);
    for (std::size_t i = 1; i < files.size(); ++i) {
      INFO(isas.front() << " against " << isas[i]);
      const auto other = Hdf5Location::open_file(files[i].string());
      REQUIRE(dataset_paths(other) == paths);
      for (const auto& path : paths) {
        INFO(path);
        CHECK(reference.read_bytes(path) == other.read_bytes(path));
      }
    }
  }
}

TEST_CASE("the version text names the instruction set that runs; --isa or ROTORSWEEP_ISA forces one",
          "[apps][isa]") {
  const auto dir = scratch_directory("isa-version");
  const auto isas = testable_isas();
  if (isas.empty()) {
    WARN("this build is native: one binary, no launcher");
    return;
  }
  const auto automatic = run_cli("--version", dir);
  CHECK(automatic.exit_code == 0);
  CHECK_THAT(automatic.output, Catch::Contains("instruction set: " + isas.back() + " ("));
  CHECK_THAT(automatic.output, Catch::Contains("this CPU runs: "));
  for (const auto& isa : isas) {
    INFO(isa);
    const auto by_option = run_cli("--isa " + isa + " --version", dir);
    CHECK(by_option.exit_code == 0);
    CHECK_THAT(by_option.output, Catch::Contains("instruction set: " + isa + " ("));
    const auto by_variable = run_cli("--version", dir, "ROTORSWEEP_ISA=" + isa + " ");
    CHECK_THAT(by_variable.output, Catch::Contains("instruction set: " + isa + " ("));
  }
}

TEST_CASE("an instruction set that cannot run is a clear error with exit code 2 and no file", "[apps][isa]") {
  const auto dir = scratch_directory("isa-refused");
  const auto scene = write_text(dir / "scene.toml", small_row_scene());
  const auto out = dir / "out.h5";
  // the launcher's refusal, and a native build's (which has no launcher but still reads the name)
  const auto unknown =
      run_cli("run '" + scene.string() + "' -o '" + out.string() + "'", dir, "ROTORSWEEP_ISA=avx1024 ");
  CHECK(unknown.exit_code == 2);
  CHECK_THAT(unknown.output, Catch::Contains("ROTORSWEEP_ISA = 'avx1024' is not an instruction set; allowed: "
                                             "auto, sse2, avx2, avx512"));
  CHECK_FALSE(std::filesystem::exists(out));
  if (testable_isas().empty()) {
    const auto named = run_cli("--version", dir, "ROTORSWEEP_ISA=avx2 ");
    CHECK(named.exit_code == 0);
    CHECK_THAT(named.output, Catch::Contains("has no effect"));
    WARN("this build is native: one binary, no launcher");
    return;
  }
  const auto missing_value = run_cli("--isa", dir);
  CHECK(missing_value.exit_code == 2);
  CHECK_THAT(missing_value.output, Catch::Contains("--isa needs a value"));

  // a launcher with only the baseline binary beside it: a wider set is "not built"
  const auto lonely = dir / "lonely";
  std::filesystem::create_directories(lonely);
  std::filesystem::copy_file(ROTORSWEEP_EXECUTABLE, lonely / "rotorsweep");
  std::filesystem::copy_file(binaries / "rotorsweep-sse2", lonely / "rotorsweep-sse2");
  const auto launcher_alone = (lonely / "rotorsweep").string();
  const auto wider = detail::run_logged(
      "ROTORSWEEP_ISA=avx2 '" + launcher_alone + "' --version > '" + (dir / "log").string() + "' 2>&1",
      dir / "log");
  CHECK(wider.exit_code == 2);
  CHECK_THAT(wider.output, Catch::Contains("ROTORSWEEP_ISA = 'avx2': ") &&
                               (Catch::Contains("no rotorsweep-avx2 (built: sse2)") ||
                                Catch::Contains("this CPU cannot execute it")));
  const auto fallback = detail::run_logged(
      "'" + launcher_alone + "' --version > '" + (dir / "log").string() + "' 2>&1", dir / "log");
  CHECK(fallback.exit_code == 0);
  CHECK_THAT(fallback.output, Catch::Contains("instruction set: sse2") && Catch::Contains("built: sse2 ("));

  // a binary run directly refuses to pretend to be another set
  const auto direct =
      detail::run_logged("'" + (lonely / "rotorsweep-sse2").string() + "' --isa avx2 info missing.h5 > '" +
                             (dir / "log").string() + "' 2>&1",
                         dir / "log");
  CHECK(direct.exit_code == 2);
  CHECK_THAT(direct.output, Catch::Contains("this is rotorsweep-sse2"));
}
