// Curve aggregation (ensemble/curves): statistics over replicas, regime fractions over all
// members, failed members kept out of the statistics.
#include <catch2/catch.hpp>
#include <cmath>

#include "ensemble/rows/curves.hpp"

using namespace rotorsweep::ensemble;

TEST_CASE("points aggregate their replicas", "[ensemble][curves]") {
  Scene scene;
  scene.A_values = {1, 2};
  scene.g_values = {0.1};
  scene.replicas = 4;
  const auto members = plan_members(scene);
  std::vector<MemberResult> results(members.size());
  const double D[] = {1, 3, 1, 3, 5, 5, 5, 5};
  const Regime regimes[] = {Regime::fm, Regime::fm, Regime::cp, Regime::afm,
                            Regime::cp, Regime::cp, Regime::cp, Regime::unsettled};
  for (std::size_t i = 0; i < results.size(); ++i) {
    results[i].summary(Summary::mean, Channel::dissipation) = D[i];
    results[i].regime = regimes[i];
  }
  results[7].status = rotorsweep::kernels::LaneStatus::non_finite;
  results[7].summary(Summary::mean, Channel::dissipation) = NAN;
  const auto curves = aggregate_curves(members, results);
  REQUIRE(curves.size() == 2);
  CHECK(curves[0].A == 1);
  CHECK(curves[0].count == 4);
  CHECK(curves[0].dissipation_mean == 2);
  CHECK(curves[0].dissipation_std == 1);
  CHECK(curves[0].dissipation_min == 1);
  CHECK(curves[0].dissipation_max == 3);
  CHECK(curves[0].regime_count[std::size_t(Regime::fm)] == 2);
  CHECK(curves[0].regime_count[std::size_t(Regime::cp)] == 1);
  CHECK(curves[1].members == 4);
  CHECK(curves[1].count == 3);
  CHECK(curves[1].dissipation_mean == 5);
  CHECK(curves[1].dissipation_std == 0);
  CHECK(curves[1].regime_count[std::size_t(Regime::unsettled)] == 0);  // the failed member is its own
  CHECK(curves[1].failed == 1);
  CHECK(curves[1].regime_count[std::size_t(Regime::cp)] == 3);
}

TEST_CASE("points of a ragged plan: random starts once, exact ones without replicas", "[ensemble][curves]") {
  Scene scene;
  scene.A_values = {1};
  scene.g_values = {0.1};
  scene.noise_values = {0.01, 0.3};
  scene.kinds = {InitialKind::random, InitialKind::afm, InitialKind::exact};
  scene.exact_angles = {0.0};
  scene.replicas = 3;
  const auto members = plan_members(scene);
  REQUIRE(members.size() == 3 + 3 + 1 + 3);  // random, AFM, exact at η = 0.01; AFM at η = 0.3
  std::vector<MemberResult> results(members.size());
  for (std::size_t i = 0; i < results.size(); ++i)
    results[i].summary(Summary::mean, Channel::dissipation) = double(i);
  const auto curves = aggregate_curves(members, results);
  REQUIRE(curves.size() == 4);
  const std::size_t sizes[] = {3, 3, 1, 3};
  const double means[] = {1, 4, 6, 8};
  for (std::size_t p = 0; p < 4; ++p) {
    CHECK(curves[p].index == p);
    CHECK(curves[p].members == sizes[p]);
    CHECK(curves[p].dissipation_mean == means[p]);
  }
  CHECK(curves[2].kind == InitialKind::exact);
  CHECK(std::isnan(curves[2].dissipation_sem));
  CHECK(curves[3].noise == 0.3);
}
