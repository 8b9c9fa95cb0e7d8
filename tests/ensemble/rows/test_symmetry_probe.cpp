// The symmetry probe (ensemble/rows/symmetry_probe.hpp, docs/numerics.md "Symmetry-limited members")
// on whole sweeps without disorder: a random start held in strict FM through the CP regime is
// symmetry-limited and held, open dipolar rows whose D converges are not, every CP member of a uniform
// ring is; with a disorder above rtol no probe runs; a disordered dipolar scene runs.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "support/scene_sweep.hpp"

using namespace rotorsweep::ensemble;

namespace {

/// The scene's members on two threads.
std::vector<MemberResult> probe_sweep(const std::string& text) { return rotorsweep::testing::sweep(text, 2); }

/// N = 16 periodic rows at A = 9, g = 2e-3 (CP), random starts of seed 11: replica 2 falls into
/// strict FM during relaxation at rtol 1e-10 and stays there without slipping.
std::string held_scene(const std::string& extra = "") {
  return "[model]\nrows = 16\n[drive]\ng = [2e-3]\n[sweep]\nA = [9.0]\n[initial]\nkinds = [\"random\"]\n"
         "replicas = 3\nseed = 11\n[numerics]\nrtol = 1e-10\natol = 1e-13\n" +
         extra;
}

}  // namespace

TEST_CASE("a random start held in strict FM through the CP regime is symmetry-limited, not resolved",
          "[ensemble][symmetry_probe]") {
  const auto results = probe_sweep(held_scene());
  std::size_t held = 0;
  for (const auto& r : results) {
    INFO("replica " << r.index << " regime " << regime_name(r.regime) << " D " << r.dissipation());
    REQUIRE(r.status == rotorsweep::kernels::LaneStatus::ok);
    CHECK(std::isfinite(r.dissipation_probe));  // every member slips or ends on a symmetric set
    CHECK_FALSE(r.dissipation_resolved());      // whatever state it is in, the symmetry decides it
    if (r.slips_per_period() == 0) {
      CHECK(r.symmetry_limited);
      CHECK(r.symmetry_held);
      CHECK(r.dissipation_error() < 1e-6 * r.dissipation());  // the local estimate alone would read resolved
      CHECK(r.dissipation_probe > 3 * r.dissipation());       // an asymmetry makes it slip
      ++held;
    }
  }
  CHECK(held == 1);
}

TEST_CASE("open dipolar rows whose D converges are not symmetry-limited; a uniform ring's CP members are",
          "[ensemble][symmetry_probe]") {
  const auto open = probe_sweep(
      "[model]\nrows = 4\ncouplings = \"dipolar\"\nrange = \"all\"\nrow_length = 7\nboundary = \"open\"\n"
      "[drive]\ng = [0.154]\n[sweep]\nA = [5.61765]\n[initial]\nkinds = [\"AFM\"]\nnoise = 0.1309\n"
      "[schedule]\nrelax_periods = 1\naverage_periods = 4\n[numerics]\nrtol = [1e-6, 1e-8]\natol = [1e-9, "
      "1e-11]\n");
  for (const auto& r : open) {
    INFO("rtol member " << r.index);
    REQUIRE(r.slips_per_period() > 0);
    CHECK(std::fabs(r.dissipation_probe - r.dissipation()) < 0.3 * r.dissipation_error());
    CHECK_FALSE(r.symmetry_limited);
    CHECK(r.dissipation_resolved());
  }
  CHECK(std::fabs(open[0].dissipation() - open[1].dissipation()) < open[0].dissipation_error());

  const auto ring = probe_sweep(
      "[model]\nrows = 8\n[drive]\ng = [0.002]\n[sweep]\nA = [6.0, 8.0]\n[initial]\nkinds = [\"AFM\"]\n"
      "[numerics]\nrtol = 1e-7\natol = 1e-10\n");
  for (const auto& r : ring) {
    INFO("A member " << r.index);
    REQUIRE(r.regime == Regime::cp);
    CHECK(r.symmetry_limited);
    CHECK_FALSE(r.symmetry_held);
  }
}

TEST_CASE("with a disorder above rtol no probe runs; disorder works with coupling tables",
          "[ensemble][symmetry_probe][disorder]") {
  for (const auto& r : probe_sweep(held_scene("[disorder]\nA = 1e-6\n"))) {
    CHECK(std::isnan(r.dissipation_probe));
    CHECK_FALSE(r.symmetry_limited);
  }
  const auto dipolar = probe_sweep(
      "[model]\nrows = 6\ncouplings = \"dipolar\"\nrange = 2\n[drive]\ng = [0.01]\n[sweep]\nA = [6.0]\n"
      "[initial]\nkinds = [\"AFM\"]\n[numerics]\nrtol = 1e-8\natol = 1e-11\n[disorder]\nA = 1e-6\n"
      "anisotropy = 1e-6\n");
  REQUIRE(dipolar.size() == 1);
  CHECK(dipolar[0].status == rotorsweep::kernels::LaneStatus::ok);
  CHECK(std::isnan(dipolar[0].dissipation_probe));
}
