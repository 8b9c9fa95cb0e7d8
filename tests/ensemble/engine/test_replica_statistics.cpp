// The replica statistic of every result file's curves: mean, population spread, standard error and
// range over the finished replicas, checked against closed forms; NaN where too few finished.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "ensemble/engine/replica_statistics.hpp"

using rotorsweep::ensemble::replica_statistics;

TEST_CASE("replica statistics over the finished replicas match their closed forms", "[replica_statistics]") {
  const std::vector<double> values{1, 100, 2, 4, 5};
  const std::vector<bool> finished{true, false, true, true, true};  // 100 did not finish
  const auto s = replica_statistics(
      values.size(), [&](std::size_t i) { return values[i]; }, [&](std::size_t i) { return finished[i]; });
  CHECK(s.count == 4);
  CHECK(s.mean == 3.0);
  CHECK(s.std == Approx(std::sqrt(10.0 / 4)));        // Σ (x − 3)² = 4 + 1 + 1 + 4
  CHECK(s.sem == Approx(std::sqrt(10.0 / 3) / 2.0));  // sample spread / √n
  CHECK(s.min == 1.0);
  CHECK(s.max == 5.0);
}

TEST_CASE("replica statistics say NaN where too few replicas finished", "[replica_statistics]") {
  const auto none = replica_statistics(
      3, [](std::size_t) { return 1.0; }, [](std::size_t) { return false; });
  CHECK(none.count == 0);
  CHECK((std::isnan(none.mean) && std::isnan(none.std) && std::isnan(none.sem) && std::isnan(none.min)));
  const auto one = replica_statistics(
      3, [](std::size_t i) { return double(i); }, [](std::size_t i) { return i == 1; });
  CHECK(one.mean == 1.0);
  CHECK(one.std == 0.0);
  CHECK(std::isnan(one.sem));
}
