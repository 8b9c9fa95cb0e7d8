// The full array at any size (docs/numerics.md "The full array at any size"): the matrix-free slider
// (numerics.linear_solver = "krylov": FFT pair sums, conjugate gradients) against the dense one over every
// observable, inertial and overdamped; box-sum substrate tables against direct sums through a scan; an
// infinite substrate against a growing finite one; the size rule of "auto"; thread-count invariance.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "ensemble/slider/slider_sweep.hpp"
#include "io/slider_scene_parser.hpp"

using namespace rotorsweep::ensemble;

namespace {

/// A 7 × 6 slider (42 rotors: its lattice sums take the FFT) over 15 × 15 magnets, two separations, every
/// optional series, half a period of rest and one of sliding at rtol 1e-9, no shadow runs; `extra` adds keys.
std::string scene(const std::string& solver, const std::string& dynamics, const std::string& extra = "") {
  return "[slider]\ncolumns = 7\nrows = 6\ndynamics = \"" + dynamics +
         "\"\n[substrate]\ncolumns = 15\nrows = 15\n[drive]\nrest = 1.0\nperiods = 1\n[sweep]\n"
         "separation = [7e-3, 9.5e-3]\n[observables]\nsamples_per_period = 20\nangles = true\nenergies = "
         "true\n"
         "field = true\nsublattices = true\ntorques = true\nforces = true\n[numerics]\nrtol = 1e-9\natol = "
         "1e-9\nglobal_error = \"local\"\n"
         "linear_solver = \"" +
         solver + "\"\n" + extra;
}

SliderResult scan(const std::string& text, int threads = 2) {
  return run_slider_scan(rotorsweep::io::parse_slider_scene_text(text, "slider-test"), {.threads = threads});
}

/// The largest difference of two series relative to the larger of their largest magnitudes.
double relative_gap(const std::vector<double>& a, const std::vector<double>& b) {
  REQUIRE(a.size() == b.size());
  double largest = 0, gap = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    largest = std::max({largest, std::fabs(a[k]), std::fabs(b[k])});
    gap = std::max(gap, std::fabs(a[k] - b[k]));
  }
  return largest > 0 ? gap / largest : gap;
}

}  // namespace

TEST_CASE("slider, matrix-free: every observable follows the dense solve, inertial and overdamped",
          "[ensemble][slider][fft]") {
  for (const std::string dynamics : {"inertial", "overdamped"}) {
    INFO(dynamics);
    const auto dense = scan(scene("dense", dynamics)), free = scan(scene("krylov", dynamics));
    for (std::size_t m = 0; m < dense.members.size(); ++m) {
      const SliderMember &a = dense.members[m], &b = free.members[m];
      REQUIRE(b.status == "ok");
      CHECK(b.friction == Catch::Detail::Approx(a.friction).epsilon(1e-6));
      for (std::size_t p = 0; p < a.period_balance.size(); ++p) CHECK(std::fabs(b.period_balance[p]) < 1e-6);
      for (const auto& [x, y] :
           std::vector<std::pair<const std::vector<double>*, const std::vector<double>*>>{
               {&a.friction_series, &b.friction_series},
               {&a.order_x_series, &b.order_x_series},
               {&a.order_y_series, &b.order_y_series},
               {&a.energy_series, &b.energy_series},
               {&a.angles, &b.angles},
               {&a.substrate_energy_series, &b.substrate_energy_series},
               {&a.pair_energy_series, &b.pair_energy_series},
               {&a.field_axis_series, &b.field_axis_series},
               {&a.torque_even_series, &b.torque_even_series},
               {&a.torques, &b.torques},
               {&a.force_y_series, &b.force_y_series},
               {&a.force_z_series, &b.force_z_series}})
        CHECK(relative_gap(*x, *y) < 1e-5);
    }
  }
}

TEST_CASE("slider, matrix-free: one thread or two give the same bits, the helper thread included",
          "[ensemble][slider][fft]") {
  // one member on two threads: the second takes its Q convolutions (OpenMP tasks)
  const std::string one = scene("krylov", "overdamped");
  const auto single = scan(one.substr(0, one.find("[sweep]")) + "[sweep]\nseparation = 8e-3\n" +
                               one.substr(one.find("[observables]")),
                           1);
  const auto helped = scan(one.substr(0, one.find("[sweep]")) + "[sweep]\nseparation = 8e-3\n" +
                               one.substr(one.find("[observables]")),
                           2);
  CHECK(single.members[0].friction_series == helped.members[0].friction_series);
  CHECK(single.members[0].angles == helped.members[0].angles);
}

TEST_CASE("slider: box-sum tables and an infinite substrate through a scan",
          "[ensemble][slider][substrate]") {
  // box sums take over where direct sums would pass 1e8 terms: 7 × 6 over 400 × 400 magnets
  const std::string big = "[substrate]\ncolumns = 400\nrows = 400\n";
  const auto base = [&](const std::string& substrate) {
    return "[slider]\ncolumns = 7\nrows = 6\n" + substrate +
           "[drive]\nrest = 0.5\nperiods = 1\n[sweep]\nseparation = 8e-3\n[observables]\nseries = false\n"
           "[numerics]\nglobal_error = \"local\"\n";
  };
  const SliderScene finite = rotorsweep::io::parse_slider_scene_text(base(big), "t");
  CHECK(substrate_table_layout(finite, finite.sizes[0], 8e-3).sums == SubstrateSums::box);
  const SliderScene small = rotorsweep::io::parse_slider_scene_text(base(""), "t");
  CHECK(substrate_table_layout(small, small.sizes[0], 8e-3).sums == SubstrateSums::direct);
  const SliderScene infinite =
      rotorsweep::io::parse_slider_scene_text(base("[substrate]\nextent = \"infinite\"\n"), "t");
  const auto layout = substrate_table_layout(infinite, infinite.sizes[0], 8e-3);
  CHECK(layout.sums == SubstrateSums::infinite);
  CHECK(layout.shared_track());
  // the friction over growing finite substrates approaches the infinite one's, the gap shrinking
  const double f_infinite = scan(base("[substrate]\nextent = \"infinite\"\n")).members[0].friction;
  double gap_before = INFINITY;
  for (const int magnets : {40, 160, 640}) {
    const std::string s =
        "[substrate]\ncolumns = " + std::to_string(magnets) + "\nrows = " + std::to_string(magnets) + "\n";
    const double gap = std::fabs(scan(base(s)).members[0].friction - f_infinite);
    INFO(magnets << " magnets a side: gap " << gap);
    CHECK(gap < gap_before);
    gap_before = gap;
  }
  CHECK(gap_before < 0.02 * std::fabs(f_infinite));
}

TEST_CASE("slider: auto takes the matrix-free solve from 14 x 14 on the CPU, the dense one on a GPU",
          "[ensemble][slider][scene]") {
  const auto parsed = [](const std::string& text) {
    return rotorsweep::io::parse_slider_scene_text(text, "t");
  };
  const SliderScene scene = parsed("[slider]\ncolumns = [13, 14]\nrows = 14\n[sweep]\nseparation = 8e-3\n");
  CHECK_FALSE(matrix_free(scene, scene.sizes[0]));
  CHECK(matrix_free(scene, scene.sizes[1]));
  SliderScene gpu = scene;
  gpu.device = Device::gpu;
  CHECK_FALSE(matrix_free(gpu, gpu.sizes[1]));
  const SliderScene forced = parsed(
      "[slider]\ncolumns = 4\nrows = 3\n[sweep]\nseparation = 8e-3\n[numerics]\nlinear_solver = "
      "\"krylov\"\n");
  CHECK(matrix_free(forced, forced.sizes[0]));
}
