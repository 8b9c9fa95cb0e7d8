// Sweeps (ensemble/sweep): results are bitwise identical for any thread count, with refill on
// or off, and on scalar or SIMD lanes; steady_tol retires settled members early; a failing
// member is isolated from the members sharing its lanes; without the period series only the last
// periods are kept, with the same summary; the stop flag ends a sweep early.
#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>

#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "support/same_results.hpp"

using namespace rotorsweep::ensemble;
using rotorsweep::testing::same_bits;

namespace {

/// A small friction curve with every observable; `extra` adds sections, `observables` keys.
Scene curve_scene(const std::string& extra = "", const std::string& observables = "") {
  const std::string model = extra.find("[model]") == std::string::npos ? "[model]\nrows = 8\n" : "";
  return rotorsweep::io::parse_scene_text(
      model +
          "[drive]\ng = [0.002]\n[sweep]\nA = { from = 0.5, to = 12.5, count = 13 }\n"
          "[initial]\nkinds = [\"AFM\", \"random\"]\nreplicas = 2\n[observables]\nestimators = true\nenergy "
          "= "
          "true\n" +
          observables + extra,
      "sweep-test.toml");
}

SweepOutcome sweep(const Scene& scene, int threads = 1) {
  return run_sweep(scene, plan_members(scene), {.threads = threads});
}

void require_identical(const std::vector<MemberResult>& a, const std::vector<MemberResult>& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    INFO("member " << i);
    CHECK(a[i].index == i);
    CHECK(same_bits(a[i].dissipation(), b[i].dissipation()));
    CHECK(same_bits(a[i].mean(rotorsweep::ensemble::Channel::work),
                    b[i].mean(rotorsweep::ensemble::Channel::work)));
    CHECK(same_bits(a[i].mean(rotorsweep::ensemble::Channel::stokes),
                    b[i].mean(rotorsweep::ensemble::Channel::stokes)));
    CHECK(same_bits(a[i].alignment_min(), b[i].alignment_min()));
    CHECK(same_bits(a[i].alignment_mean(), b[i].alignment_mean()));
    CHECK(same_bits(a[i].mean(rotorsweep::ensemble::Channel::energy_mean),
                    b[i].mean(rotorsweep::ensemble::Channel::energy_mean)));
    CHECK(a[i].slips_per_period() == b[i].slips_per_period());
    CHECK(a[i].regime == b[i].regime);
    CHECK(a[i].status == b[i].status);
    CHECK(a[i].steps_accepted == b[i].steps_accepted);
    CHECK(a[i].steps_rejected == b[i].steps_rejected);
    CHECK(a[i].theta_final == b[i].theta_final);
  }
}

}  // namespace

TEST_CASE("results do not depend on the thread count", "[ensemble][sweep]") {
  const Scene scene = curve_scene();
  const auto one = sweep(scene, 1), two = sweep(scene, 2);
  CHECK(two.statistics.threads == 2);
  require_identical(one.results, two.results);
}

TEST_CASE("results do not depend on refilling lanes", "[ensemble][sweep]") {
  const auto refilled = sweep(curve_scene());
  const auto blockwise = sweep(curve_scene("[schedule]\nrefill = false\n"));
  require_identical(refilled.results, blockwise.results);
  // refilling keeps the lanes busier than waiting for a whole block to finish
  CHECK(refilled.statistics.occupancy() > blockwise.statistics.occupancy());
}

TEST_CASE("scalar and SIMD lanes give the same bits", "[ensemble][sweep]") {
  const auto simd = sweep(curve_scene());
  const auto scalar = sweep(curve_scene("[numerics]\nlanes = \"scalar\"\n"));
  CHECK(scalar.statistics.lane_width == 1);
  CHECK(scalar.statistics.occupancy() == 1.0);
  require_identical(simd.results, scalar.results);
}

TEST_CASE("every member runs its schedule and reports sane observables", "[ensemble][sweep]") {
  const Scene scene = curve_scene("", "period_series = true\n");
  const auto outcome = sweep(scene);
  for (const auto& r : outcome.results) {
    INFO("member " << r.index);
    CHECK(r.status == rotorsweep::kernels::LaneStatus::ok);
    CHECK(r.periods_run == 4);
    REQUIRE(r.periods.size() == 4);
    CHECK(r.dissipation() ==
          Approx((r.periods[2].dissipation() + r.periods[3].dissipation()) / 2).epsilon(1e-14));
    CHECK(r.dissipation() > 0);
    CHECK(r.alignment_min() <= r.alignment_mean() + 1e-9);
    CHECK(r.alignment_mean() <= r.alignment_max() + 1e-9);
    CHECK(r.alignment_min() >= 0);
    CHECK(r.alignment_max() <= 1);
    for (double theta : r.theta_final) CHECK((theta >= 0 && theta < 2 * M_PI));
  }
}

TEST_CASE("steady_tol retires members once successive periods agree", "[ensemble][sweep]") {
  const Scene scene =
      curve_scene("[schedule]\nrelax_periods = 1\naverage_periods = 1\nsteady_tol = 1e-4\nmax_periods = 12\n",
                  "period_series = true\n");
  const auto outcome = sweep(scene);
  int early = 0;
  for (const auto& r : outcome.results) {
    INFO("member " << r.index);
    CHECK(r.periods_run >= 2);
    CHECK(r.periods_run <= 12);
    if (r.settled) {
      const double now = r.periods[r.periods.size() - 1].dissipation();
      const double before = r.periods[r.periods.size() - 2].dissipation();
      CHECK(std::fabs(now - before) <= 1e-4 * std::max(std::fabs(now), std::fabs(before)));
      early += r.periods_run < 12;
    } else {
      CHECK(r.periods_run == 12);
      CHECK(r.regime == Regime::unsettled);
    }
  }
  CHECK(early > int(outcome.results.size()) / 2);
}

TEST_CASE("without period_series a member keeps only its last periods, with the same summary",
          "[ensemble][sweep]") {
  // 40 + 3 periods and steady_tol retirements: the history is cut back several times
  const std::string schedule[] = {
      "[schedule]\nrelax_periods = 40\naverage_periods = 3\n",
      "[schedule]\nrelax_periods = 2\naverage_periods = 2\nsteady_tol = 1e-9\nmax_periods = 30\n"};
  for (const auto& text : schedule) {
    INFO(text);
    const auto with_series = sweep(curve_scene(text, "period_series = true\n"));
    const auto without = sweep(curve_scene(text));
    require_identical(with_series.results, without.results);
    for (std::size_t i = 0; i < without.results.size(); ++i) {
      CHECK(without.results[i].periods.empty());
      CHECK(without.results[i].periods_run == with_series.results[i].periods_run);
      CHECK(int(with_series.results[i].periods.size()) == with_series.results[i].periods_run);
      CHECK(same_bits(without.results[i].dissipation_std(), with_series.results[i].dissipation_std()));
      CHECK(without.results[i].settled == with_series.results[i].settled);
    }
  }
}

TEST_CASE("a failing member is isolated from its lane neighbours", "[ensemble][sweep]") {
  const auto free = sweep(curve_scene());
  std::vector<double> steps;
  for (const auto& r : free.results) steps.push_back(r.steps_accepted + r.steps_rejected);
  std::vector<double> sorted = steps;
  std::sort(sorted.begin(), sorted.end());
  const double budget = sorted[sorted.size() / 2];
  const auto limited = sweep(curve_scene("[numerics]\nmax_steps = " + std::to_string(long(budget)) + "\n"));
  int failed = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const auto& r = limited.results[i];
    INFO("member " << i);
    if (steps[i] >= budget) {
      ++failed;
      CHECK(r.status == rotorsweep::kernels::LaneStatus::step_budget);
      CHECK(std::isnan(r.dissipation()));
      CHECK(r.regime == Regime::unsettled);
    } else {
      CHECK(r.status == rotorsweep::kernels::LaneStatus::ok);
      CHECK(same_bits(r.dissipation(), free.results[i].dissipation()));
    }
  }
  CHECK(failed >= int(steps.size()) / 2);
}

TEST_CASE("a subset of the plan gives the same bits as the whole plan", "[ensemble][sweep]") {
  const Scene scene = curve_scene("[model]\nrows = [2, 8]\n[numerics]\nrtol = [1e-5, 1e-8]\n");
  const auto members = plan_members(scene);
  REQUIRE(members.size() == 4 * 52);
  const auto whole = run_sweep(scene, members, {.threads = 2});
  std::vector<Member> every_third;
  std::vector<MemberResult> expected;
  for (std::size_t i = 0; i < members.size(); i += 3) {
    every_third.push_back(members[i]);
    expected.push_back(whole.results[i]);
  }
  const auto part = run_sweep(scene, every_third, {.threads = 1});
  REQUIRE(part.results.size() == every_third.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    INFO("member " << every_third[i].index);
    CHECK(part.results[i].index == every_third[i].index);
    CHECK(part.results[i].theta_final.size() == every_third[i].rows);
    CHECK(same_bits(part.results[i].dissipation(), expected[i].dissipation()));
    CHECK(part.results[i].theta_final == expected[i].theta_final);
  }
}

TEST_CASE("noise and offset lists give the same members as separate scenes, bit for bit",
          "[ensemble][sweep]") {
  const std::string base =
      "[model]\nrows = 8\n[drive]\ng = [0.002]\n[sweep]\nA = [3.0, 6.0, 9.0]\n[observables]\nestimators = "
      "true\n"
      "[initial]\nkinds = [\"FM\", \"AFM\"]\nreplicas = 2\n";
  const auto together = sweep(
      rotorsweep::io::parse_scene_text(base + "noise = [1e-4, 0.3]\noffset = [0.0, 1.5]\n", "lists.toml"), 2);
  const auto plan = plan_members(
      rotorsweep::io::parse_scene_text(base + "noise = [1e-4, 0.3]\noffset = [0.0, 1.5]\n", "x"));
  for (double noise : {1e-4, 0.3})
    for (double offset : {0.0, 1.5}) {
      char extra[96];
      std::snprintf(extra, sizeof extra, "noise = %.17g\noffset = %.17g\n", noise, offset);
      const auto alone = sweep(rotorsweep::io::parse_scene_text(base + extra, "one.toml"));
      std::vector<MemberResult> subset;
      for (std::size_t i = 0; i < plan.size(); ++i)
        if (plan[i].noise == noise && plan[i].offset == offset) subset.push_back(together.results[i]);
      INFO("noise " << noise << ", offset " << offset);
      REQUIRE(subset.size() == alone.results.size());
      for (std::size_t i = 0; i < subset.size(); ++i) {
        CHECK(same_bits(subset[i].dissipation(), alone.results[i].dissipation()));
        CHECK(subset[i].theta_final == alone.results[i].theta_final);
        CHECK(subset[i].steps_accepted == alone.results[i].steps_accepted);
      }
    }
}

TEST_CASE("the stop flag ends a sweep early and says so", "[ensemble][sweep]") {
  const Scene scene = curve_scene("[model]\nrows = [2, 8]\n");
  const auto members = plan_members(scene);
  std::atomic<bool> stop{false};
  const auto raised = [&] { return stop.load(); };
  CHECK_FALSE(run_sweep(scene, members, {.threads = 2, .stop = raised}).interrupted);

  stop = true;
  const auto before = run_sweep(scene, members, {.threads = 2, .stop = raised});
  CHECK(before.interrupted);
  CHECK(before.results.size() == members.size());
  CHECK(before.statistics.lane_steps_total == 0);  // not one step was taken

  // raised from the progress callback: the members still to come are skipped
  stop = false;
  std::size_t seen = 0;
  const auto during = run_sweep(scene, members,
                                {.threads = 1,
                                 .progress =
                                     [&](std::size_t done) {
                                       seen = done;
                                       if (done >= 5) stop = true;
                                     },
                                 .stop = raised});
  CHECK(during.interrupted);
  CHECK(seen < members.size());

  // raised after the last member: nothing was left out, so the sweep is whole
  stop = false;
  const auto after = run_sweep(scene, members,
                               {.threads = 2,
                                .progress =
                                    [&](std::size_t done) {
                                      if (done == members.size()) stop = true;
                                    },
                                .stop = raised});
  CHECK_FALSE(after.interrupted);
  CHECK(std::count(after.finished.begin(), after.finished.end(), 1) == std::ptrdiff_t(members.size()));
}

TEST_CASE("progress moves within members: every closed period is counted and reported", "[ensemble][sweep]") {
  // two long members: without the period count the progress would stay at 0 of 2 until the end
  const auto scene = rotorsweep::io::parse_scene_text(
      "[model]\nrows = 20\n[drive]\ng = 0.001\n[sweep]\nA = [4, 6]\n[schedule]\nrelax_periods = 3\n"
      "average_periods = 3\n",
      "progress.toml");
  const auto members = plan_members(scene);
  const MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }};
  std::atomic<std::size_t> periods{0};
  std::vector<std::size_t> reports;
  std::vector<std::size_t> periods_seen;
  const RunControl control{.threads = 1,
                           .progress =
                               [&](std::size_t done) {
                                 reports.push_back(done);
                                 periods_seen.push_back(periods.load());
                               },
                           .stops = &periods};
  // a member whose averaged periods slip runs them again (ensemble/rows/shadow_run.hpp), and so does
  // its symmetry probe (ensemble/rows/symmetry_probe.hpp)
  std::size_t reruns = 0;
  run_members(scene, source, control, [&](MemberResult&& r) {
    reruns += std::isfinite(r.dissipation_shadow) ? 1 : 0;
    reruns += std::isfinite(r.dissipation_probe) ? 1 : 0;
  });
  CHECK(periods.load() == 12 + 3 * reruns);  // 2 members × (3 + 3) periods, and 3 per rerun
  CHECK(reports.size() >= 12);
  REQUIRE(!reports.empty());
  CHECK(reports.front() == 0);  // reported while both members were still running
  CHECK(periods_seen.front() >= 1);
  CHECK(reports.back() == 2);
}
