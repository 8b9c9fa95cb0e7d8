// Critical points of the two-angle landscape (landscape/critical_points): zero gradient,
// completeness against Newton from a dense grid of starts, the Euler characteristic of the
// torus on a dense (A, τ) grid, the strict-FM fold only for 3 ≤ A ≤ 6, and the paper's minima.
// (H_r as the N = 2 row model's energy is tested in
// tests/kernels/models/rows/test_nearest_neighbour_rows.cpp.)
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <set>

#include "landscape/critical_points.hpp"

using namespace rotorsweep::landscape;

namespace {

using std::numbers::pi;

double torus_distance(double a, double b) {
  const double d = std::fabs(std::remainder(a - b, 2 * pi));
  return d;
}

/// Newton's method on the gradient from (even, odd); converged critical point or nothing.
std::optional<std::array<double, 2>> newton(const TwoAngleEnergy& h, double even, double odd) {
  for (int i = 0; i < 60; ++i) {
    const auto [ge, go] = h.gradient(even, odd);
    const auto [ee, eo, oo] = h.hessian(even, odd);
    const double det = ee * oo - eo * eo;
    if (std::fabs(det) < 1e-12) return std::nullopt;
    const double de = (oo * ge - eo * go) / det, dodd = (ee * go - eo * ge) / det;
    even -= de;
    odd -= dodd;
    if (std::hypot(de, dodd) < 1e-13) {
      const auto [re, ro] = h.gradient(even, odd);
      if (std::hypot(re, ro) < 1e-9) return std::array<double, 2>{even, odd};
    }
  }
  return std::nullopt;
}

}  // namespace

TEST_CASE("every critical point found has zero gradient and none is missed", "[landscape]") {
  for (double A : {0.3, 1.0, 3.5, 4.0, 5.2, 6.0, 7.3, 8.0, 9.5, 11.0, 30.0}) {
    for (double tau : {0.0, 0.2, 0.61, 1.0, 1.37}) {
      const TwoAngleEnergy h{A, tau};
      const auto set = critical_points(h);
      INFO("A = " << A << " tau = " << tau);
      for (const auto& p : set.points) {
        const auto [ge, go] = h.gradient(p.even, p.odd);
        CHECK(std::hypot(ge, go) < 1e-8);
      }
      for (int i = 0; i < 40; ++i)
        for (int j = 0; j < 40; ++j) {
          const auto found = newton(h, 2 * pi * (i + 0.5) / 40, 2 * pi * (j + 0.37) / 40);
          if (!found) continue;
          const bool listed = std::any_of(set.points.begin(), set.points.end(), [&](const CriticalPoint& p) {
            return torus_distance(p.even, (*found)[0]) < 1e-6 && torus_distance(p.odd, (*found)[1]) < 1e-6;
          });
          INFO("Newton found (" << (*found)[0] << ", " << (*found)[1] << ")");
          CHECK(listed);
        }
    }
  }
}

TEST_CASE("minima minus saddles plus maxima is zero on a dense (A, tau) grid", "[landscape]") {
  int degenerate = 0, checked = 0;
  for (int a = 1; a <= 240; ++a)
    for (int t = 0; t < 90; ++t) {
      const auto set = critical_points({0.05 * a, 0.5 * pi * t / 90});
      INFO("A = " << 0.05 * a << " tau = " << 0.5 * pi * t / 90);
      CHECK(set.euler_consistent());
      degenerate += set.degenerate > 0;
      ++checked;
    }
  CHECK(degenerate < checked / 100);
}

TEST_CASE("over random coefficient tables every set is Morse-consistent or flagged, rarely flagged",
          "[landscape]") {
  std::mt19937_64 engine(20261125);
  std::uniform_real_distribution<double> coefficient(0.05, 3.0), cross(-1.0, 1.0), A(0.0, 15.0),
      tau(0.0, 2 * pi);
  int flagged = 0, checked = 0;
  for (int table = 0; table < 40; ++table) {
    const TwoAngleCoefficients k{coefficient(engine), coefficient(engine), cross(engine)};
    for (int point = 0; point < 40; ++point) {
      const double a_value = A(engine), t_value = tau(engine);
      const auto set = critical_points({a_value, t_value, k});
      INFO("a " << k.a << " b " << k.b << " c " << k.c << " A " << a_value << " tau " << t_value);
      CHECK((set.degenerate > 0 || set.minima - set.saddles + set.maxima == 0));
      flagged += set.degenerate > 0;
      ++checked;
    }
  }
  CHECK(flagged < checked / 50);
  // tables where the root finders cannot resolve every point: flagged, never miscounted
  int unresolved = 0;
  for (const TwoAngleCoefficients k : {TwoAngleCoefficients{0, 0, 1e-3}, {1e3, 1, 0}, {1.5, 1e-9, 0}})
    for (int point = 0; point < 60; ++point) {
      const auto set = critical_points({A(engine), tau(engine), k});
      CHECK((set.degenerate > 0 || set.minima - set.saddles + set.maxima == 0));
      unresolved += set.degenerate > 0 && k.a == 0;
    }
  CHECK(unresolved == 60);  // a = b = 0: the off-diagonal polynomial vanishes, no cell is countable
}

TEST_CASE("strict-FM points fold only for 3 <= A <= 6", "[landscape]") {
  const auto strict_count = [](double A, double tau) {
    const auto set = critical_points({A, tau});
    return std::count_if(set.points.begin(), set.points.end(),
                         [](const CriticalPoint& p) { return p.alignment == AlignmentClass::strict_fm; });
  };
  // the fold lies at A² = 9 + 27 cos² 2χ; near A = 6 only for τ within a few 1e-3 of 0 (mod π/2)
  const auto counts = [&](double A) {
    std::set<long> seen;
    for (int t = 0; t < 360; ++t) seen.insert(strict_count(A, 0.5 * pi * t / 360));
    return seen.size();
  };
  for (double A : {0.5, 2.0, 2.9, 6.1, 7.0, 20.0}) {
    INFO("A = " << A);
    CHECK(counts(A) == 1);
  }
  for (double A : {3.2, 4.5, 5.5, 5.8}) {
    INFO("A = " << A);
    CHECK(counts(A) == 2);
  }
}

TEST_CASE("the paper's minima at A = 1 and A = 11", "[landscape]") {
  for (int t = 0; t < 12; ++t) {
    const double tau = 0.5 * pi * t / 12;
    const auto large = critical_points({11, tau});
    CHECK(large.minima == 1);
    for (const auto& p : large.points)
      if (p.type == MorseType::minimum) CHECK(p.alignment == AlignmentClass::strict_fm);
    // the paper counts the exchange pair (θe, θo) ↔ (θo, θe) as one AFM-like state
    const auto small = critical_points({1, tau});
    CHECK(small.minima == 4);
    std::vector<CriticalPoint> strict, afm_like;
    for (const auto& p : small.points) {
      if (p.type != MorseType::minimum) continue;
      if (p.alignment == AlignmentClass::strict_fm) strict.push_back(p);
      if (p.alignment == AlignmentClass::afm_like) afm_like.push_back(p);
    }
    CHECK(strict.size() == 2);
    REQUIRE(afm_like.size() == 2);
    CHECK(torus_distance(afm_like[0].even, afm_like[1].odd) < 1e-9);
    CHECK(afm_like[0].energy == Approx(afm_like[1].energy));
  }
}
