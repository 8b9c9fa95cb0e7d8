// Jumps and smooth slips (ensemble/rows/slip_kinds.hpp, docs/model.md §3): the matching rule on given
// energies, and on N = 2 rows the CP side (A = 8) against the smooth-alternation window (A = 9, 9.5) with
// the slips' energies adding up to D, as the window's study found them (docs/studies.md); no SA below A_*.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "ensemble/rows/slip_kinds.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"

using namespace rotorsweep;
using Catch::Detail::Approx;

namespace {

ensemble::MemberResult cp_member(std::vector<std::vector<double>> energies) {
  ensemble::MemberResult m;
  m.regime = ensemble::Regime::cp;
  m.final_state.attractor = "CP:2SL:p1";
  m.slip_energies = std::move(energies);
  return m;
}

}  // namespace

TEST_CASE("a slip whose energy keeps more than a quarter at g/10 is a jump; all smooth is SA",
          "[ensemble][slip_kinds]") {
  auto primary = cp_member({{1.0, 2.0}, {1.0, 2.0}});
  SECTION("every slip smooth: smooth alternation, the attractor label follows") {
    ensemble::take_slower_rerun(primary, cp_member({{0.1, 0.2}, {0.12, 0.4}}), true);
    CHECK(primary.slip_jumps == 0.0);
    CHECK(primary.slip_smooth == 2.0);
    CHECK(primary.regime == ensemble::Regime::sa);
    CHECK(primary.final_state.attractor == "SA:2SL:p1");
  }
  SECTION("one jump keeps it CP") {
    ensemble::take_slower_rerun(primary, cp_member({{0.1, 1.9}, {0.1, 0.2}}), true);
    CHECK(primary.slip_jumps == 0.5);
    CHECK(primary.slip_smooth == 1.5);
    CHECK(primary.regime == ensemble::Regime::cp);
    CHECK(primary.final_state.attractor == "CP:2SL:p1");
  }
  SECTION("a period whose slip count differs is unmatched: not SA") {
    ensemble::take_slower_rerun(primary, cp_member({{0.1, 0.2}, {0.1}}), true);
    CHECK(primary.slip_jumps == 0.0);
    CHECK(primary.slip_smooth == 1.0);
    CHECK(primary.regime == ensemble::Regime::cp);
  }
  SECTION("every slip smooth where the landscape has jumps (below A_*): counted, but CP") {
    ensemble::take_slower_rerun(primary, cp_member({{0.1, 0.2}, {0.12, 0.4}}), false);
    CHECK(primary.slip_smooth == 2.0);
    CHECK(primary.regime == ensemble::Regime::cp);
    CHECK(primary.final_state.attractor == "CP:2SL:p1");
  }
  SECTION("a failed rerun classifies nothing") {
    auto failed = cp_member({});
    failed.status = kernels::LaneStatus::step_budget;
    ensemble::take_slower_rerun(primary, failed, true);
    CHECK(std::isnan(primary.slip_jumps));
    CHECK(primary.regime == ensemble::Regime::cp);
  }
}

TEST_CASE("N = 2 at small g: CP below A_* jumps, the window above it is smooth alternation",
          "[ensemble][slip_kinds]") {
  const auto scene = io::parse_scene_text(
      "[model]\nrows = 2\n[drive]\ng = 1e-5\n[sweep]\nA = [8.0, 9.0, 9.5]\n[initial]\nkinds = [\"AFM\"]\n"
      "noise = 0.0\nreplicas = 2\n[disorder]\nA = 1e-6\n[schedule]\nrelax_periods = 2\naverage_periods = 2\n"
      "[observables]\nslip_kinds = true\n[numerics]\nrtol = 1e-12\natol = 1e-15\n",
      "slip-kinds");
  const auto results = ensemble::run_sweep(scene, ensemble::plan_members(scene), {.threads = 2}).results;
  REQUIRE(results.size() == 6);
  for (std::size_t i = 0; i < results.size(); ++i) {
    const auto& m = results[i];
    INFO("member " << i);
    REQUIRE(m.status == kernels::LaneStatus::ok);
    CHECK(m.slips_per_period() == 4);  // two slips per half period
    if (i < 2) {
      CHECK(m.regime == ensemble::Regime::cp);
      CHECK(m.slip_jumps == 4);
      CHECK(m.slip_smooth == 0);
    } else {
      CHECK(m.regime == ensemble::Regime::sa);
      CHECK(m.slip_smooth == 4);
      CHECK(m.final_state.attractor.rfind("SA:", 0) == 0);
    }
    // the slips carry the friction: their energies add up to D but for the smooth rotation's part
    double slipped = 0;
    for (const auto& period : m.slip_energies)
      for (const double e : period) slipped += e / double(m.slip_energies.size());
    if (i < 2) CHECK(slipped == Approx(m.dissipation()).epsilon(0.01));  // 99.9 %
    CHECK(slipped < m.dissipation());
  }
}

TEST_CASE("without slip_kinds nothing reruns and nothing is counted", "[ensemble][slip_kinds]") {
  const auto scene = io::parse_scene_text(
      "[model]\nrows = 2\n[drive]\ng = 1e-5\n[sweep]\nA = 9.0\n[initial]\nkinds = [\"AFM\"]\nnoise = 0.0\n"
      "[disorder]\nA = 1e-6\n[numerics]\nrtol = 1e-12\natol = 1e-15\n",
      "no-slip-kinds");
  const auto results = ensemble::run_sweep(scene, ensemble::plan_members(scene), {.threads = 1}).results;
  CHECK(results.front().regime == ensemble::Regime::cp);
  CHECK(std::isnan(results.front().slip_jumps));
  CHECK(results.front().slip_energies.empty());
}

TEST_CASE("just below A_* slips that look smooth at g = 1e-3 stay CP: the landscape still has jumps there",
          "[ensemble][slip_kinds]") {
  // J(8.6) = 6e-4 per row and period, far below the slips' part that scales with g: comparing g with g/10
  // counts every slip smooth (as in the demo scene with σ_A = 1e-6, A = 8.55 … 8.75), the label stays CP
  const auto scene = io::parse_scene_text(
      "[model]\nrows = 2\n[drive]\ng = 1e-3\n[sweep]\nA = [8.6, 9.0]\n[initial]\nkinds = [\"AFM\"]\n"
      "noise = 0.0\n[disorder]\nA = 1e-6\n[observables]\nslip_kinds = true\n[numerics]\nrtol = 1e-10\n"
      "atol = 1e-13\n",
      "below-a-star");
  const auto results = ensemble::run_sweep(scene, ensemble::plan_members(scene), {.threads = 2}).results;
  REQUIRE(results.size() == 2);
  CHECK(results[0].slip_smooth == 4);
  CHECK(results[0].regime == ensemble::Regime::cp);
  CHECK(results[1].slip_smooth == 4);
  CHECK(results[1].regime == ensemble::Regime::sa);
}
