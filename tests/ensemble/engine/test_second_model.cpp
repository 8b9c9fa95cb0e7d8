// The engine with a second model: one overdamped rotor in a rotating field (kernels/models/single_rotor.hpp,
// docs/model.md §1) through the same lane scheduler as the row model, against its closed form, through
// the GPU's member driver and chunk loop on the host, against the lanes' bits, and as a scene names it
// (model.kind = "single_rotor", ensemble/rows/row_models.hpp) through run_members; its Jacobian against
// central differences (docs/architecture.md "Worked example: adding a model").
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <numbers>
#include <tuple>
#include <vector>

#include "ensemble/engine/lane_scheduler.hpp"
#include "ensemble/gpu/device_drivers.hpp"
#include "ensemble/rows/device_member.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/row_chunks.hpp"
#include "ensemble/rows/row_models.hpp"
#include "ensemble/rows/row_problem.hpp"
#include "kernels/models/single_rotor.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "io/scene_parser.hpp"
#include "support/kernel_scratch.hpp"
#include "support/linearization_check.hpp"
#include "support/same_results.hpp"
#include "support/slot_runs.hpp"

using namespace rotorsweep;
using ensemble::Channel;

namespace {

constexpr double pi = std::numbers::pi;

/// θ(t) from ψ = θ - t - π: the Adler equation dψ/dt = -1 - a sin ψ, a = A/g > 1, solved by
/// v = tan(ψ/2) + a, v(t) = ω (v0 + ω tanh(ωt/2)) / (ω + v0 tanh(ωt/2)), ω = √(a² - 1).
double closed_form_theta(double A, double g, double psi0, double t) {
  const double a = A / g, omega = std::sqrt(a * a - 1), v0 = std::tan(psi0 / 2) + a;
  const double th = std::tanh(omega * t / 2);
  const double v = omega * (v0 + omega * th) / (omega + v0 * th);
  return t + pi + 2 * std::atan(v - a);
}

/// The member's three averaged periods against the closed form: R over period k is
/// g (θ(t_{k+1}) − θ(t_k)), from ψ0.
void check_periods_follow_closed_form(const ensemble::MemberResult& result, double A, double g, double psi0) {
  REQUIRE(result.status == kernels::LaneStatus::ok);
  REQUIRE(result.periods.size() == 3);
  for (std::size_t k = 0; k < 3; ++k) {
    const double t0 = 2 * pi * double(k), t1 = t0 + 2 * pi;
    const double R = g * (closed_form_theta(A, g, psi0, t1) - closed_form_theta(A, g, psi0, t0));
    CHECK(result.periods[k][Channel::dissipation] == Approx(R).epsilon(1e-7).margin(1e-9));
  }
}

/// How a member of the rotor enters a lane: its start is Member::start (θ0 = π + ψ0), A and g its own.
template <class V>
struct RotorSetup {
  std::tuple<> model_arguments() const { return {}; }  ///< the model needs none beyond its size
  std::vector<double> initial_state(const ensemble::Member& m) const { return *m.start; }
  typename kernels::SingleRotor<V>::Parameters parameters(const ensemble::Member& m,
                                                          const std::vector<double>&) const {
    return {m.A, m.g};
  }
};

template <class V>
using RotorIntegrator =
    kernels::AdaptiveIntegrator<kernels::SingleRotor<V>, kernels::RosenbrockStepper<kernels::SingleRotor<V>>>;

/// The members on lanes of type V (LaneScheduler, as `rotorsweep run` runs the row models).
template <class V>
std::vector<ensemble::MemberResult> run(const ensemble::Scene& scene,
                                        const std::vector<ensemble::Member>& members) {
  using Problem = ensemble::RowProblem<kernels::SingleRotor<V>, RotorIntegrator<V>, RotorSetup<V>>;
  ensemble::LaneScheduler<Problem> scheduler(scene, members.front(), RotorSetup<V>{});
  std::vector<ensemble::MemberResult> results(members.size());
  std::size_t next = 0;
  scheduler.run(
      [&]() -> std::optional<ensemble::Member> {
        if (next == members.size()) return std::nullopt;
        return members[next++];
      },
      [&](ensemble::MemberResult&& r) { results[r.index] = std::move(r); }, [] { return false; });
  return results;
}

/// The members as the GPU runs them, on the host: DeviceMember on one double lane each, through
/// run_row_chunks in chunks of 4 (two in flight).
std::vector<ensemble::MemberResult> run_on_device_member(const ensemble::Scene& scene,
                                                         const std::vector<ensemble::Member>& members) {
  using Driver = ensemble::DeviceMember<kernels::SingleRotor<double>, RotorIntegrator<double>>;
  testing::HostSlotDevice device{
      [](const ensemble::SlotSchedule& s, const ensemble::SlotViews& v, std::size_t k) {
        std::vector<double> storage(Driver::storage_size(s));
        Driver::run(s, v, k, storage.data(), storage.size());
      }};
  const auto schedule = ensemble::slot_schedule(
      scene, members.front(),
      ensemble::device_first_step_scale<RotorIntegrator<double>>(scene, members.front()));
  const ensemble::MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }};
  std::vector<ensemble::MemberResult> results(members.size());
  ensemble::run_row_chunks(
      scene, {&source, 0, members.size()}, schedule, 4, {.threads = 2},
      [&](ensemble::MemberResult&& r) { results.at(r.index) = std::move(r); }, device);
  return results;
}

}  // namespace

TEST_CASE("a second model through the same scheduler: the single rotor's closed form", "[ensemble][model]") {
  static_assert(kernels::LaneModel<kernels::SingleRotor<double>>);
  static_assert(kernels::LaneModel<kernels::SingleRotor<kernels::simd_lane>>);
  ensemble::Scene scene;
  scene.stepper = *kernels::parse_stepper("rodas4");
  scene.relax_periods = 0;
  scene.average_periods = 3;
  scene.period_series = true;
  scene.observables = {};
  scene.observables.set(ensemble::Observable::dissipation, true);
  const double g = 0.5;
  std::vector<double> psi0;
  std::vector<ensemble::Member> members;
  for (std::size_t i = 0; i < 11; ++i) {
    const double A = 0.6 + 0.4 * double(i);  // a = A/g from 1.2 to 9.2
    psi0.push_back(-1.0 + 0.25 * double(i));
    ensemble::Member member;
    member.index = member.stream = i;
    member.A = A;
    member.g = g;
    member.kind = ensemble::InitialKind::exact;
    member.start = std::make_shared<const std::vector<double>>(std::vector<double>{pi + psi0.back()});
    member.rows = 1;
    member.rtol = 1e-10;
    member.atol = 1e-12;
    members.push_back(member);
  }
  const auto scalar = run<double>(scene, members);
  const auto simd = run<kernels::simd_lane>(scene, members);
  const auto device = run_on_device_member(scene, members);
  for (std::size_t i = 0; i < members.size(); ++i) {
    const double A = members[i].A, start = psi0[i];
    INFO("member " << i << ": A/g = " << A / g << ", psi0 = " << start);
    check_periods_follow_closed_form(scalar[i], A, g, start);
    CHECK(scalar[i].theta_final[0] ==
          Approx(kernels::wrap_2pi(closed_form_theta(A, g, start, 6 * pi))).margin(1e-7));
    // SIMD lanes give the scalar bits
    CHECK(simd[i].theta_final[0] == scalar[i].theta_final[0]);
    CHECK(simd[i].dissipation() == scalar[i].dissipation());
    CHECK(simd[i].steps_accepted == scalar[i].steps_accepted);
    // and so does the GPU's driver, period by period
    CHECK(testing::result_difference(scalar[i], device[i]) == "");
  }
  // locked state: R per period → 2π g
  CHECK(scalar.back().periods.back()[Channel::dissipation] == Approx(2 * pi * g).epsilon(1e-6));
}

TEST_CASE("the single rotor's linearization agrees with central differences", "[ensemble][model]") {
  auto m = testing::model<kernels::SingleRotor<double>>(1);
  for (const auto& [A, g] : {std::pair{0.6, 0.5}, {4.6, 0.5}, {2.0, 3.0}}) {
    m.set_lane(0, {A, g});
    for (const double theta : {0.3, 2.0, -4.1})
      for (const double t : {0.0, 1.3, 5.9}) {
        INFO("A = " << A << ", g = " << g << ", theta = " << theta << ", t = " << t);
        testing::check_linearization(m, {theta}, t);
      }
  }
}

TEST_CASE("a scene names the single rotor and run_members sweeps it to its closed form", "[ensemble][model]") {
  const std::string text =
      "[model]\nkind = \"single_rotor\"\n[drive]\ng = [0.5]\n[sweep]\nA = { from = 0.6, to = 4.6, count = 11 "
      "}\n[initial]\nkinds = [\"FM\"]\nnoise = [0]\noffset = [2.14, 2.64, 3.14]\n[schedule]\nrelax_periods = "
      "0\naverage_periods = 3\n[observables]\nperiod_series = true\n[numerics]\nrtol = 1e-10\natol = 1e-12\n";
  for (const char* stepper : {"rodas4", "ros2"}) {
    const auto scene = io::parse_scene_text(text + "stepper = \"" + stepper + "\"\n", "single_rotor");
    REQUIRE(scene.model == ensemble::RowModelKind::single_rotor);
    REQUIRE(scene.row_counts == std::vector<std::size_t>{1});
    CHECK(scene.lanes == ensemble::LaneKind::scalar);
    CHECK_FALSE(scene.has(ensemble::Observable::alignment));
    CHECK_FALSE(scene.has(ensemble::Observable::slips));
    const auto members = ensemble::plan_members(scene);
    REQUIRE(members.size() == 33);
    const auto results = ensemble::run_sweep(scene, members, {.threads = 2}).results;
    for (std::size_t i = 0; i < members.size(); ++i) {
      const double A = members[i].A, g = members[i].g, psi0 = members[i].offset - pi;
      INFO(stepper << ", member " << i << ": A/g = " << A / g << ", psi0 = " << psi0);
      check_periods_follow_closed_form(results[i], A, g, psi0);
    }
  }
  const auto refused = [&](const std::string& extra, const std::string& key) {
    INFO(extra);
    CHECK_THROWS_WITH(io::parse_scene_text(text + extra, "single_rotor"), Catch::Contains(key));
  };
  refused("device = \"gpu\"\n", "numerics.device");
  refused("stepper = \"dopri5\"\n", "numerics.stepper");
  refused("lanes = \"simd\"\n", "numerics.lanes");
  refused("[thermal]\ntemperature = 0.1\n", "thermal.temperature");
  refused("[disorder]\nA = 0.01\n", "disorder.A");
  const std::string model_keys = text.substr(0, text.find("[drive]"));
  for (const char* key : {"rows = 2", "couplings = \"dipolar\"", "boundary = \"open\""}) {
    INFO(key);
    CHECK_THROWS_WITH(io::parse_scene_text(model_keys + key + "\n" + text.substr(model_keys.size()), "s"),
                      Catch::Contains("model.") && Catch::Contains("single_rotor"));
  }
  CHECK_THROWS_WITH(io::parse_scene_text(text.substr(0, text.find("[numerics]")) + "alignment = true\n", "s"),
                    Catch::Contains("observables.alignment"));
  CHECK_THROWS_WITH(io::parse_scene_text("[model]\nkind = \"rotor\"\n" + text.substr(model_keys.size()), "s"),
                    Catch::Contains("model.kind") && Catch::Contains("rows") && Catch::Contains("single_rotor"));
}
