// The GPU backend's member driver compiled for the host: run member by member through member slots,
// it gives the CPU lanes' (scalar and SIMD) results bit for bit, for every stepper and schedule.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ensemble/engine/device_member.hpp"
#include "ensemble/engine/member_slots.hpp"
#include "ensemble/engine/shadow_run.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "support/same_results.hpp"

using namespace rotorsweep;

namespace {

/// Members [0, count) of `source` through DeviceMember on the host, in one chunk of slots.
std::vector<ensemble::MemberResult> run_through_slots(const ensemble::Scene& scene,
                                                      const ensemble::MemberSource& source) {
  return kernels::with_stepper_id(scene.stepper, [&]<kernels::StepperId id>() {
    using Model = kernels::NearestNeighbourRows<double>;
    using Stepper = typename kernels::stepper_at<id>::type::template type<Model>;
    using Driver = ensemble::DeviceMember<Model, Stepper>;
    const ensemble::Member variant = source.at(0);
    const auto schedule = ensemble::slot_schedule(
        scene, variant, Driver::Integrator::first_step_scale({variant.rtol, variant.atol}));
    ensemble::SlotChunk chunk(schedule, source.count);
    chunk.fill(scene, {&source, 0, source.count}, 0, source.count);
    std::vector<double> storage(Driver::storage_size(variant.rows));
    const ensemble::SlotViews views = chunk.views();
    for (std::size_t k = 0; k < source.count; ++k)
      Driver::run(schedule, views, k, storage.data(), storage.size());
    std::vector<ensemble::MemberResult> results;
    for (std::size_t k = 0; k < source.count; ++k) results.push_back(chunk.result(scene, k));
    return results;
  });
}

std::string scene_text(const std::string& stepper, int rows, const std::string& schedule,
                       const std::string& extra = "") {
  return "[model]\nrows = " + std::to_string(rows) +
         "\n[drive]\ng = [0.05, 0.3]\n[sweep]\nA = {from = 0.5, to = 14, count = 7}\n"
         "[initial]\nkinds = [\"AFM\", \"random\", \"FM\"]\nreplicas = 2\n[schedule]\n" +
         schedule + "\n[numerics]\nstepper = \"" + stepper + "\"\nrtol = 1e-7\natol = 1e-10\n" + extra;
}

void check_backends_agree(const ensemble::Scene& scene) {
  const ensemble::MemberPlan plan(scene);
  std::vector<ensemble::Member> members;
  for (std::size_t i = 0; i < plan.size(); ++i) members.push_back(plan[i]);
  const ensemble::MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }, {}};
  const auto slots = run_through_slots(scene, source);
  for (const auto lanes : {ensemble::LaneKind::scalar, ensemble::LaneKind::simd}) {
    ensemble::Scene cpu = scene;
    cpu.lanes = lanes;
    const auto outcome = ensemble::run_sweep(cpu, members, 2, {});
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
  const ensemble::MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }, {}};
  const auto slots = run_through_slots(scene, source);
  const auto cpu = ensemble::run_sweep(scene, members, 2, {});
  std::string first;
  CHECK(testing::count_differences(cpu.results, slots, first) == 0);
  INFO(first);
  CHECK(first.empty());
  // and the scale and the start took effect: the plain members give other results
  const auto plain = ensemble::run_sweep(scene, ensemble::plan_members(scene), 2, {});
  CHECK(testing::count_differences(plain.results, slots, first) > 0);
}
