// The slider scan (ensemble/slider/slider_sweep.cpp, slider_scene.cpp; docs/model.md §9): units, the schedule
// of samples and periods, the energy balance per period, convergence of the mean friction with the tolerance
// and with the substrate table, thread-count invariance, and the scene keys' errors.
#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "ensemble/slider/slider_sweep.hpp"
#include "io/slider_scene_parser.hpp"

using namespace rotorsweep::ensemble;
using Catch::Detail::Approx;

namespace {

/// A small slider (3 × 2 over 11 × 11) with the experiment's constants, two separations × two replicas,
/// 1/4 period of rest and two periods of sliding; `extra` replaces or adds keys (TOML sections).
std::string small_scene(const std::string& numerics = "rtol = 1e-7\natol = 1e-7\n",
                        const std::string& substrate = "") {
  return "[slider]\ncolumns = 3\nrows = 2\n[substrate]\ncolumns = 11\nrows = 11\n" + substrate +
         "[drive]\nrest = 0.5\nend = 4.5\n[sweep]\nseparation = [7e-3, 9e-3]\n"
         "[initial]\nreplicas = 2\n[observables]\nsamples_per_period = 20\n[numerics]\n" +
         numerics;
}

SliderResult scan(const std::string& text, int threads = 1) {
  return run_slider_scan(rotorsweep::io::parse_slider_scene_text(text, "slider-test"), {.threads = threads});
}

}  // namespace

TEST_CASE("slider units: the experiment's energy and time scales", "[ensemble][slider]") {
  const SliderUnits units(SliderScene{});
  CHECK(units.energy == Approx(1e-7 * 4.57e-2 * 4.57e-2 / std::pow(16e-3, 3)));  // μ0 m²/(4π a³) = 5.10e-5 J
  CHECK(units.time == Approx(16e-3 / (2 * 3.141592653589793 * 8e-3)));           // a/(2π v) = 0.318 s
  CHECK(units.force == Approx(units.energy / 16e-3));
  const auto lattice = substrate_lattice(SliderScene{}, {7, 7}, 8e-3);
  CHECK(lattice.x_offset == -14.0);  // substrate column 17 (the middle of 35) under slider column 3
  CHECK(lattice.depth == 0.5);
}

TEST_CASE("slider friction's error: its shadow run's difference bounds the deviation from a tight run",
          "[ensemble][slider][global_error]") {
  const auto loose = scan(small_scene("rtol = 1e-6\natol = 1e-6\n"), 2);
  const auto tight = scan(small_scene("rtol = 1e-10\natol = 1e-10\nglobal_error = \"local\"\n"), 2);
  double largest = 0;
  for (std::size_t k = 0; k < loose.members.size(); ++k) {
    const auto& m = loose.members[k];
    INFO("member " << k << " friction " << m.friction << " error " << m.friction_error);
    REQUIRE(m.status == "ok");
    CHECK(m.friction_error > 0);
    CHECK(m.friction_error < 1e-3 * std::fabs(m.friction));
    CHECK(m.friction_error == Approx(2 * std::fabs(m.friction - m.friction_shadow) / 0.9));
    const double deviation = std::fabs(m.friction - tight.members[k].friction);
    CHECK(deviation <= m.friction_error);
    largest = std::max(largest, deviation / m.friction_error);
    CHECK(std::isnan(tight.members[k].friction_error));  // "local": no shadow, no error
  }
  CHECK(largest > 0.05);  // the estimate is an error's size, not a far bound
}

TEST_CASE("slider friction averages the periods after drive.relax_periods", "[ensemble][slider]") {
  const auto scene_with = [](const std::string& relax) {
    return "[slider]\ncolumns = 2\nrows = 2\n[substrate]\ncolumns = 9\nrows = 9\n[drive]\nrest = 0.5\nperiods = 3\n" +
           relax + "[sweep]\nseparation = 8e-3\n[observables]\nsamples_per_period = 20\n";
  };
  for (const auto& [relax, first] : {std::pair{std::string(), 1}, std::pair{std::string("relax_periods = 0\n"), 0},
                                     std::pair{std::string("relax_periods = 2\n"), 2}}) {
    INFO(relax);
    const auto m = scan(scene_with(relax)).members.front();
    REQUIRE(m.period_friction.size() == 3);
    double sum = 0;
    for (std::size_t p = std::size_t(first); p < 3; ++p) sum += m.period_friction[p];
    CHECK(m.friction == Approx(sum / double(3 - first)).epsilon(1e-12));
  }
  // one period slid: it is averaged by default, and a relax_periods that leaves none is refused
  const auto one = scan(scene_with("").replace(scene_with("").find("periods = 3"), 11, "periods = 1"));
  CHECK(one.members.front().friction == Approx(one.members.front().period_friction[0]).epsilon(1e-12));
  CHECK_THROWS_WITH(rotorsweep::io::parse_slider_scene_text(scene_with("relax_periods = 3\n"), "s"),
                    Catch::Contains("drive.relax_periods") && Catch::Contains("fewer than the 3 the run slides"));
}

TEST_CASE("slider scan: samples, periods, energy balance and friction", "[ensemble][slider]") {
  const auto result = scan(small_scene());
  REQUIRE(result.members.size() == 4);
  CHECK(result.timeline.periods == 2);
  REQUIRE(result.timeline.sample_times.size() == 1);
  CHECK(result.timeline.period.front() == Approx(2.0));
  const auto& times = result.timeline.sample_times.front();
  CHECK(times.size() == result.timeline.samples);
  CHECK(times.front() == 0.0);
  CHECK(times.back() == Approx(4.5));
  for (const auto& m : result.members) {
    CHECK(m.status == "ok");
    REQUIRE(m.period_friction.size() == 2);
    CHECK(m.friction == Approx(m.period_friction[1]));  // the first period is the transient after the rest
    for (std::size_t p = 0; p < 2; ++p) {
      CHECK(std::fabs(m.period_balance[p]) < 1e-5);
      CHECK(m.period_work[p] == Approx(m.period_friction[p] * 16e-3).epsilon(1e-9));  // W = F̄ a
      CHECK(m.period_dissipation[p] > 0.0);
    }
    CHECK(m.friction_series.size() == result.timeline.samples);
  }
  // replicas start from different angles
  CHECK(result.members[0].friction_series.back() != result.members[1].friction_series.back());
}

TEST_CASE("slider scan: the mean friction converges with the tolerance and the table's nodes",
          "[ensemble][slider]") {
  const auto reference = scan(small_scene("rtol = 1e-10\natol = 1e-10\n", "nodes_per_depth = 32\n"));
  const auto loose = scan(small_scene("rtol = 1e-6\natol = 1e-6\n"));
  const auto coarse_table = scan(small_scene("rtol = 1e-10\natol = 1e-10\n", "nodes_per_depth = 8\n"));
  // relative to the scan's force scale: a member's mean force can come out near zero (2e-4 of the
  // others' for one of these starts), where a relative bound would ask for more than the tolerance
  double scale = 0;
  for (const auto& m : reference.members) scale = std::max(scale, std::fabs(m.friction));
  for (std::size_t k = 0; k < reference.members.size(); ++k) {
    const double f = reference.members[k].friction;
    INFO("member " << k << " friction " << f << ", scale " << scale);
    CHECK(std::fabs(loose.members[k].friction - f) < 1e-4 * scale);
    CHECK(std::fabs(coarse_table.members[k].friction - f) < 1e-4 * scale);
  }
}

TEST_CASE("slider scan: a member that runs out of steps is flagged and its values are NaN",
          "[ensemble][slider]") {
  const auto result = scan(small_scene("rtol = 1e-7\natol = 1e-7\nmax_steps = 50\n"));
  for (const auto& m : result.members) {
    CHECK(m.status == "step_budget");
    CHECK(std::isnan(m.friction));
    CHECK(std::isnan(m.order_x));
    CHECK(std::isnan(m.period_balance.front()));
  }
}

TEST_CASE("slider scan: a member that fails frees its lane for the next and leaves the others' bits alone",
          "[ensemble][slider]") {
  // 4 x 4 at rtol 1e-8: the closest separations run out of 1500 steps, the farther ones finish
  const auto scene_with = [](const std::string& separations) {
    return "[slider]\ncolumns = 4\nrows = 4\n[drive]\nend = 4.7\n[sweep]\nseparation = " + separations +
           "\n[initial]\nreplicas = 3\n[observables]\nsamples_per_period = 30\n"
           "[numerics]\nstepper = \"rodas5p\"\nrtol = 1e-8\natol = 1e-8\nmax_steps = 1500\n";
  };
  const auto mixed = scan(scene_with("[4e-3, 6e-3, 9e-3, 12e-3, 14e-3]"), 2);
  const auto finishing = scan(scene_with("[12e-3, 14e-3]"), 1);
  std::size_t failed = 0;
  for (const auto& m : mixed.members) {
    if (m.status == "ok") continue;
    ++failed;
    CHECK(m.status == "step_budget");
    CHECK(std::isnan(m.friction));
    // the samples after the failure hold its frozen state
    CHECK(m.friction_series.back() == m.friction_series[m.friction_series.size() - 2]);
    CHECK(m.energy_series.back() == m.energy_series[m.energy_series.size() - 2]);
  }
  CHECK(failed >= 3);
  for (std::size_t k = 0; k < finishing.members.size(); ++k) {
    const auto& alone = finishing.members[k];
    const auto& among = mixed.members[mixed.members.size() - finishing.members.size() + k];
    REQUIRE(alone.status == "ok");
    CHECK(among.separation == alone.separation);
    CHECK(among.friction == alone.friction);
    CHECK(among.friction_series == alone.friction_series);
    CHECK(among.period_balance == alone.period_balance);
    CHECK(among.steps_accepted == alone.steps_accepted);
  }
}

TEST_CASE("slider scan: sizes are a sweep axis", "[ensemble][slider]") {
  const std::string two_sizes =
      "[slider]\ncolumns = [2, 3]\nrows = [2, 2]\n[substrate]\ncolumns = 11\nrows = 11\n"
      "[drive]\nrest = 0.5\nend = 2.5\n[sweep]\nseparation = [8e-3]\n[initial]\nreplicas = 2\n";
  const auto both = scan(two_sizes);
  REQUIRE(both.members.size() == 4);
  CHECK(both.members[0].size == SliderSize{2, 2});
  CHECK(both.members[3].size == SliderSize{3, 2});
  CHECK(both.members[3].index.replica == 1);
  for (const auto& m : both.members) CHECK(m.status == "ok");
  CHECK(both.members[0].friction != both.members[2].friction);
  const auto threaded = scan(two_sizes, 2);  // blocks of one size each, on two threads: the same bits
  for (std::size_t k = 0; k < 4; ++k) CHECK(threaded.members[k].friction == both.members[k].friction);
  CHECK(both.members[0].friction_series.size() == both.members[2].friction_series.size());
}

TEST_CASE("slider scan: speed and damping are sweep axes; each member has the bits of its own scan",
          "[ensemble][slider]") {
  const auto scene_with = [](const std::string& speeds, const std::string& dampings) {
    return "[slider]\ncolumns = 3\nrows = 2\ndamping = " + dampings +
           "\n[substrate]\ncolumns = 11\nrows = 11\n[drive]\nrest = 0.5\nperiods = 2\nspeed = " + speeds +
           "\n[sweep]\nseparation = [7e-3, 9e-3]\n[observables]\nsamples_per_period = 20\n"
           "[numerics]\nrtol = 1e-7\natol = 1e-7\n";
  };
  const auto both = scan(scene_with("[4e-3, 16e-3]", "[2.5e-6, 1e-5]"), 2);
  REQUIRE(both.members.size() == 8);
  // plan order: speed, then damping, then separation
  CHECK(both.members[5].index.speed == 1);
  CHECK(both.members[5].index.damping == 0);
  CHECK(both.members[5].index.separation == 1);
  CHECK(both.members[5].speed == 16e-3);
  CHECK(both.members[5].damping == 2.5e-6);
  // both speeds slide two periods (41 samples); the 0.5 s of rest take 10 samples at 16 mm/s (a period
  // of 1 s) but 3 at 4 mm/s (a period of 4 s: t = 0, 0.1, 0.3 s), so the slower speed's first 7 are NaN
  const auto& timeline = both.timeline;
  CHECK(timeline.periods == 2);
  REQUIRE(timeline.period.size() == 2);
  CHECK(timeline.period[0] == Approx(4.0));
  CHECK(timeline.period[1] == Approx(1.0));
  CHECK(timeline.samples == 10 + 41);
  CHECK(std::isnan(timeline.sample_times[0][6]));
  CHECK(timeline.sample_times[0][7] == 0.0);
  CHECK(timeline.sample_times[0][8] == Approx(0.1));
  CHECK(timeline.sample_times[0].back() == Approx(8.5));
  CHECK(timeline.sample_times[1][0] == 0.0);
  CHECK(timeline.sample_times[1].back() == Approx(2.5));
  for (std::size_t v = 0; v < 2; ++v)
    for (std::size_t d = 0; d < 2; ++d) {
      const char* speed[] = {"4e-3", "16e-3"};
      const char* damping[] = {"2.5e-6", "1e-5"};
      INFO("speed " << speed[v] << ", damping " << damping[d]);
      const auto alone = scan(scene_with(speed[v], damping[d]));
      for (std::size_t h = 0; h < 2; ++h) {
        const auto& m = both.members[(v * 2 + d) * 2 + h];
        const auto& own = alone.members[h];
        CHECK(m.status == "ok");
        CHECK(m.friction == own.friction);
        CHECK(m.period_balance == own.period_balance);
        for (const double balance : m.period_balance) CHECK(std::fabs(balance) < 1e-5);
        // its own samples at the end, NaN before them
        const std::size_t pad = timeline.samples - own.friction_series.size();
        REQUIRE(m.friction_series.size() == timeline.samples);
        CHECK(std::equal(own.friction_series.begin(), own.friction_series.end(),
                         m.friction_series.begin() + long(pad)));
        CHECK(std::all_of(m.friction_series.begin(), m.friction_series.begin() + long(pad),
                          [](double x) { return std::isnan(x); }));
        CHECK(alone.timeline.sample_times.front().size() == own.friction_series.size());
      }
    }
  // the physics moves with both axes
  CHECK(both.members[0].friction != both.members[4].friction);
  CHECK(both.members[0].friction != both.members[2].friction);
}

TEST_CASE("slider scan: a member's result does not depend on the other separations or replicas",
          "[ensemble][slider]") {
  // (separation, replica) → friction and series, from scenes with other plans around them
  const auto scene_with = [](const std::string& separations, int replicas) {
    return "[slider]\ncolumns = 3\nrows = 2\n[substrate]\ncolumns = 11\nrows = 11\n[drive]\nrest = 0.5\n"
           "end = 4.5\n[sweep]\nseparation = " +
           separations + "\n[initial]\nreplicas = " + std::to_string(replicas) +
           "\n[observables]\nsamples_per_period = 20\n[numerics]\nrtol = 1e-7\natol = 1e-7\n";
  };
  const auto find = [](const SliderResult& r, double h, std::size_t replica) {
    for (const auto& m : r.members)
      if (m.separation == h && m.index.replica == replica) return m;
    FAIL("no member at h = " << h << ", replica " << replica);
    return r.members.front();
  };
  const auto alone = scan(scene_with("[9e-3, 10e-3]", 1));
  const auto more = scan(scene_with("[8e-3, 9e-3, 10e-3]", 2), 2);
  const auto single = scan(scene_with("[9e-3]", 1));
  for (double h : {9e-3, 10e-3}) {
    INFO("h = " << h);
    CHECK(find(more, h, 0).friction == find(alone, h, 0).friction);
    CHECK(find(more, h, 0).friction_series == find(alone, h, 0).friction_series);
  }
  CHECK(single.members[0].friction == find(alone, 9e-3, 0).friction);
  CHECK(single.members[0].friction_series == find(alone, 9e-3, 0).friction_series);
  CHECK(find(more, 9e-3, 1).friction != find(more, 9e-3, 0).friction);  // replicas do differ
}

TEST_CASE("slider scan: a slider of one row has no odd rows, and their means are NaN", "[ensemble][slider]") {
  const auto result = scan(
      "[slider]\ncolumns = 3\nrows = 1\n[substrate]\ncolumns = 9\nrows = 9\n[drive]\nrest = 0.5\nend = 2.5\n"
      "[sweep]\nseparation = [8e-3]\n[observables]\nsublattices = true\n");
  const auto& m = result.members.front();
  REQUIRE(m.status == "ok");
  for (const auto* odd : {&m.moment_axis_odd_series, &m.moment_z_odd_series, &m.torque_odd_series})
    CHECK(std::all_of(odd->begin(), odd->end(), [](double x) { return std::isnan(x); }));
  CHECK(std::all_of(m.torque_even_series.begin(), m.torque_even_series.end(),
                    [](double x) { return std::isfinite(x); }));
}

TEST_CASE("slider scan: one thread or two give the same bits", "[ensemble][slider]") {
  const auto one = scan(small_scene(), 1), two = scan(small_scene(), 2);
  for (std::size_t k = 0; k < one.members.size(); ++k) {
    CHECK(one.members[k].friction == two.members[k].friction);
    CHECK(one.members[k].friction_series == two.members[k].friction_series);
  }
}

TEST_CASE("slider scan: the run API's claim, progress, stops and stop", "[ensemble][slider]") {
  const auto scene = rotorsweep::io::parse_slider_scene_text(small_scene(), "slider-test");
  const auto one = run_slider_scan(scene, {.threads = 1});
  std::vector<std::size_t> all(scene.member_count());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;

  // two processes of mpirun as two runs on two threads, claiming from one counter: each member once, its bits
  std::atomic<std::size_t> counter{0};
  std::atomic<std::size_t> samples{0};
  std::vector<SliderMember> members(all.size());
  std::vector<int> runs(all.size(), 0);
  std::mutex lock;
  const RunControl shared{.threads = 1, .stops = &samples, .claim = [&](std::size_t begin, std::size_t) {
                            return begin + counter++;
                          }};
  const auto finished = [&](std::vector<SliderMember>&& block) {
    const std::lock_guard guard(lock);
    for (auto& m : block) {
      ++runs[m.plan_index];
      members[m.plan_index] = std::move(m);
    }
  };
  std::thread other([&] { run_slider_members(scene, all, shared, finished); });
  run_slider_members(scene, all, shared, finished);
  other.join();
  std::size_t taken = 0;
  for (std::size_t k = 0; k < all.size(); ++k) {
    CHECK(runs[k] == 1);
    CHECK(members[k].friction_series == one.members[k].friction_series);
    taken += std::size_t(std::count_if(members[k].friction_series.begin(), members[k].friction_series.end(),
                                       [](double x) { return !std::isnan(x); }));
  }
  REQUIRE(scene.shadow_runs);
  CHECK(samples == 2 * taken);  // a stop per sample, and per sample of each member's shadow run

  // progress after each member; a stop raised after the first leaves the others out
  std::size_t last = 0;
  bool stop = false;
  const auto stopped = run_slider_members(scene, all,
                                          {.threads = 1,
                                           .progress =
                                               [&](std::size_t done) {
                                                 last = done;
                                                 stop = true;
                                               },
                                           .stop = [&] { return stop; }},
                                          [](std::vector<SliderMember>&&) {});
  CHECK(stopped.interrupted);
  CHECK(last == 1);
  const auto whole =
      run_slider_scan(scene, {.threads = 2, .progress = [&](std::size_t done) { last = done; }});
  CHECK_FALSE(whole.outcome.interrupted);
  CHECK(last == all.size());
  CHECK(whole.outcome.statistics.lane_steps_busy > 0);
}

TEST_CASE("slider scan: a given start, row by row from the smallest y, gives the drawn start's bits",
          "[ensemble][slider]") {
  // the angles the default start draws for replica 0, given back one by one: the same member
  const std::string base =
      "[slider]\ncolumns = 3\nrows = 2\n[substrate]\ncolumns = 11\nrows = 11\n[drive]\nrest = 0.5\n"
      "end = 4.5\n[sweep]\nseparation = [7e-3, 9e-3]\n[observables]\nsamples_per_period = 20\n"
      "[numerics]\nrtol = 1e-7\natol = 1e-7\n";
  const auto drawn_scene = rotorsweep::io::parse_slider_scene_text(base + "[initial]\nseed = 5\n", "drawn");
  const std::vector<double> start = slider_start(drawn_scene, SliderMemberIndex{});
  REQUIRE(start.size() == 6);
  CHECK(start[0] == Approx(0).margin(0.14));  // row 0 (smallest y) near 0, row 1 near π
  CHECK(start[3] == Approx(3.14159).margin(0.14));
  std::string list;
  for (const double a : start) {
    char number[40];
    std::snprintf(number, sizeof number, "%.17g", a);
    list += (list.empty() ? "" : ", ") + std::string(number);
  }
  const auto drawn = scan(base + "[initial]\nseed = 5\n");
  const auto given = scan(base + "[initial]\nangles = [" + list + "]\n");
  REQUIRE(given.members.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(given.members[k].friction == drawn.members[k].friction);
    CHECK(given.members[k].friction_series == drawn.members[k].friction_series);
  }
  // another start gives another run
  const auto flipped =
      scan(base + "[initial]\nkind = \"given\"\nangles = [3.1, 3.2, 3.0, 0.1, -0.05, 0.0]\n");
  CHECK(flipped.members[0].friction_series != drawn.members[0].friction_series);
}

TEST_CASE("slider scan: a shifted, turned slider over turned moments balances its energy, and φ = π flips B",
          "[ensemble][slider]") {
  const std::string base =
      "[substrate]\ncolumns = 11\nrows = 11\n[drive]\nrest = 0.5\nend = 4.5\n[sweep]\nseparation = [7e-3, "
      "9e-3]\n[observables]\nsamples_per_period = 20\n[numerics]\nrtol = 1e-7\natol = 1e-7\n";
  const std::string start = "[initial]\nkind = \"given\"\nangles = [0.1, -0.05, 0.02, 3.1, 3.2, 3.15]\n";
  const std::string flipped_start =
      "[initial]\nkind = \"given\"\nangles = [3.2415926535897931, 3.0915926535897931, 3.1615926535897931, "
      "6.2415926535897931, 6.3415926535897931, 6.2915926535897931]\n";
  const std::string grid = "[slider]\ncolumns = 3\nrows = 2\n";
  const auto plain = scan(grid + start + base);
  const std::string placed = "[slider]\ncolumns = 3\nrows = 2\ntilt = 0.3\nshift_x = 4e-3\nshift_y = -3e-3\n";
  for (const std::string& variant : {grid + "tilt = 0.3\n", grid + "shift_x = 4e-3\nshift_y = -3e-3\n",
                                     placed + "[substrate]\nangle = 0.4\n"}) {
    INFO(variant);
    const std::string text =
        variant.find("[substrate]") != std::string::npos
            ? variant + "columns = 11\nrows = 11\n" + start + base.substr(base.find("[drive]"))
            : variant + start + base;
    const auto moved = scan(text);
    for (std::size_t k = 0; k < 2; ++k) {
      CHECK(moved.members[k].status == "ok");
      for (const double balance : moved.members[k].period_balance) CHECK(std::fabs(balance) < 1e-5);
      CHECK(moved.members[k].friction != Approx(plain.members[k].friction).epsilon(1e-6));
    }
  }
  // moments turned by π reverse the substrate's field: every angle + π gives the same run
  const auto reversed = scan(placed + "[substrate]\ncolumns = 11\nrows = 11\nangle = 3.141592653589793\n" +
                             flipped_start + base.substr(base.find("[drive]")));
  const auto forward = scan(placed + start + base);
  for (std::size_t k = 0; k < 2; ++k)
    CHECK(reversed.members[k].friction == Approx(forward.members[k].friction).epsilon(1e-6));
}

TEST_CASE("slider scenes: bad keys are named with what they must be", "[ensemble][slider][scene]") {
  using rotorsweep::io::parse_slider_scene_text;
  using rotorsweep::io::SceneError;
  const auto message = [](const std::string& text) {
    try {
      parse_slider_scene_text(text, "bad");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(message("[slider]\ncolums = 3\n"),
             Catch::Contains("slider.colums") && Catch::Contains("columns"));
  CHECK_THAT(message("[slider]\ndynamics = \"fast\"\n"), Catch::Contains("inertial, overdamped"));
  CHECK_THAT(message("[drive]\nrest = 2.0\nend = 1.0\n"), Catch::Contains("drive.end"));
  CHECK_THAT(message("[drive]\nrest = 0.5\nend = 2.0\n"), Catch::Contains("at least one substrate period"));
  CHECK_THAT(message("[sweep]\nseparation = [0.1e-3]\n"), Catch::Contains("sweep.separation"));
  CHECK_THAT(message("[substrate]\nnodes_per_depth = 1\n"), Catch::Contains("from 2 to 1000"));
  CHECK_THAT(message("[slider]\ncolumns = [3, 5]\nrows = [2, 2, 2]\n"), Catch::Contains("paired"));
  CHECK_THAT(message("[slider]\ncolumns = [3, 3]\nrows = 2\n"), Catch::Contains("twice"));
  CHECK_THAT(message("[slider]\ncolumns = 1\nrows = 1\n"), Catch::Contains("at least 2 rotors"));
  CHECK_THAT(
      message("[slider]\ncolumns = [3, 4]\n[sweep]\nseparation = [8e-3]\n[observables]\nangles = true\n"),
      Catch::Contains("observables.angles"));
  const std::string sep = "[sweep]\nseparation = [8e-3]\n";
  CHECK_THAT(
      message(sep + "[slider]\ncolumns = 3\nrows = 2\n[initial]\nangles = [0, 1, 2, 3, 4]\n"),
      Catch::Contains("initial.angles") && Catch::Contains("= 6 angles") && Catch::Contains("(got 5)"));
  CHECK_THAT(message(sep + "[initial]\nkind = \"given\"\n"),
             Catch::Contains("initial.angles") && Catch::Contains("49 angles"));
  CHECK_THAT(
      message(sep + "[slider]\ncolumns = 2\nrows = 1\n[initial]\nkind = \"random\"\nangles = [0, 1]\n"),
      Catch::Contains("initial.angles") && Catch::Contains("kind = \"given\""));
  CHECK_THAT(message(sep + "[slider]\ncolumns = 2\nrows = 1\n[initial]\nangles = [0, 1]\nreplicas = 2\n"),
             Catch::Contains("initial.replicas"));
  CHECK_THAT(message(sep + "[slider]\ncolumns = [2, 3]\nrows = 1\n[initial]\nangles = [0, 1]\n"),
             Catch::Contains("single slider size"));
  CHECK_THAT(message(sep + "[slider]\ncolumns = 2\nrows = 1\n[initial]\nangles = [0, 1e5]\n"),
             Catch::Contains("from -1e4 to 1e4"));
  CHECK_THAT(message(sep + "[slider]\ntilt = 4\n"),
             Catch::Contains("slider.tilt") && Catch::Contains("-π to π"));
  CHECK_THAT(message(sep + "[slider]\nshift_y = -2\n"),
             Catch::Contains("slider.shift_y") && Catch::Contains("from -1 to 1 (m)"));
  CHECK_THAT(message(sep + "[substrate]\nangle = \"up\"\n"), Catch::Contains("substrate.angle"));
  CHECK_THAT(message(sep + "[observables]\nseries = false\nfield = true\n"),
             Catch::Contains("observables.field") && Catch::Contains("observables.series = true"));
  CHECK_THAT(message(sep + "[slider]\ncolumns = [2, 3]\nrows = 2\n[observables]\ntorques = true\n"),
             Catch::Contains("observables.torques") && Catch::Contains("single slider size"));
  CHECK_THAT(message(sep + "[observables]\nenergies = 1\n"), Catch::Contains("observables.energies"));
  CHECK_THAT(message(sep + "[drive]\nspeed = [4e-3, 8e-3]\n"),
             Catch::Contains("drive.periods") && Catch::Contains("is needed with several drive.speed"));
  CHECK_THAT(message(sep + "[drive]\nspeed = [4e-3, 8e-3]\nend = 20.0\n"),
             Catch::Contains("drive.end") && Catch::Contains("give drive.periods"));
  CHECK_THAT(message(sep + "[drive]\nperiods = 3\nend = 20.0\n"),
             Catch::Contains("drive.periods") && Catch::Contains("give one"));
  CHECK_THAT(message(sep + "[drive]\nperiods = 0\n"),
             Catch::Contains("drive.periods") && Catch::Contains("from 1 to 10000"));
  CHECK_THAT(message(sep + "[drive]\nperiods = 2.5\n"), Catch::Contains("drive.periods"));
  CHECK_THAT(message(sep + "[drive]\nperiods = 2\nspeed = [4e-3, -1e-3]\n"),
             Catch::Contains("drive.speed") && Catch::Contains("> 0 (m/s)"));
  CHECK_THAT(message(sep + "[slider]\ndamping = { from = 0.0, to = 1e-5, count = 3 }\n"),
             Catch::Contains("slider.damping") && Catch::Contains("> 0 (kg m²/s)"));
  CHECK_THAT(message("[model]\nrows = 3\n"), Catch::Contains("the scene sections are"));
  CHECK_THAT(message(""), Catch::Contains("sweep.separation") && Catch::Contains("is missing"));
  CHECK(message("[sweep]\nseparation = [8e-3]\n") ==
        "no error");                                             // every other key has the experiment's value
  CHECK(message("[sweep]\nseparation = 8e-3\n") == "no error");  // one number: a list of one
  CHECK(rotorsweep::io::parse_slider_scene_text("[sweep]\nseparation = 8e-3\n", "one").separations ==
        std::vector<double>{8e-3});
  const auto swept = rotorsweep::io::parse_slider_scene_text(
      sep +
          "[drive]\nperiods = 4\nspeed = { from = 1e-3, to = 16e-3, count = 5, spacing = \"log\" }\n"
          "[slider]\ndamping = [2.5e-6, 5e-6]\n",
      "swept");
  CHECK(swept.speeds.size() == 5);
  CHECK(swept.speeds[1] == Approx(2e-3));
  CHECK(swept.member_count() == 10);
  CHECK(slider_variant(swept, 1, 1).end == Approx(0.5 + 4 * 16e-3 / 2e-3));
  CHECK(slider_variant(swept, 1, 1).damping == 5e-6);
}

TEST_CASE("slider scan: the experiment's 7 x 7 slider matches the reference code's published examples",
          "[ensemble][slider]") {
  // The experiment's public simulation code documents three separations (mean F_x on the slider over
  // t > 2.5 s, and the order parameter across y): 6.5 mm −0.21 N, 1.00; 8.5 mm −1.33 N, 0.67; 11.0 mm
  // −0.0045 N, −0.97. Its initial noise is its own, so agreement is to the digits it quotes.
  const auto result =
      scan("[sweep]\nseparation = [6.5e-3, 8.5e-3, 11.0e-3]\n[numerics]\nglobal_error = \"local\"\n", 2);
  const double published_force[] = {0.21, 1.33, 0.0045}, published_order[] = {1.00, 0.67, -0.97};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& m = result.members[k];
    double force = 0, order = 0;
    std::size_t samples = 0;
    const auto& times = result.timeline.sample_times.front();
    for (std::size_t i = 0; i < times.size(); ++i) {
      if (times[i] <= 2.5) continue;
      force += m.friction_series[i];
      order += m.order_y_series[i];
      ++samples;
    }
    force /= double(samples);
    order /= double(samples);
    INFO("h = " << m.separation << ": mean F " << force << ", order across y " << order);
    CHECK(std::fabs(force - published_force[k]) < 0.04 * published_force[k]);
    CHECK(std::fabs(order - published_order[k]) < 0.01);
  }
}
