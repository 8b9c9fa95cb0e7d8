// Closed forms of the bifurcation set (landscape/bifurcation_curves): every curve point is a
// degenerate critical point, A_- and A_* from their formulas and by direct minimisation, the
// alignment curve's max/saddle/min segments, the tangential strict-FM curve on 3 ≤ A ≤ 6.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "landscape/bifurcation_curves.hpp"
#include "landscape/critical_points.hpp"

using namespace rotorsweep::landscape;

namespace {

constexpr double pi = std::numbers::pi;

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

TEST_CASE("every point of the four bifurcation curves is a degenerate critical point",
          "[landscape][curves]") {
  for (auto curve :
       {Curve::fm_tangential, Curve::fm_transverse, Curve::off_diagonal_plus, Curve::off_diagonal_minus}) {
    const auto points = sample_curve(curve, 200, 40);
    REQUIRE(points.size() > 50);
    for (const auto& p : points) {
      if (p.A < 1e-6) continue;  // A = 0 is a whole circle of critical points
      INFO(curve_name(curve) << " at A = " << p.A << ", tau = " << p.tau);
      CHECK(most_degenerate({p.A, p.tau}) < 1e-5 * (10 + p.A));
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
  const double t1 = alignment_tau1(), t2 = alignment_tau2();
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
