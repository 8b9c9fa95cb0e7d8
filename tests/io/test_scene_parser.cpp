// Scene validation (io/scene_parser): defaults, grids, and one clear message naming the key
// for every kind of bad scene: missing key, wrong type, out of range, unknown key, unreadable.
#include <sys/stat.h>

#include <catch2/catch.hpp>
#include <cmath>

#include "ensemble/gpu/gpu_executor.hpp"
#include "io/scene_parser.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "support/scene_text.hpp"

using rotorsweep::io::parse_scene_file;
using rotorsweep::io::parse_scene_text;
using rotorsweep::io::SceneError;

namespace {

const std::string minimal = "[model]\nrows = 20\n[drive]\ng = [0.001]\n[sweep]\nA = [1.0, 2]\n";

/// The message of the SceneError the text raises ("" if it parses).
std::string error_of(const std::string& text) {
  try {
    parse_scene_text(text, "test.toml");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("a minimal scene gets the documented defaults", "[io][scene]") {
  const auto scene = parse_scene_text(minimal, "test.toml");
  CHECK(scene.row_counts.front() == 20);
  CHECK(scene.A_values == std::vector<double>{1.0, 2.0});
  CHECK(scene.g_values == std::vector<double>{0.001});
  CHECK(scene.kinds == std::vector{rotorsweep::ensemble::InitialKind::afm});
  CHECK(scene.noise_values == std::vector<double>{0.01});
  CHECK(scene.offset_values == std::vector<double>{0.0});
  CHECK(scene.replicas == 1);
  CHECK(scene.relax_periods == 2);
  CHECK(scene.average_periods == 2);
  CHECK(scene.steady_tol == 0);
  CHECK(scene.rtol_values.front() == 1e-6);
  CHECK(scene.atol_values.front() == 1e-9);
  CHECK(rotorsweep::kernels::stepper_names[scene.stepper] == "rodas4p2");
  CHECK(scene.has(rotorsweep::ensemble::Observable::dissipation));
  CHECK(scene.has(rotorsweep::ensemble::Observable::alignment));
  CHECK(scene.has(rotorsweep::ensemble::Observable::slips));
  CHECK_FALSE(scene.has(rotorsweep::ensemble::Observable::energy));
  CHECK_FALSE(scene.period_series);
  CHECK(scene.text == minimal);
  CHECK(scene.member_count() == 2);
}

TEST_CASE("a single number where a list is allowed is a list of one", "[io][scene]") {
  const auto scene = parse_scene_text("[model]\nrows = 4\n[drive]\ng = 0.001\n[sweep]\nA = 6\n", "test.toml");
  CHECK(scene.g_values == std::vector<double>{0.001});
  CHECK(scene.A_values == std::vector<double>{6.0});
  const auto lists =
      parse_scene_text("[model]\nrows = 4\n[drive]\ng = [0.001]\n[sweep]\nA = [6]\n", "test.toml");
  CHECK(lists.g_values == scene.g_values);
  CHECK(lists.A_values == scene.A_values);
}

TEST_CASE("grids are lists or ranges with linear or log spacing", "[io][scene]") {
  const auto scene = parse_scene_text(
      "[model]\nrows = 4\n[drive]\ng = { from = 1e-4, to = 1e-1, count = 4, spacing = \"log\" }\n"
      "[sweep]\nA = { from = 0.25, to = 14.0, count = 281 }\n",
      "test.toml");
  REQUIRE(scene.g_values.size() == 4);
  CHECK(scene.g_values[1] == Approx(1e-3).epsilon(1e-12));
  CHECK(scene.g_values[3] == 1e-1);
  REQUIRE(scene.A_values.size() == 281);
  CHECK(scene.A_values.front() == 0.25);
  CHECK(scene.A_values[4] == Approx(0.25 + 4 * 13.75 / 280));
  CHECK(scene.A_values.back() == 14.0);
}

TEST_CASE("a range's points are the nearest doubles to its exact points, its ends exactly from and to",
          "[io][scene]") {
  const auto scene = parse_scene_text(
      "[model]\nrows = 4\n[drive]\ng = { from = 1e-6, to = 10.0, count = 8, spacing = \"log\" }\n"
      "[sweep]\nA = { from = 0.25, to = 11.0, count = 44 }\n",
      "test.toml");
  // 0.25 + k/4: the grid meets 3.75, 6, 7.25 and 8 (each came out one bit off as from + k/43 · 10.75)
  REQUIRE(scene.A_values.size() == 44);
  CHECK(scene.A_values[14] == 3.75);
  CHECK(scene.A_values[23] == 6.0);
  CHECK(scene.A_values[28] == 7.25);
  CHECK(scene.A_values[31] == 8.0);
  for (std::size_t i = 0; i < 44; ++i) CHECK(scene.A_values[i] == Approx(0.25 + double(i) / 4));
  CHECK(scene.g_values.front() == 1e-6);  // exp(log(1e-6)) is 1.0000000000000004e-6
  CHECK(scene.g_values.back() == 10.0);
  const auto offsets =
      parse_scene_text(minimal + "[initial]\noffset = { from = -3.0, to = 3.0, count = 7 }\n", "test.toml");
  CHECK(offsets.offset_values == std::vector<double>{-3, -2, -1, 0, 1, 2, 3});
}

TEST_CASE("every option is read from its key", "[io][scene]") {
  const auto scene =
      parse_scene_text(minimal +
                           "[initial]\nkinds = [\"FM\", \"exact\"]\nangles = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, "
                           "10, 11, 12, 13, 14, 15, 16, 17, 18, 19]\nreplicas = 3\nseed = 9\nnoise = 0.1\n"
                           "[schedule]\nsteady_tol = 1e-5\nmax_periods = 9\nrefill = false\n"
                           "[observables]\nenergy = true\nestimators = true\nslip_rate = 4\n"
                           "[numerics]\nstepper = \"ros2\"\nlanes = \"scalar\"\nh_max = 0.25\n"
                           "[output]\npath = \"x.h5\"\n",
                       "test.toml");
  CHECK(scene.kinds.size() == 2);
  CHECK(scene.exact_angles.size() == 20);
  CHECK(scene.replicas == 3);
  CHECK(scene.seed == 9);
  CHECK(scene.noise_values == std::vector<double>{0.1});
  CHECK(scene.steady_tol == 1e-5);
  CHECK(scene.max_periods == 9);
  CHECK_FALSE(scene.refill);
  CHECK(scene.has(rotorsweep::ensemble::Observable::energy));
  CHECK(scene.has(rotorsweep::ensemble::Observable::estimators));
  CHECK(scene.slip_rate == 4);
  CHECK(rotorsweep::kernels::stepper_names[scene.stepper] == "ros2");
  CHECK(scene.lanes == rotorsweep::ensemble::LaneKind::scalar);
  CHECK(scene.h_max == 0.25);
  CHECK(scene.output_path == "x.h5");
  CHECK(scene.member_count() == 2 * (3 + 1));  // per A: FM × 3 replicas, exact once (nothing drawn)
}

TEST_CASE("a missing required key is named", "[io][scene]") {
  CHECK_THAT(error_of("[model]\nrows = 20\n[drive]\ng = [0.001]\n"),
             Catch::Contains("'sweep.A'") && Catch::Contains("missing"));
  CHECK_THAT(error_of("[drive]\ng = [0.001]\n[sweep]\nA = [1]\n"), Catch::Contains("'model.rows'"));
  CHECK_THAT(error_of(minimal + "[initial]\nkinds = [\"exact\"]\n"), Catch::Contains("'initial.angles'"));
  CHECK_THAT(error_of("[model]\nrows = 2\n[drive]\ng = { from = 1, count = 3 }\n[sweep]\nA = [1]\n"),
             Catch::Contains("'drive.g.to'"));
}

TEST_CASE("a wrong type is named with what is allowed", "[io][scene]") {
  CHECK_THAT(error_of("[model]\nrows = \"20\"\n[drive]\ng = [0.001]\n[sweep]\nA = [1]\n"),
             Catch::Contains("'model.rows'") && Catch::Contains("even integer"));
  CHECK_THAT(error_of(minimal + "[observables]\nalignment = 1\n"),
             Catch::Contains("'observables.alignment'") && Catch::Contains("true or false"));
  CHECK_THAT(error_of(minimal + "[numerics]\nstepper = \"euler\"\n"),
             Catch::Contains("'numerics.stepper'") && Catch::Contains("rodas4"));
  CHECK_THAT(error_of(minimal + "[numerics]\ncontroller = \"PID\"\n"),
             Catch::Contains("'numerics.controller'") && Catch::Contains("integral, pi"));
  CHECK_THAT(error_of(minimal + "[thermal]\ntemperature = 0.1\n[numerics]\ncontroller = \"pi\"\n"),
             Catch::Contains("'numerics.controller'") && Catch::Contains("Langevin"));
  CHECK(parse_scene_text(minimal + "[numerics]\ncontroller = \"pi\"\n", "test.toml").controller ==
        rotorsweep::kernels::StepController::pi);
  CHECK_THAT(error_of("[model]\nrows = 20\n[drive]\ng = \"slow\"\n[sweep]\nA = [1]\n"),
             Catch::Contains("'drive.g'") && Catch::Contains("a number, a list of numbers"));
  CHECK_THAT(error_of("[model]\nrows = 20\n[drive]\ng = -1\n[sweep]\nA = [1]\n"),
             Catch::Contains("'drive.g'") && Catch::Contains("> 0"));
  CHECK_THAT(error_of("[model]\nrows = 20\n[drive]\ng = [0.01]\n[sweep]\nA = [inf]\n"),
             Catch::Contains("'sweep.A'") && Catch::Contains("must be a finite number"));
  CHECK_THAT(error_of(minimal + "[numerics]\nrtol = nan\n"),
             Catch::Contains("'numerics.rtol'") && Catch::Contains("must be a finite number"));
  CHECK_THAT(error_of(minimal + "[initial]\nkinds = [\"ferro\"]\n"),
             Catch::Contains("'initial.kinds'") && Catch::Contains("FM, AFM, random, exact"));
  CHECK_THAT(error_of("model = 3\n"), Catch::Contains("'model'"));
}

TEST_CASE("an out-of-range value is named with the allowed range", "[io][scene]") {
  CHECK_THAT(error_of("[model]\nrows = 3\n[drive]\ng = [0.001]\n[sweep]\nA = [1]\n"),
             Catch::Contains("'model.rows'") && Catch::Contains("got 3"));
  CHECK_THAT(error_of("[model]\nrows = 20\n[drive]\ng = [0.001, -1]\n[sweep]\nA = [1]\n"),
             Catch::Contains("'drive.g'") && Catch::Contains("> 0"));
  CHECK_THAT(error_of(minimal + "[numerics]\nrtol = 0.5\n"), Catch::Contains("'numerics.rtol'"));
  CHECK_THAT(error_of(minimal + "[schedule]\nrelax_periods = 5\nmax_periods = 4\n"),
             Catch::Contains("'schedule.max_periods'"));
  CHECK_THAT(error_of(minimal + "[initial]\nreplicas = 0\n"), Catch::Contains("'initial.replicas'"));
  CHECK_THAT(error_of("[model]\nrows = 2\n[drive]\ng = { from = 0, to = 1, count = 3, spacing = \"log\" }\n"
                      "[sweep]\nA = [1]\n"),
             Catch::Contains("'drive.g"));
  CHECK_THAT(
      error_of("[model]\nrows = 2\n[drive]\ng = [0.1]\n[sweep]\nA = { from = 3, to = 1, count = 3 }\n"),
      Catch::Contains("'sweep.A.to'"));
  CHECK_THAT(error_of(minimal + "[initial]\nkinds = [\"FM\", \"FM\"]\n"), Catch::Contains("'initial.kinds'"));
}

TEST_CASE("unknown keys and sections are rejected with the allowed ones", "[io][scene]") {
  CHECK_THAT(error_of(minimal + "[numerics]\nrtoll = 1e-6\n"),
             Catch::Contains("'numerics.rtoll'") && Catch::Contains("rtol"));
  CHECK_THAT(error_of(minimal + "[solver]\nrtol = 1e-6\n"),
             Catch::Contains("'solver'") && Catch::Contains("numerics"));
  CHECK_THAT(
      error_of(
          "[model]\nrows = 2\n[drive]\ng = { from = 1, to = 2, count = 2, steps = 3 }\n[sweep]\nA = [1]\n"),
      Catch::Contains("'drive.g.steps'"));
}

TEST_CASE("syntax errors and unreadable files name the file", "[io][scene]") {
  CHECK_THAT(error_of("[model\nrows = 20\n"), Catch::Contains("test.toml") && Catch::Contains("line 1"));
  const auto dir = rotorsweep::testing::scratch_directory("scene-parser");
  CHECK_THROWS_WITH(parse_scene_file((dir / "absent.toml").string()),
                    Catch::Contains("cannot read scene file"));
  CHECK_THROWS_WITH(parse_scene_file((dir / "absent.toml").string()), Catch::Contains("No such file"));
  CHECK_THROWS_WITH(parse_scene_file(dir.string()), Catch::Contains("is a directory"));
  const auto fifo = dir / "fifo.toml";
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(parse_scene_file(fifo.string()), Catch::Contains("not a regular file"));
  const auto path = rotorsweep::testing::write_text(dir / "ok.toml", minimal);
  CHECK(parse_scene_file(path.string()).A_values.size() == 2);
}

TEST_CASE("a huge bad value is cut in the message", "[io][scene]") {
  const std::string huge(1 << 20, 'x');
  const std::string message = error_of(minimal + "[numerics]\nstepper = \"" + huge + "\"\n");
  CHECK_THAT(message, Catch::Contains("'numerics.stepper'") && Catch::Contains("1048578 bytes"));
  CHECK(message.size() < 600);
  const std::string key_message = error_of(minimal + "[numerics]\n" + huge + " = 1\n");
  CHECK_THAT(key_message, Catch::Contains("unknown key"));
  CHECK(key_message.size() < 600);
}

TEST_CASE("angles and offsets beyond 1e4 rad are refused", "[io][scene]") {
  CHECK_THAT(error_of(minimal + "[initial]\noffset = 1e20\n"), Catch::Contains("'initial.offset'"));
  CHECK_THAT(error_of(minimal + "[initial]\nkinds = [\"exact\"]\nangles = [0.1, 2e4]\n"),
             Catch::Contains("'initial.angles'"));
  CHECK(error_of(minimal + "[initial]\noffset = -9999.5\n").empty());
}

TEST_CASE("the plan size is counted without overflow and the largest axis named", "[io][scene]") {
  const std::string message = error_of(
      "[model]\nrows = 4\n[drive]\ng = { from = 0.001, to = 1, count = 8388608 }\n"
      "[sweep]\nA = { from = 1, to = 2, count = 8388608 }\n[initial]\nkinds = [\"random\"]\nreplicas = "
      "262144\n");
  CHECK_THAT(message, Catch::Contains("'sweep.A'") && Catch::Contains("1.84e+19 members") &&
                          Catch::Contains("initial.replicas 262144"));
  CHECK_THAT(
      error_of(
          "[model]\nrows = 20\n[drive]\ng = [0.001]\n[sweep]\nA = { from = 1, to = 2, count = 100 }\n"
          "[initial]\nkinds = [\"random\"]\nreplicas = 1000000\n[numerics]\nrtol = [1e-6, 1e-7, 1e-8]\n"),
      Catch::Contains("'initial.replicas'"));
}

TEST_CASE("rows and tolerances may be lists: one variant each", "[io][scene]") {
  const auto scene = parse_scene_text(
      "[model]\nrows = [2, 64]\n[drive]\ng = [0.1]\n[sweep]\nA = [1]\n[initial]\nkinds = [\"exact\"]\n"
      "angles = [0, 3.14]\n[numerics]\nrtol = [1e-4, 1e-8, 1e-10]\natol = 1e-12\n",
      "test.toml");
  REQUIRE(scene.variants().size() == 6);
  CHECK(scene.variants()[1].rows == 2);
  CHECK(scene.variants()[1].rtol == 1e-8);
  CHECK(scene.variants()[5].rows == 64);
  CHECK(scene.variants()[5].atol == 1e-12);
  CHECK(scene.member_count() == 6);
  CHECK(scene.max_rows() == 64);
  CHECK_THAT(error_of(minimal + "[numerics]\nrtol = [1e-4, 1e-8]\natol = [1e-7, 1e-9, 1e-11]\n"),
             Catch::Contains("'numerics.atol'"));
  CHECK_THAT(error_of("[model]\nrows = [2, 2]\n[drive]\ng = [0.1]\n[sweep]\nA = [1]\n"),
             Catch::Contains("'model.rows'") && Catch::Contains("distinct"));
  CHECK_THAT(error_of("[model]\nrows = [4, 6]\n[drive]\ng = [0.1]\n[sweep]\nA = [1]\n[initial]\nkinds = "
                      "[\"exact\"]\nangles = [0, 1, 2, 3]\n"),
             Catch::Contains("'initial.angles'") && Catch::Contains("N = 6"));
}

TEST_CASE("disorder: drawn or per row, with the key named when wrong", "[io][scene]") {
  const auto scene = parse_scene_text(
      minimal + "[disorder]\nA = 1e-6\nseed = 4\ncoupling_rows = [0.1, -0.1]\n", "test.toml");
  CHECK(scene.disorder.A == 1e-6);
  CHECK(scene.disorder.seed == 4);
  CHECK(scene.disorder.coupling_rows == std::vector<double>{0.1, -0.1});
  CHECK(scene.disorder.any());
  CHECK_FALSE(parse_scene_text(minimal, "test.toml").disorder.any());
  CHECK_THAT(error_of(minimal + "[disorder]\nA = -1e-3\n"), Catch::Contains("'disorder.A'"));
  CHECK_THAT(error_of(minimal + "[disorder]\nanisotropy = 2\n"), Catch::Contains("'disorder.anisotropy'"));
  CHECK_THAT(error_of(minimal + "[disorder]\nA_rows = [0.1, 0.2, 0.3]\n"),
             Catch::Contains("'disorder.A_rows'") && Catch::Contains("does not divide N = 20"));
  CHECK_THAT(error_of(minimal + "[disorder]\ncoupling_rows = [0.1, -1.5]\n"),
             Catch::Contains("'disorder.coupling_rows'") && Catch::Contains("> -1"));
  CHECK_THAT(error_of(minimal + "[disorder]\nA = 1e-3\nA_rows = [0.1]\n"),
             Catch::Contains("'disorder.A_rows'") && Catch::Contains("both given"));
  CHECK_THAT(error_of(minimal + "[disorder]\nsigma = 1\n"), Catch::Contains("'disorder.sigma'"));
}

TEST_CASE("thermal: temperature, steps per period and seed, with the key named when wrong", "[io][scene]") {
  const auto scene = parse_scene_text(
      minimal + "[thermal]\ntemperature = 0.01\nsteps_per_period = 500\nseed = 2\n", "test.toml");
  CHECK(scene.thermal.temperature == 0.01);
  CHECK(scene.thermal.steps_per_period == 500);
  CHECK(scene.thermal.seed == 2);
  CHECK(scene.thermal.on());
  CHECK_FALSE(parse_scene_text(minimal, "test.toml").thermal.on());
  CHECK_THAT(error_of(minimal + "[thermal]\ntemperature = -0.1\n"), Catch::Contains("'thermal.temperature'"));
  CHECK_THAT(error_of(minimal + "[thermal]\ntemperature = nan\n"), Catch::Contains("'thermal.temperature'"));
  CHECK_THAT(error_of(minimal + "[thermal]\nsteps_per_period = 3\n"),
             Catch::Contains("'thermal.steps_per_period'"));
  CHECK_THAT(error_of(minimal + "[thermal]\ntemperature = 0.1\n[observables]\nestimators = true\n"),
             Catch::Contains("'observables.estimators'"));
}

TEST_CASE("the GPU takes every row scene up to its row limit, which the refusal names", "[io][scene][gpu]") {
  const std::string gpu = "[numerics]\ndevice = \"gpu\"\n";
  CHECK(parse_scene_text(minimal + gpu, "test.toml").device == rotorsweep::ensemble::Device::gpu);
  CHECK(parse_scene_text(minimal, "test.toml").device == rotorsweep::ensemble::Device::cpu);
  CHECK_THAT(error_of(minimal + "[numerics]\ndevice = \"tpu\"\n"),
             Catch::Contains("'numerics.device'") && Catch::Contains("cpu, gpu"));
  for (const std::string kind :
       {"[thermal]\ntemperature = 0.01\n", "[disorder]\nA = 1e-6\n", "[observables]\nrow_profiles = true\n"})
    CHECK(error_of(minimal + gpu + kind) == "");
  const std::string rest = "[drive]\ng = [0.001]\n[sweep]\nA = [1]\n" + gpu;
  CHECK(error_of("[model]\nrows = 20\ncouplings = \"dipolar\"\nrange = 2\n" + rest) == "");
  CHECK(error_of("[model]\nrows = 20\nboundary = \"open\"\n" + rest) == "");
  const auto limit = rotorsweep::ensemble::gpu_executor().max_rows(parse_scene_text(minimal + gpu, "test.toml"));
  CHECK(limit >= 128);
  CHECK(error_of("[model]\nrows = " + std::to_string(limit) + "\n" + rest) == "");
  CHECK_THAT(error_of("[model]\nrows = " + std::to_string(limit + 2) + "\n" + rest),
             Catch::Contains("'model.rows'") && Catch::Contains("at most " + std::to_string(limit)) &&
                 Catch::Contains("numerics.device = \"cpu\""));
  const std::string dipolar = "couplings = \"dipolar\"\nboundary = \"open\"\n";
  const auto coupled_limit = rotorsweep::ensemble::gpu_executor().max_rows(
      parse_scene_text("[model]\nrows = 4\n" + dipolar + rest, "test.toml"));
  CHECK_THAT(error_of("[model]\nrows = " + std::to_string(coupled_limit + 2) + "\n" + dipolar + rest),
             Catch::Contains("'model.rows'") && Catch::Contains("coupling table"));
}

TEST_CASE("slip_kinds needs the regime rule, no temperature and the CPU, each refusal naming its key",
          "[io][scene]") {
  const std::string on = "[observables]\nslip_kinds = true\n";
  CHECK(parse_scene_text(minimal + on, "test.toml").slip_kinds);
  CHECK_FALSE(parse_scene_text(minimal, "test.toml").slip_kinds);
  CHECK_THAT(error_of(minimal + on + "slips = false\n"),
             Catch::Contains("'observables.slip_kinds'") && Catch::Contains("observables.slips"));
  CHECK_THAT(error_of(minimal + on + "[thermal]\ntemperature = 0.01\n"),
             Catch::Contains("'observables.slip_kinds'") && Catch::Contains("thermal.temperature"));
  CHECK_THAT(error_of(minimal + on + "[numerics]\ndevice = \"gpu\"\n"),
             Catch::Contains("'numerics.device'") && Catch::Contains("slip_kinds"));
  CHECK_THAT(error_of(minimal + "[observables]\nslip_kinds = 1\n"), Catch::Contains("'observables.slip_kinds'"));
}

TEST_CASE("at T > 0 what needs a deterministic member is refused, naming its key", "[io][scene]") {
  const std::string hot = "[thermal]\ntemperature = 0.1\n";
  // the moments carry W and S: the Stokes estimator diverges with noise, as estimators does
  CHECK_THAT(error_of(minimal + hot + "[observables]\nmoments = true\n"),
             Catch::Contains("'observables.moments'") && Catch::Contains("Stokes estimator diverges"));
  CHECK(error_of(minimal + "[observables]\nmoments = true\n") == "");
  // shadow runs are a T = 0 error estimate: asked for at T > 0 they are refused, not dropped
  CHECK_THAT(error_of(minimal + hot + "[numerics]\nglobal_error = \"shadow\"\n"),
             Catch::Contains("'numerics.global_error'") && Catch::Contains("\"local\""));
  CHECK(error_of(minimal + hot + "[numerics]\nglobal_error = \"local\"\n") == "");
  CHECK(error_of(minimal + hot) == "");  // the default
}

TEST_CASE("an axis that gives a value twice is refused, naming it", "[io][scene]") {
  const std::string start = "[model]\nrows = 4\n";
  CHECK_THAT(error_of(start + "[drive]\ng = 0.01\n[sweep]\nA = [1, 2, 1]\n"),
             Catch::Contains("'sweep.A': has the value 1 more than once"));
  CHECK_THAT(error_of(start + "[drive]\ng = [0.01, 0.01]\n[sweep]\nA = 1\n"), Catch::Contains("'drive.g'"));
  CHECK_THAT(error_of(start + "[drive]\ng = { from = 0.01, to = 0.01, count = 3 }\n[sweep]\nA = 1\n"),
             Catch::Contains("'drive.g'"));
  CHECK_THAT(error_of(minimal + "[initial]\nnoise = [0.1, 0.1]\n"), Catch::Contains("'initial.noise'"));
  CHECK_THAT(error_of(minimal + "[initial]\noffset = [0, 0.0]\n"), Catch::Contains("'initial.offset'"));
  CHECK(error_of(start + "[drive]\ng = { from = 0.01, to = 0.02, count = 3 }\n[sweep]\nA = [0, 1]\n") == "");
}
