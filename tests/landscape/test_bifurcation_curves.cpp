// Closed forms of the bifurcation set (landscape/bifurcation_curves): every curve point is a
// degenerate critical point, A_- and A_* from their formulas and by direct minimisation, the
// alignment curve's max/saddle/min segments, the tangential strict-FM curve on 3 ≤ A ≤ 6.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "landscape/bifurcation_curves.hpp"
#include "landscape/critical_points.hpp"
#include "support/dipolar_range_4.hpp"

using namespace rotorsweep::landscape;
using rotorsweep::testing::dipolar_range_4;

namespace {

using std::numbers::pi;

/// Coefficients beyond nearest neighbours: point-dipole rows with range 4 (dipolar_range_4) and an
/// arbitrary table.
const TwoAngleCoefficients arbitrary{1.2, 2.6, 0.7};
const TwoAngleCoefficients all_coefficients[] = {TwoAngleCoefficients{}, dipolar_range_4, arbitrary};

/// Smallest |eigenvalue| of the Hessian over all critical points at (A, τ), and the point.
double most_degenerate(const TwoAngleEnergy& h) {
  double smallest = 1e300;
  for (const auto& p : critical_points(h).points) {
    const auto [ee, eo, oo] = h.hessian(p.even, p.odd);
    const double mean = 0.5 * (ee + oo), radius = std::hypot(0.5 * (ee - oo), eo);
    smallest = std::min({smallest, std::fabs(mean - radius), std::fabs(mean + radius)});
  }
  return smallest;
}

}  // namespace

TEST_CASE("phase folding keeps the critical energies", "[landscape][curves]") {
  for (double tau : {-2.9, -0.4, 0.3, 1.9, 2.8, 4.4, 7.0}) {
    const double folded = fundamental_phase(tau);
    REQUIRE(folded >= 0);
    REQUIRE(folded <= pi / 2);
    const auto a = critical_points({6.3, tau}), b = critical_points({6.3, folded});
    REQUIRE(a.points.size() == b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i) CHECK(a.points[i].energy == Approx(b.points[i].energy));
  }
}

TEST_CASE("every point of the four bifurcation curves is a degenerate critical point, for any coefficients",
          "[landscape][curves]") {
  for (const auto& k : all_coefficients)
    for (auto curve :
         {Curve::fm_tangential, Curve::fm_transverse, Curve::off_diagonal_plus, Curve::off_diagonal_minus}) {
      const auto points = sample_curve(curve, 200, 40, k);
      REQUIRE(points.size() > 50);
      for (const auto& p : points) {
        if (p.A < 1e-6) continue;  // A = 0 is a whole circle of critical points
        INFO(curve_name(curve) << " at A = " << p.A << ", tau = " << p.tau << ", (a, b, c) = " << k.a << ", "
                               << k.b << ", " << k.c);
        CHECK(most_degenerate({p.A, p.tau, k}) < 1e-5 * (k.hessian_scale() + p.A));
      }
    }
}

TEST_CASE("strict-FM curves: tangential on 3 <= A <= 6, transverse up to A = 10", "[landscape][curves]") {
  const auto extent = [](Curve curve) {
    const auto points = sample_curve(curve, 20001);
    const auto [lo, hi] = std::minmax_element(points.begin(), points.end(),
                                              [](const auto& a, const auto& b) { return a.A < b.A; });
    return std::pair{lo->A, hi->A};
  };
  const auto [t_lo, t_hi] = extent(Curve::fm_tangential);
  CHECK(t_lo == Approx(3).epsilon(1e-8));
  CHECK(t_hi == Approx(6).epsilon(1e-12));
  const auto [p_lo, p_hi] = extent(Curve::fm_transverse);  // A² = 27c² − 48c + 25, c = cos 2χ
  CHECK(p_lo == Approx(std::sqrt(11.0 / 3)).epsilon(1e-8));
  CHECK(p_hi == Approx(10).epsilon(1e-12));
}

TEST_CASE("A_* in closed form: end of the lower off-diagonal curve on the transverse strict-FM curve",
          "[landscape][curves]") {
  CHECK(A_star() == Approx(8.778365775883558).epsilon(1e-15));
  CHECK(A_star() == Approx(std::sqrt((1100 + 40 * std::sqrt(601.0)) / 27)).epsilon(1e-15));
  CHECK(off_diagonal_point(1, -1).A == Approx(A_star()).epsilon(1e-14));
  const double x_star = (4 - std::sqrt(601.0)) / 27;  // x_-(1)
  CHECK(off_diagonal_cos2chi(1, -1) == Approx(x_star).epsilon(1e-15));
  const double transverse = std::sqrt(27 * x_star * x_star - 48 * x_star + 25);
  CHECK(transverse == Approx(A_star()).epsilon(1e-14));
  // the two events coalesce: same folded phase as the transverse strict-FM curve at cos 2χ = x_*
  const double chi = 0.5 * std::acos(x_star);
  const double tau = fundamental_phase(chi - std::atan2(3 * std::sin(2 * chi), 2 * (3 * x_star - 2)));
  CHECK(off_diagonal_point(1, -1).tau == Approx(tau).epsilon(1e-12));
}

TEST_CASE("A_- is the minimum of the lower off-diagonal curve", "[landscape][curves]") {
  CHECK(A_minus() == Approx(4.634583466980286).epsilon(1e-14));
  CHECK(lower_curve_zeta0() == Approx(0.4589781198752156).epsilon(1e-14));
  // ζ0² is the root of 256y⁴ − 384y³ + 16y² + 54y − 9 (the paper's quartic) near 0.21
  const double y = lower_curve_zeta0() * lower_curve_zeta0();
  CHECK((((256 * y - 384) * y + 16) * y + 54) * y - 9 == Approx(0).margin(1e-12));
  // golden-section minimisation of A_L(ζ), independent of the quartic
  double a = 0.05, b = 0.95;
  const double r = (std::sqrt(5.0) - 1) / 2;
  const auto AL = [](double z) { return off_diagonal_point(z, -1).A; };
  for (int i = 0; i < 200; ++i) {
    const double c = b - r * (b - a), d = a + r * (b - a);
    (AL(c) < AL(d) ? b : a) = AL(c) < AL(d) ? d : c;
  }
  CHECK(AL(0.5 * (a + b)) == Approx(A_minus()).epsilon(1e-13));
  CHECK(0.5 * (a + b) == Approx(lower_curve_zeta0()).epsilon(1e-7));
  // A_L rises monotonically from ζ0 to ζ = 1 (A_* is its largest value there)
  double previous = A_minus();
  for (int i = 1; i <= 1000; ++i) {
    const double A = AL(lower_curve_zeta0() + (1 - lower_curve_zeta0()) * i / 1000);
    REQUIRE(A > previous);
    previous = A;
  }
}

TEST_CASE("alignment curve: its rho = 1/2 point is a maximum, saddle, minimum on the paper's segments",
          "[landscape][curves]") {
  const auto changes = alignment_type_changes();
  REQUIRE(changes.size() == 2);
  const double t1 = changes[0], t2 = changes[1];
  CHECK(t1 == Approx(std::atan((std::sqrt(41.0) - 6) / 5)).epsilon(1e-13));
  CHECK(t2 == Approx(std::atan((std::sqrt(41.0) + 6) / 5)).epsilon(1e-13));
  CHECK(4 - 6 * std::cos(2 * t1) + 12 * std::sin(2 * t1) == Approx(0).margin(1e-13));  // μ+(τ1) = 0
  CHECK(4 - 6 * std::cos(2 * t2) - 12 * std::sin(2 * t2) == Approx(0).margin(1e-13));  // μ−(τ2) = 0
  for (const auto& p : sample_curve(Curve::alignment, 181)) {
    if (std::fabs(p.tau - t1) < 0.02 || std::fabs(p.tau - t2) < 0.02 || p.A < 0.05) continue;
    const auto set = critical_points({p.A, p.tau});
    const auto half = std::find_if(set.points.begin(), set.points.end(),
                                   [](const auto& q) { return std::fabs(q.rho - 0.5) < 1e-8; });
    INFO("tau = " << p.tau << ", A = " << p.A);
    REQUIRE(half != set.points.end());
    const MorseType expected = p.tau < t1   ? MorseType::maximum
                               : p.tau < t2 ? MorseType::saddle
                                            : MorseType::minimum;
    CHECK(half->type == expected);
  }
}

TEST_CASE("beyond nearest neighbours: A_- is the minimum of A_L, A_* its end on the transverse curve",
          "[landscape][curves]") {
  for (const auto& k : {dipolar_range_4, arbitrary}) {
    INFO("(a, b, c) = " << k.a << ", " << k.b << ", " << k.c);
    const auto AL = [&](double z) { return off_diagonal_point(z, -1, k).A; };
    double lo = 0.05, hi = 0.95;  // golden section, independent of the closed-form slope
    const double r = (std::sqrt(5.0) - 1) / 2;
    for (int i = 0; i < 200; ++i) {
      const double c = hi - r * (hi - lo), d = lo + r * (hi - lo);
      (AL(c) < AL(d) ? hi : lo) = AL(c) < AL(d) ? d : c;
    }
    CHECK(AL(0.5 * (lo + hi)) == Approx(A_minus(k)).epsilon(1e-13));
    CHECK(0.5 * (lo + hi) == Approx(lower_curve_zeta0(k)).epsilon(1e-7));
    CHECK(AL(1) == A_star(k));
    double previous = A_minus(k);
    for (int i = 1; i <= 1000; ++i) {
      const double A = AL(lower_curve_zeta0(k) + (1 - lower_curve_zeta0(k)) * i / 1000);
      REQUIRE(A > previous);
      previous = A;
    }
    // at ζ = 1 the degenerate point is the strict-FM point on the transverse curve:
    // A² = (4ax − 2b)² + (2a + c)²(1 − x²) at x = x_-(1), with the same folded phase
    const double x = off_diagonal_cos2chi(1, -1, k), chi = 0.5 * std::acos(x);
    const double C = 4 * k.a * x - 2 * k.b, S = (2 * k.a + k.c) * std::sin(2 * chi);
    CHECK(std::hypot(C, S) == Approx(A_star(k)).epsilon(1e-13));
    CHECK(off_diagonal_point(1, -1, k).tau ==
          Approx(fundamental_phase(chi - std::atan2(S, C))).epsilon(1e-12));
  }
  // the dipolar interval is wider than the nearest-neighbour one at both ends
  CHECK(A_minus(dipolar_range_4) < A_minus());
  CHECK(A_star(dipolar_range_4) > A_star() + 4);
}

TEST_CASE(
    "beyond nearest neighbours: the alignment curve holds a rho = 1/2 point that changes type where found",
    "[landscape][curves]") {
  for (const auto& k : {dipolar_range_4, arbitrary}) {
    const auto changes = alignment_type_changes(k);
    INFO("(a, b, c) = " << k.a << ", " << k.b << ", " << k.c << ": " << changes.size() << " type changes");
    std::vector<MorseType> types;
    for (const auto& p : sample_curve(Curve::alignment, 181, 1e300, k)) {
      const auto near_change =
          std::any_of(changes.begin(), changes.end(), [&](double t) { return std::fabs(p.tau - t) < 0.02; });
      if (p.A < 0.05 || near_change) continue;
      const auto set = critical_points({p.A, p.tau, k});
      const auto half = std::find_if(set.points.begin(), set.points.end(),
                                     [](const auto& q) { return std::fabs(q.rho - 0.5) < 1e-8; });
      INFO("chi = " << p.parameter << ", tau = " << p.tau << ", A = " << p.A);
      REQUIRE(half != set.points.end());
      if (types.empty() || types.back() != half->type) types.push_back(half->type);
    }
    CHECK(types.size() == changes.size() + 1);  // one segment more than type changes, along χ
  }
}
