// The GPU backend's member driver compiled for the host: run member by member through member slots,
// it gives the CPU lanes' (scalar and SIMD) results bit for bit, for every stepper, schedule and
// scene kind (disorder, temperature, coupling tables, open rows, row profiles); and the GPU's chunk
// loop on a host device: shadow runs between chunks, members claimed by two devices.
#include <algorithm>
#include <array>
#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "ensemble/gpu/device_drivers.hpp"
#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/row_chunks.hpp"
#include "ensemble/rows/shadow_run.hpp"
#include "ensemble/rows/symmetry_probe.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "support/same_results.hpp"
#include "support/slot_runs.hpp"

using namespace rotorsweep;

namespace {

/// Members [0, count) of `source` through DeviceMember on the host, in one chunk of slots, with the
/// model and integrator the GPU backend picks for the scene.
std::vector<ensemble::MemberResult> run_through_slots(const ensemble::Scene& scene,
                                                      const ensemble::MemberSource& source) {
  return ensemble::with_device_driver(scene, [&]<class Model, class Integrator>() {
    using Driver = ensemble::DeviceMember<Model, Integrator>;
    const ensemble::Member variant = source.at(0);
    const auto schedule = ensemble::slot_schedule(
        scene, variant, ensemble::device_first_step_scale<Integrator>(scene, variant));
    std::vector<ensemble::Member> members;
    for (std::size_t k = 0; k < source.count; ++k) members.push_back(source.at(k));
    ensemble::SlotChunk chunk(schedule, source.count);
    chunk.fill(scene, members);
    std::vector<double> storage(Driver::storage_size(schedule));
    const ensemble::SlotViews views = chunk.views();
    for (std::size_t k = 0; k < source.count; ++k)
      Driver::run(schedule, views, k, storage.data(), storage.size());
    std::vector<ensemble::MemberResult> results;
    for (std::size_t k = 0; k < source.count; ++k) results.push_back(chunk.result(scene, k));
    return results;
  });
}

/// The tolerances a stepper runs at here: the bits do not depend on them, the cost does. ros2, of order 2
/// with an error estimate of order 1, takes 350 times rodas4's steps at rtol 1e-7 (17 s for the 84
/// members of one sweep); at rtol 1e-4 it takes 32 times fewer, and rejects more of them.
std::string tolerances(const std::string& stepper) {
  return stepper == "ros2" ? "rtol = 1e-4\natol = 1e-7\n" : "rtol = 1e-7\natol = 1e-10\n";
}

std::string scene_text(const std::string& stepper, int rows, const std::string& schedule,
                       const std::string& extra = "", const std::string& model = "") {
  return "[model]\nrows = " + std::to_string(rows) + "\n" + model +
         "[drive]\ng = [0.05, 0.3]\n[sweep]\nA = {from = 0.5, to = 14, count = 7}\n"
         "[initial]\nkinds = [\"AFM\", \"random\", \"FM\"]\nreplicas = 2\n[schedule]\n" +
         schedule + "\n[numerics]\nstepper = \"" + stepper + "\"\n" + tolerances(stepper) + extra;
}

/// The members' own runs on both backends (the shadow runs of slipping members are chunks of their
/// own through the same driver, run_row_chunks, and off here).
void check_backends_agree(ensemble::Scene scene) {
  scene.shadow_runs = false;
  const ensemble::MemberPlan plan(scene);
  std::vector<ensemble::Member> members;
  for (std::size_t i = 0; i < plan.size(); ++i) members.push_back(plan[i]);
  const ensemble::MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }};
  const auto slots = run_through_slots(scene, source);
  for (const auto lanes : {ensemble::LaneKind::scalar, ensemble::LaneKind::simd}) {
    ensemble::Scene cpu = scene;
    cpu.lanes = lanes;
    const auto outcome = ensemble::run_sweep(cpu, members, {.threads = 2});
    std::string first;
    INFO((lanes == ensemble::LaneKind::simd ? "simd lanes" : "scalar lanes"));
    CHECK(testing::count_differences(outcome.results, slots, first) == 0);
    INFO(first);
    CHECK(first.empty());
  }
}

}  // namespace

TEST_CASE("the device member driver gives the CPU lanes' bits with every stepper", "[device_member]") {
  for (const std::string_view name : kernels::stepper_names) {
    const std::string stepper(name);
    INFO(stepper);
    check_backends_agree(io::parse_scene_text(
        scene_text(stepper, 6, "relax_periods = 1\naverage_periods = 2"), "device-member"));
  }
}

TEST_CASE("the device member driver keeps the CPU's schedule: steady test, wrap, period series",
          "[device_member]") {
  const auto scene = io::parse_scene_text(
      scene_text(
          "rodas4", 4, "relax_periods = 1\naverage_periods = 3\nsteady_tol = 1e-4\nmax_periods = 9",
          "wrap_angles = true\n[observables]\nperiod_series = true\nestimators = true\nenergy = true\n"),
      "device-member-schedule");
  check_backends_agree(scene);
}

TEST_CASE("the device member driver gives the CPU's failures: step budget", "[device_member]") {
  const auto scene = io::parse_scene_text(
      scene_text("rodas4", 2, "relax_periods = 1\naverage_periods = 1", "max_steps = 40\n"),
      "device-member-budget");
  check_backends_agree(scene);
}

TEST_CASE("the device member driver at N = 2 and N = 20, without the slip counter", "[device_member]") {
  for (int rows : {2, 20}) {
    INFO(rows);
    check_backends_agree(
        io::parse_scene_text(scene_text("rodas5p", rows, "relax_periods = 1\naverage_periods = 1",
                                        "[observables]\nslips = false\n"),
                             "device-member-rows"));
  }
}

TEST_CASE("the device member driver with the PI step controller", "[device_member][controller]") {
  check_backends_agree(io::parse_scene_text(
      scene_text("rodas4", 6, "relax_periods = 1\naverage_periods = 2", "controller = \"pi\"\n"),
      "device-member-pi"));
}

TEST_CASE("the device member driver runs a shadow run as the CPU does: its tolerance scale and its start",
          "[device_member][shadow]") {
  const auto scene = io::parse_scene_text(
      scene_text("rodas4p2", 6, "relax_periods = 0\naverage_periods = 2", "global_error = \"local\"\n"),
      "device-member-shadow");
  const ensemble::MemberPlan plan(scene);
  std::vector<ensemble::Member> members;
  for (std::size_t i = 0; i < plan.size(); ++i) {
    ensemble::Member m = plan[i];
    m.tolerance_scale = ensemble::shadow_tolerance_scale;
    auto start = ensemble::member_initial_angles(scene, m);
    for (double& theta : start) theta += 0.25;  // a start of its own, as a primary's averaged periods give
    m.start = std::make_shared<const std::vector<double>>(std::move(start));
    members.push_back(std::move(m));
  }
  const ensemble::MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }};
  const auto slots = run_through_slots(scene, source);
  const auto cpu = ensemble::run_sweep(scene, members, {.threads = 2});
  std::string first;
  CHECK(testing::count_differences(cpu.results, slots, first) == 0);
  INFO(first);
  CHECK(first.empty());
  // and the scale and the start took effect: the plain members give other results
  const auto plain = ensemble::run_sweep(scene, ensemble::plan_members(scene), {.threads = 2});
  CHECK(testing::count_differences(plain.results, slots, first) > 0);
}

/// The members of `source` through the GPU's chunk loop (run_row_chunks) on a host device that runs
/// DeviceMember, in chunks of `capacity`: results by plan index (an index not run keeps its default),
/// the last progress count, each chunk's (stops, members), whether it was stopped and what it started
/// after; `stop_after`: the stop flag rises once that many members were delivered; `claim`: the control's.
struct HostChunkRun {
  std::vector<ensemble::MemberResult> results;
  std::vector<char> delivered;
  std::size_t progress = 0;
  std::vector<std::pair<int, std::size_t>> chunks;
  bool interrupted = false;
  std::size_t started_after_stop = 0;  ///< members of chunks started once it was stopped
};
HostChunkRun run_host_chunks(const ensemble::Scene& scene, const ensemble::MemberSource& source,
                             std::size_t plan_size, std::size_t capacity,
                             std::size_t stop_after = std::size_t(-1),
                             std::function<std::size_t(std::size_t, std::size_t)> claim = {}) {
  HostChunkRun run;
  run.results.resize(plan_size);
  run.delivered.assign(plan_size, 0);
  ensemble::with_device_driver(scene, [&]<class Model, class Integrator>() {
    using Driver = ensemble::DeviceMember<Model, Integrator>;
    std::atomic<bool> stop = false;
    std::atomic<std::size_t> started_after_stop = 0;
    testing::HostSlotDevice device{
        [&](const ensemble::SlotSchedule& s, const ensemble::SlotViews& v, std::size_t k) {
          if (stop) ++started_after_stop;
          std::vector<double> storage(Driver::storage_size(s));
          Driver::run(s, v, k, storage.data(), storage.size());
        }};
    const ensemble::Member first = source.at(0);
    const auto schedule =
        ensemble::slot_schedule(scene, first, ensemble::device_first_step_scale<Integrator>(scene, first));
    const ensemble::RunControl control{.threads = 2,
                                       .progress =
                                           [&](std::size_t done) {
                                             run.progress = done;
                                             if (done >= stop_after) stop = true;
                                           },
                                       .stop = [&] { return stop.load(); },
                                       .claim = claim};
    run.interrupted = ensemble::run_row_chunks(
                          scene, {&source, 0, source.count}, schedule, capacity, control,
                          [&](ensemble::MemberResult&& r) {
                            run.delivered.at(r.index) += 1;
                            run.results.at(r.index) = std::move(r);
                          },
                          device)
                          .interrupted;
    run.chunks = device.chunks;
    run.started_after_stop = started_after_stop;
  });
  return run;
}

/// Random starts without disorder at N = 6: CP members, symmetry-limited, some of whose shadows fall into
/// the strict-FM set.
ensemble::Scene shadowed_scene() {
  return io::parse_scene_text(
      "[model]\nrows = 6\n[drive]\ng = [0.002]\n[sweep]\nA = [6.0, 8.1, 9.3]\n"
      "[initial]\nkinds = [\"random\", \"AFM\"]\nreplicas = 3\n[numerics]\nrtol = 1e-7\natol = 1e-10\n",
      "device-member-shadow-chunks");
}

TEST_CASE("the device's chunks run shadow runs between the plan's and give the CPU lanes' errors and flags",
          "[device_member][shadow]") {
  const auto scene = shadowed_scene();
  const auto members = ensemble::plan_members(scene);
  const auto cpu = ensemble::run_sweep(scene, members, {.threads = 2}).results;
  const ensemble::MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }};
  const HostChunkRun gpu = run_host_chunks(scene, source, members.size(), 3);
  CHECK(gpu.progress == members.size());

  std::size_t departed = 0, shadowed = 0, limited = 0;
  for (std::size_t i = 0; i < cpu.size(); ++i) {
    INFO("member " << i);
    CHECK(int(gpu.delivered[i]) == 1);
    CHECK(testing::result_difference(cpu[i], gpu.results[i]) == "");  // the error, the shadow's D, the flags
    departed += cpu[i].shadow_departed;
    limited += cpu[i].symmetry_limited;
    shadowed += ensemble::needs_shadow(cpu[i]);
    shadowed += ensemble::runs_probes(scene, false, members[i].rtol) && ensemble::needs_probe(cpu[i], false);
  }
  CHECK(departed > 0);  // the test covers a departed shadow and a symmetry probe's verdict
  CHECK(limited > 0);
  // six plan chunks of 3 (4 periods each) and chunks of the shadows and symmetry probes (2 averaged
  // periods), the first of them started before the plan's last
  std::size_t plan = 0, shadows = 0, last_plan = 0, first_shadows = gpu.chunks.size();
  for (std::size_t c = 0; c < gpu.chunks.size(); ++c) {
    const auto [stops, count] = gpu.chunks[c];
    if (stops == 4) plan += count, last_plan = c;
    if (stops == 2) shadows += count, first_shadows = std::min(first_shadows, c);
  }
  CHECK(plan == members.size());
  CHECK(shadows == shadowed);
  CHECK(first_shadows < last_plan);
}

TEST_CASE("a stopped device loop starts no chunk more and hands over no primary without its shadow",
          "[device_member][shadow]") {
  const auto scene = shadowed_scene();
  const auto members = ensemble::plan_members(scene);
  const ensemble::MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }};
  const HostChunkRun gpu = run_host_chunks(scene, source, members.size(), 3, 1);
  CHECK(gpu.interrupted);
  CHECK(gpu.started_after_stop == 0);  // the chunk in flight when the flag rose was finished, none started
  std::size_t delivered = 0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    if (!gpu.delivered[i]) continue;
    ++delivered;
    INFO("member " << i);
    if (ensemble::needs_shadow(gpu.results[i])) CHECK_FALSE(std::isnan(gpu.results[i].dissipation_shadow));
  }
  CHECK(delivered == gpu.progress);
  CHECK(delivered < members.size());
}

TEST_CASE("two devices claiming members from one counter run each member once, with the CPU lanes' bits",
          "[device_member][claim]") {
  // as two ranks of mpirun with a GPU each: every claim takes the counter's next member
  const auto scene = shadowed_scene();
  const auto members = ensemble::plan_members(scene);
  const auto cpu = ensemble::run_sweep(scene, members, {.threads = 2}).results;
  std::atomic<std::size_t> counter = 0;
  const ensemble::MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }};
  const auto claim = [&](std::size_t begin, std::size_t) { return begin + counter++; };
  std::array<HostChunkRun, 2> ranks;
  std::array<std::thread, 2> threads;
  for (std::size_t r = 0; r < 2; ++r)
    threads[r] = std::thread(
        [&, r] { ranks[r] = run_host_chunks(scene, source, members.size(), 2, std::size_t(-1), claim); });
  for (auto& t : threads) t.join();

  for (std::size_t i = 0; i < members.size(); ++i) {
    INFO("member " << i);
    REQUIRE(int(ranks[0].delivered[i]) + int(ranks[1].delivered[i]) == 1);
    CHECK(testing::result_difference(cpu[i], ranks[ranks[0].delivered[i] ? 0 : 1].results[i]) == "");
  }
  CHECK(ranks[0].progress + ranks[1].progress == members.size());
}

TEST_CASE("the device member driver with disorder: drawn and given per row", "[device_member][disorder]") {
  check_backends_agree(io::parse_scene_text(
      scene_text("rodas4p2", 6, "relax_periods = 1\naverage_periods = 2",
                 "[disorder]\nA = 0.05\nanisotropy = 0.02\ncoupling_rows = [0.1, -0.1, 0.0]\nseed = 4\n"),
      "device-member-disorder"));
}

TEST_CASE("the device member driver with row profiles, periodic and open rows",
          "[device_member][row_profiles]") {
  const std::string profiles = "[observables]\nrow_profiles = true\nenergy = true\n";
  check_backends_agree(
      io::parse_scene_text(scene_text("rodas5p", 6, "relax_periods = 1\naverage_periods = 3", profiles),
                           "device-member-profiles"));
  const auto open = io::parse_scene_text(
      scene_text("rodas4", 8, "relax_periods = 1\naverage_periods = 2", profiles, "boundary = \"open\"\n"),
      "device-member-open");
  REQUIRE(open.couplings.open);
  check_backends_agree(open);
}

TEST_CASE("the device member driver with coupling tables: dipolar rows, an explicit table with disorder",
          "[device_member][couplings]") {
  check_backends_agree(
      io::parse_scene_text(scene_text("rodas4p2", 8, "relax_periods = 1\naverage_periods = 2", "",
                                      "couplings = \"dipolar\"\nrange = \"all\"\n"),
                           "device-member-dipolar"));
  check_backends_agree(
      io::parse_scene_text(scene_text("rodas4", 6, "relax_periods = 1\naverage_periods = 2",
                                      "[disorder]\nA = 0.05\nanisotropy_rows = [0.02, -0.03]\nseed = 4\n",
                                      "coupling_table = { a = 1.2, b = [1.0, 0.2], c = [0.1, 0.05] }\n"),
                           "device-member-table"));
}

TEST_CASE("the device member driver at T > 0: the Langevin stepper, its noise and slip threshold",
          "[device_member][thermal]") {
  const auto scene =
      io::parse_scene_text(scene_text("rodas4p2", 4, "relax_periods = 1\naverage_periods = 3",
                                      "[thermal]\ntemperature = 0.05\nsteps_per_period = 400\nseed = 9\n"
                                      "[observables]\nrow_profiles = true\nenergy = true\n"),
                           "device-member-thermal");
  REQUIRE(scene.thermal.on());
  check_backends_agree(scene);
}

TEST_CASE("a GPU thread's row limit depends on the model, the integrator and the row profiles",
          "[device_member]") {
  ::setenv("ROTORSWEEP_GPU_TEAM", "1", 1);  // a member per thread, also where a team could run it
  const auto limit = [](const std::string& text) {
    return ensemble::gpu_executor().max_rows(io::parse_scene_text(text, "device-member-limit"));
  };
  const std::string plain = scene_text("rodas4p2", 6, "relax_periods = 1\naverage_periods = 2");
  const std::size_t nearest = limit(plain);
  CHECK(nearest % 2 == 0);
  CHECK(nearest >= 100);
  CHECK(limit(scene_text("rodas4p2", 6, "relax_periods = 1\naverage_periods = 2", "",
                         "couplings = \"dipolar\"\n")) < nearest);
  CHECK(limit(plain + "[observables]\nrow_profiles = true\n") < nearest);
  CHECK(limit(plain + "[thermal]\ntemperature = 0.1\n") > nearest);  // one stage, no error estimate
  ::unsetenv("ROTORSWEEP_GPU_TEAM");
}
