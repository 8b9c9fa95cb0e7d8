// Closed parametric forms of the strict-FM, off-diagonal and alignment curves, folded into
// τ ∈ [0, π/2], and the CP-interval ends A_- and A_* (paper appendix on the quasi-static friction).
#include "landscape/bifurcation_curves.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "landscape/bisection.hpp"

namespace rotorsweep::landscape {

namespace {

constexpr double pi = std::numbers::pi;

/// A cos(χ − τ) = C, A sin(χ − τ) = S  ⇒  A = √(C² + S²), τ = χ − atan2(S, C).
BifurcationPoint from_stationarity(double chi, double C, double S, double parameter) {
  return {std::hypot(C, S), fundamental_phase(chi - std::atan2(S, C)), parameter};
}

double quartic(double y) { return (((256 * y - 384) * y + 16) * y + 54) * y - 9; }

}  // namespace

double fundamental_phase(double tau) { return std::fabs(tau - pi * std::round(tau / pi)); }

std::string_view curve_name(Curve curve) {
  switch (curve) {
    case Curve::fm_tangential: return "fm_tangential";
    case Curve::fm_transverse: return "fm_transverse";
    case Curve::off_diagonal_plus: return "off_diagonal_plus";
    case Curve::off_diagonal_minus: return "off_diagonal_minus";
    case Curve::alignment: return "alignment";
  }
  return "unknown";
}

double off_diagonal_cos2chi(double zeta, int sign) {
  const double z2 = zeta * zeta;
  const double root = std::sqrt(((160 * z2 + 324) * z2 + 108) * z2 + 9);
  return (4 * z2 + sign * root) / (3 * (8 * z2 + 1));
}

DegeneratePoint off_diagonal_degenerate_point(double zeta, int sign) {
  const double x = off_diagonal_cos2chi(zeta, sign);
  if (x > 1 || x < -1) return {std::numeric_limits<double>::quiet_NaN(), 0, 0, zeta};
  const double chi = 0.5 * std::acos(x);
  const double C = 2 * zeta * (3 * x - 2);
  const double S = 3 * (2 * zeta * zeta - 1) * std::sqrt(1 - x * x) / zeta;
  return {std::hypot(C, S), chi - std::atan2(S, C), chi, zeta};
}

BifurcationPoint off_diagonal_point(double zeta, int sign) {
  const auto p = off_diagonal_degenerate_point(zeta, sign);
  return {p.A, fundamental_phase(p.tau), zeta};
}

std::vector<BifurcationPoint> sample_curve(Curve curve, int count, double A_max) {
  std::vector<BifurcationPoint> points;
  points.reserve(count);
  for (int i = 0; i < count; ++i) {
    const double u = count > 1 ? double(i) / (count - 1) : 0.0;
    switch (curve) {
      case Curve::fm_tangential:
      case Curve::fm_transverse: {
        const double chi = 0.5 * pi * u, c = std::cos(2 * chi);
        const double C = curve == Curve::fm_tangential ? 6 * c : 2 * (3 * c - 2);
        points.push_back(from_stationarity(chi, C, 3 * std::sin(2 * chi), chi));
        break;
      }
      case Curve::off_diagonal_plus:
      case Curve::off_diagonal_minus: {
        const double zeta = count > 1 ? (i + 1.0) / count : 1.0;  // ζ = 0 is excluded (A → ∞)
        const auto p = off_diagonal_point(zeta, curve == Curve::off_diagonal_plus ? 1 : -1);
        if (std::isfinite(p.A) && p.A <= A_max) points.push_back(p);
        break;
      }
      case Curve::alignment: {
        const double tau = 0.5 * pi * u;
        points.push_back({alignment_curve_A(tau), tau, tau});
        break;
      }
    }
  }
  return points;
}

double lower_curve_zeta0() {
  static const double zeta0 = [] {
    // Unsquared condition P√Δ + 2Q = 0; squaring adds the roots of P√Δ − 2Q = 0.
    const auto unsquared = [](double y, int sign) {
      const double P = ((576 * y + 216) * y - 38) * y - 9;
      const double Q = ((((2560 * y + 4096) * y + 1752) * y + 128) * y - 72) * y - 9;
      const double delta = ((160 * y + 324) * y + 108) * y + 9;
      return P * std::sqrt(delta) + sign * 2 * Q;
    };
    double best = std::numeric_limits<double>::quiet_NaN(), best_residual = 1e300;
    constexpr int cells = 1000;
    for (int i = 0; i < cells; ++i) {
      const double a = double(i) / cells, b = double(i + 1) / cells;
      const bool rising = quartic(a) < 0;
      if (rising == (quartic(b) < 0)) continue;
      const double y = bisect([&](double x) { return (quartic(x) < 0) == rising; }, a, b);
      const double residual = std::fabs(unsquared(y, 1)) / (std::fabs(unsquared(y, -1)) + 1e-300);
      if (residual < best_residual) best = y, best_residual = residual;
    }
    return std::sqrt(best);
  }();
  return zeta0;
}

double A_minus() {
  static const double A = off_diagonal_point(lower_curve_zeta0(), -1).A;
  return A;
}

double A_star() { return std::sqrt((1100 + 40 * std::sqrt(601.0)) / 27); }

double alignment_curve_A(double tau) { return std::sqrt(2.0) * std::fabs(3 * std::cos(2 * tau) - 2); }
double alignment_tau1() { return std::atan((std::sqrt(41.0) - 6) / 5); }
double alignment_tau2() { return std::atan((std::sqrt(41.0) + 6) / 5); }

}  // namespace rotorsweep::landscape
