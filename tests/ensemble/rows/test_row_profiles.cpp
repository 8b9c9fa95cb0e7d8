// Row profiles (docs/model.md §3 "Row profiles"): D_j sums to D and the links' alignment averages to
// ρ̄, open rows started symmetric keep a mirror-symmetric profile whose edges differ from the bulk,
// the profile converges with the tolerance, and lanes, threads and the Langevin stepper agree.
#include <catch2/catch.hpp>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "support/same_results.hpp"
#include "support/scene_sweep.hpp"

using namespace rotorsweep::ensemble;
using Catch::Detail::Approx;
using rotorsweep::testing::sweep;

namespace {
const std::string open_rows = "[model]\nrows = 10\ncouplings = \"dipolar\"\nrange = 3\nboundary = \"open\"\n";

std::string profile_grid(const std::string& rtol) {
  return "[drive]\ng = [0.05]\n[sweep]\nA = [1.0, 3.0, 12.0]\n[initial]\nkinds = [\"FM\"]\nnoise = 0.0\n"
         "[numerics]\nrtol = " +
         rtol + "\natol = 1e-13\n";
}

double sum(const std::vector<double>& values) { return std::accumulate(values.begin(), values.end(), 0.0); }

double largest_magnitude(const std::vector<double>& values) {
  double m = 0;
  for (double v : values) m = std::max(m, std::fabs(v));
  return m;
}

}  // namespace

TEST_CASE("open rows: D_j sums to D, links average to ρ̄, the profile is mirror-symmetric with distinct edges",
          "[ensemble][profiles]") {
  const auto results = sweep(open_rows + profile_grid("1e-10"));
  REQUIRE(results.size() == 3);
  bool edges_differ = false;
  for (const auto& r : results) {
    INFO("A index " << r.index);
    REQUIRE(r.status == rotorsweep::kernels::LaneStatus::ok);
    REQUIRE(r.row_dissipation.size() == 10);
    REQUIRE(r.link_alignment.size() == 9);
    const double scale = largest_magnitude(r.row_dissipation);
    CHECK(sum(r.row_dissipation) == Approx(r.dissipation()).epsilon(1e-7).margin(1e-12));
    CHECK(sum(r.link_alignment) / 9 == Approx(r.alignment_mean()).epsilon(1e-9));
    for (std::size_t j = 0; j < 5; ++j) {
      CHECK(r.row_dissipation[j] == Approx(r.row_dissipation[9 - j]).margin(1e-8 * scale));
      if (j < 4) CHECK(r.link_alignment[j] == Approx(r.link_alignment[8 - j]).margin(1e-9));
    }
    edges_differ = edges_differ || std::fabs(r.row_dissipation[0] - r.row_dissipation[4]) > 1e-3 * scale;
  }
  CHECK(edges_differ);
}

TEST_CASE("periodic rows started alike share D equally", "[ensemble][profiles]") {
  const auto results =
      sweep("[model]\nrows = 6\n[observables]\nrow_profiles = true\n" + profile_grid("1e-10"));
  for (const auto& r : results) {
    REQUIRE(r.row_dissipation.size() == 6);
    REQUIRE(r.link_alignment.size() == 6);
    for (std::size_t j = 0; j < 6; ++j) {
      CHECK(r.row_dissipation[j] == Approx(r.dissipation() / 6).epsilon(1e-7).margin(1e-12));
      CHECK(r.link_alignment[j] == Approx(r.alignment_mean()).epsilon(1e-9));
    }
  }
}

TEST_CASE("the row profile converges with the tolerance", "[ensemble][profiles]") {
  const auto reference = sweep(open_rows + profile_grid("1e-12"));
  double previous = 0;
  for (const char* rtol_text : {"1e-5", "1e-7", "1e-9"}) {
    const double rtol = std::stod(rtol_text);
    const auto results = sweep(open_rows + profile_grid(rtol_text));
    double error = 0;
    for (std::size_t i = 0; i < results.size(); ++i)
      for (std::size_t j = 0; j < 10; ++j)
        error = std::max(error, std::fabs(results[i].row_dissipation[j] - reference[i].row_dissipation[j]));
    INFO("rtol " << rtol << ": largest error of D_j " << error << ", at the looser tolerance " << previous);
    if (previous > 0) CHECK(error < previous / 10);
    CHECK(error < 1e3 * rtol);
    previous = error;
  }
}

TEST_CASE("row profiles: scalar and SIMD lanes and thread counts give the same bits",
          "[ensemble][profiles]") {
  const std::string scene = open_rows +
                            "[drive]\ng = [0.01, 0.2]\n[sweep]\nA = [0.5, 4.0, 7.0, 12.0]\n[initial]\n"
                            "kinds = [\"AFM\", \"random\"]\n[numerics]\nrtol = 1e-8\natol = 1e-12\n";
  const auto simd = sweep(scene, 2);
  const auto scalar = sweep(scene + "lanes = \"scalar\"\n", 1);
  std::string first;
  CHECK(rotorsweep::testing::count_differences(simd, scalar, first) == 0);
  INFO(first);
  CHECK(simd.front().row_dissipation.size() == 10);
}

TEST_CASE("at T > 0 the rows' drive sums are D's own sum", "[ensemble][profiles][thermal]") {
  const auto results = sweep(open_rows +
                             "[drive]\ng = [0.5]\n[sweep]\nA = [2.0, 8.0]\n[thermal]\ntemperature = 0.05\n"
                             "steps_per_period = 400\n[schedule]\naverage_periods = 4\n");
  for (const auto& r : results) {
    REQUIRE(r.status == rotorsweep::kernels::LaneStatus::ok);
    CHECK(sum(r.row_dissipation) == Approx(r.dissipation()).epsilon(1e-12).margin(1e-12));
    CHECK(sum(r.link_alignment) / 9 == Approx(r.alignment_mean()).epsilon(1e-12));
  }
}

TEST_CASE("row_profiles is on for open rows, off for periodic ones, and can be switched",
          "[ensemble][profiles][io]") {
  using rotorsweep::io::parse_scene_text;
  const std::string rest = "[drive]\ng = [0.01]\n[sweep]\nA = [1.0]\n";
  CHECK(parse_scene_text(open_rows + rest, "s").row_profiles);
  CHECK_FALSE(parse_scene_text("[model]\nrows = 4\n" + rest, "s").row_profiles);
  const auto off = sweep(open_rows + rest + "[observables]\nrow_profiles = false\n");
  CHECK(off.front().row_dissipation.empty());
  CHECK_THROWS_WITH(parse_scene_text("[model]\nrows = 4\n" + rest + "[observables]\nrow_profiles = 1\n", "s"),
                    Catch::Contains("observables.row_profiles"));
}
