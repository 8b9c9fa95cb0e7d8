// One member in a warp's registers (ensemble/rows/warp_member.hpp, on the host's emulation of the
// warp) against the one-thread driver DeviceMember (the CPU lanes' bits) on the same slots: the same
// periods, slips, regimes and attractors, D and every channel within the integration error.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include "ensemble/rows/device_member.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/warp_member.hpp"
#include "io/scene_parser.hpp"
#include "kernels/lanes/warp.hpp"
#include "kernels/lanes/warp_operation_count.hpp"
#include "kernels/models/rows/warp_rows.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "kernels/steppers/warp_member_form.hpp"
#include "kernels/steppers/warp_rosenbrock.hpp"
#include "support/member_follows.hpp"
#include "support/slot_runs.hpp"

using namespace rotorsweep;
using Model = kernels::NearestNeighbourRows<double>;
using Lanes = kernels::AdaptiveIntegrator<Model, kernels::RosenbrockStepper<Model>>;

namespace {

/// Every member of the scene in registers on L lanes × R slots (rows disordered where PerRow).
template <std::size_t L, std::size_t R, bool PerRow>
std::vector<ensemble::MemberResult> in_registers(const ensemble::Scene& scene) {
  using Rows = kernels::WarpRows<kernels::HostWarp<L>, R, PerRow, kernels::all_integrals>;
  using Driver = ensemble::WarpMember<Rows, kernels::WarpIntegrator<Rows, kernels::WarpRosenbrock<Rows, 8>>>;
  return testing::through_slots<Lanes>(
      scene, [&](const ensemble::SlotSchedule& s, const ensemble::SlotViews& v, std::size_t k) {
        REQUIRE(Driver::fits(s, kernels::all_integrals));
        Driver::run(s, v, k);
      });
}

/// The members in registers follow the one-thread driver (testing::check_member_follows), D outside CP
/// within 5e-10 and a hundredth of its own error.
template <std::size_t L, std::size_t R, bool PerRow>
void check_follows(const std::string& text) {
  const auto scene = io::parse_scene_text(text, "warp-member");
  const auto thread = testing::on_one_thread<Model, Lanes>(scene);
  const auto warp = in_registers<L, R, PerRow>(scene);
  REQUIRE(warp.size() == thread.size());
  for (std::size_t k = 0; k < thread.size(); ++k) {
    const auto &a = thread[k], &b = warp[k];
    INFO("L = " << L << ", R = " << R << ", member " << k << ": D " << a.dissipation() << ", "
                << a.final_state.attractor);
    testing::check_member_follows(a, b, 5e-10);
    // outside CP the stage solve's other order of eliminations moves D by rounding: 1.2e-10 and 1.8e-10
    // relative at A = 1 without disorder, a hundredth of D's own error or less
    INFO("relative D difference " << (b.dissipation() - a.dissipation()) / a.dissipation());
    if (a.regime != ensemble::Regime::cp)
      CHECK(std::fabs(b.dissipation() - a.dissipation()) <= 0.01 * a.dissipation_error());
  }
}

/// 20 rows from noisy AFM and FM starts at A = 1, 6, 12 (AFM, CP, FM) with a disorder of A that breaks
/// the rows' symmetry physically (so that CP's slips do not depend on rounding), every quadrature.
const std::string rows_20 =
    "[model]\nrows = 20\n[drive]\ng = 0.0011\n[sweep]\nA = [1.0, 6.0, 12.0]\n[initial]\nkinds = [\"AFM\", "
    "\"FM\"]\nnoise = 0.01\n[schedule]\nrelax_periods = 2\naverage_periods = 2\n[numerics]\nrtol = 1e-10\n"
    "atol = 1e-13\n[disorder]\nA = 1e-6\n[observables]\nestimators = true\nenergy = true\nmoments = true\n";

}  // namespace

TEST_CASE("a member in registers follows the one-thread driver: labels, slips, D and every channel",
          "[warp][device_member]") {
  check_follows<8, 3, true>(rows_20);
}

TEST_CASE("a member in registers runs uniform rows, wrapped periods and one thread's four rows",
          "[warp][device_member]") {
  const std::string uniform =
      rows_20.substr(0, rows_20.find("[disorder]")) + "[observables]\nenergy = true\n";
  check_follows<8, 3, false>(uniform.substr(0, uniform.find("[sweep]")) + "[sweep]\nA = [1.0, 12.0]\n" +
                             uniform.substr(uniform.find("[initial]")));
  check_follows<8, 3, false>(
      "[model]\nrows = 20\n[drive]\ng = 0.0011\n[sweep]\nA = [1.0, 12.0]\n[schedule]\nrelax_periods = 2\n"
      "average_periods = 2\n[numerics]\nwrap_angles = true\nrtol = 1e-10\natol = 1e-13\n");
  check_follows<1, 4, false>(
      "[model]\nrows = 4\n[drive]\ng = 0.05\n[sweep]\nA = [0.5, 3.0, 8.0]\n[initial]\nkinds = [\"AFM\", "
      "\"random\"]\n[schedule]\nrelax_periods = 2\naverage_periods = 2\n[numerics]\nrtol = 1e-10\natol = "
      "1e-13\n");
}

TEST_CASE("a schedule runs in registers only where the kernel can hold it", "[warp][device_member]") {
  using Rows = kernels::WarpRows<kernels::HostWarp<8>, 3, true, kernels::all_integrals>;
  using Driver = ensemble::WarpMember<Rows, kernels::WarpIntegrator<Rows, kernels::WarpRosenbrock<Rows, 8>>>;
  const auto schedule_of = [](const std::string& text) {
    const auto scene = io::parse_scene_text(text, "warp-fits");
    const ensemble::MemberPlan plan(scene);
    return ensemble::slot_schedule(scene, plan[0], 0.01);
  };
  const std::string base = "[drive]\ng = 0.01\n[sweep]\nA = [1.0]\n";
  CHECK(Driver::fits(schedule_of("[model]\nrows = 20\n" + base), kernels::all_integrals));
  CHECK(Driver::fits(schedule_of("[model]\nrows = 8\n" + base), kernels::all_integrals));  // a row per lane
  CHECK_FALSE(
      Driver::fits(schedule_of("[model]\nrows = 6\n" + base), kernels::all_integrals));  // a lane empty
  CHECK_FALSE(
      Driver::fits(schedule_of("[model]\nrows = 26\n" + base), kernels::all_integrals));  // beyond 8 × 3
  CHECK_FALSE(Driver::fits(schedule_of("[model]\nrows = 20\n" + base + "[thermal]\ntemperature = 0.01\n"),
                           kernels::all_integrals));
  CHECK_FALSE(
      Driver::fits(schedule_of("[model]\nrows = 20\n" + base + "[observables]\nrow_profiles = true\n"),
                   kernels::all_integrals));
  CHECK_FALSE(Driver::fits(schedule_of("[model]\nrows = 20\n" + base + "[observables]\nenergy = true\n"),
                           kernels::Integrals{}));  // an instantiation that carries R only
  using UniformRows = kernels::WarpRows<kernels::HostWarp<8>, 3, false, kernels::all_integrals>;
  using Uniform =
      ensemble::WarpMember<UniformRows,
                           kernels::WarpIntegrator<UniformRows, kernels::WarpRosenbrock<UniformRows, 8>>>;
  CHECK(Uniform::fits(schedule_of("[model]\nrows = 20\n" + base), kernels::all_integrals));
  CHECK_FALSE(Uniform::fits(schedule_of("[model]\nrows = 20\n" + base + "[disorder]\nA = 1e-3\n"),
                            kernels::all_integrals));  // no disorder factors per row to read it into
}

namespace {

/// A member's operations per attempt in registers on L lanes × R slots, counted on the emulation.
template <std::size_t L, std::size_t R, bool PerRow>
kernels::WarpOperationCount counted(const ensemble::Scene& scene, double& attempts) {
  kernels::WarpOperationCount count;
  std::vector<ensemble::MemberResult> results;
  {
    const kernels::CountingWarpOperations counting(count);
    results = in_registers<L, R, PerRow>(scene);
  }
  attempts = 0.0;
  for (const auto& r : results) attempts += r.steps_accepted + r.steps_rejected;
  return count;
}

}  // namespace

TEST_CASE("the emulation counts what a member in registers asks of its threads",
          "[warp][device_member][counts]") {
  const std::string uniform =
      "[model]\nrows = 20\n[drive]\ng = 0.0011\n[sweep]\nA = [1.0, 12.0]\n[schedule]\n"
      "relax_periods = 1\naverage_periods = 1\n[numerics]\nrtol = 1e-8\natol = 1e-11\n";
  const auto scene = io::parse_scene_text(uniform, "warp-counts");
  double attempts = 0.0, again = 0.0;
  const auto count = counted<8, 3, false>(scene, attempts);
  const auto repeated = counted<8, 3, false>(scene, again);
  REQUIRE(attempts > 0.0);
  CHECK(again == attempts);  // the same run counts the same operations
  CHECK(repeated.arithmetic == count.arithmetic);
  CHECK(repeated.shuffle == count.shuffle);
  CHECK(repeated.other == count.other);
  CHECK(repeated.division == count.division);
  // every stage evaluation reads both neighbour rows and the error norm is a sum over the lanes
  const int stages = kernels::rodas4p2_tableau.stages;  // the default stepper
  CHECK(double(count.shuffle) >= attempts * (2.0 * stages + 3.0));
  CHECK(double(count.arithmetic) > 10.0 * double(count.division + count.square_root));
  kernels::WarpOperationCount outside;
  { const kernels::CountingWarpOperations counting(outside); }
  in_registers<8, 3, false>(scene);
  CHECK(outside.arithmetic == 0);  // nothing counted once the scope has closed
  std::printf(
      "8 x 3 lanes x slots, 20 uniform rows, rodas4p2: per attempt and thread %.0f FP64 +-*, %.1f /, %.1f "
      "sqrt, %.0f other, %.0f shuffles (%.0f attempts)\n",
      double(count.arithmetic) / attempts, double(count.division) / attempts,
      double(count.square_root) / attempts, double(count.other) / attempts, double(count.shuffle) / attempts,
      attempts);
  // every quadrature (what a shape with every_quadrature carries): more arithmetic per attempt
  const auto every = io::parse_scene_text(
      uniform + "[observables]\nestimators = true\nenergy = true\nmoments = true\n", "warp-counts-every");
  double every_attempts = 0.0;
  const auto all = counted<8, 3, false>(every, every_attempts);
  REQUIRE(every_attempts > 0.0);
  CHECK(double(all.arithmetic) / every_attempts > double(count.arithmetic) / attempts);
  std::printf(
      "the same with every quadrature: per attempt and thread %.0f FP64 +-*, %.1f /, %.1f sqrt, %.0f other, "
      "%.0f shuffles (%.0f attempts)\n",
      double(all.arithmetic) / every_attempts, double(all.division) / every_attempts,
      double(all.square_root) / every_attempts, double(all.other) / every_attempts,
      double(all.shuffle) / every_attempts, every_attempts);
}
