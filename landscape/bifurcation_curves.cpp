// Parametric forms of the strict-FM, off-diagonal and alignment curves for coefficients (a, b, c),
// folded into τ ∈ [0, π/2], and the CP interval [A_-, A_*] (model.md §5, §8).
#include "landscape/bifurcation_curves.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "landscape/bisection.hpp"

namespace rotorsweep::landscape {

namespace {

constexpr double pi = std::numbers::pi;
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// A cos(χ − τ) = C, A sin(χ − τ) = S  ⇒  A = √(C² + S²), τ = χ − atan2(S, C).
BifurcationPoint from_stationarity(double chi, double C, double S, double parameter) {
  return {std::hypot(C, S), fundamental_phase(chi - std::atan2(S, C)), parameter};
}

/// The quadratic F(x, ζ) = (Px + Q)(Rx − 4b) + K(1 − x²) whose roots are x±(ζ), with its partial
/// derivatives (for dA_L/dζ).
struct DegeneracyQuadratic {
  double P, Q, R, S0, K, dP, dQ, dK;
  DegeneracyQuadratic(double zeta, const TwoAngleCoefficients& k) {
    const double z2 = zeta * zeta, w = 8 * k.a * z2 + 4 * k.a - 2 * k.c;
    P = 8 * k.a * z2 - 8 * k.a + 4 * k.c;
    Q = 4 * k.b * z2;
    R = 8 * k.a;
    S0 = -4 * k.b;
    K = w * w / z2;
    dP = 16 * k.a * zeta;
    dQ = 8 * k.b * zeta;
    dK = 2 * w * 16 * k.a * zeta / z2 - 2 * w * w / (z2 * zeta);
  }
  double root(int sign) const {
    const double lead = K - P * R, linear = -(P * S0 + Q * R), constant = -(Q * S0 + K);
    return (-linear + sign * std::sqrt(linear * linear - 4 * lead * constant)) / (2 * lead);
  }
  /// dx/dζ along the root x: −F_ζ / F_x.
  double slope(double x) const {
    const double F_x = P * (R * x + S0) + R * (P * x + Q) - 2 * K * x;
    const double F_z = (dP * x + dQ) * (R * x + S0) + dK * (1 - x * x);
    return -F_z / F_x;
  }
};

/// d(A_L²)/dζ on the off-diagonal curve `sign`, from A cos(χ − τ) = C(ζ), A sin(χ − τ) = S(ζ).
double squared_A_slope(double zeta, int sign, const TwoAngleCoefficients& k) {
  const DegeneracyQuadratic q(zeta, k);
  const double x = q.root(sign), dx = q.slope(x);
  const double s = std::sqrt(1 - x * x), ds = -x * dx / s;
  const double w = 2 * k.a * (2 * zeta * zeta - 1) + k.c, dw = 8 * k.a * zeta;
  const double C = (4 * k.a * x - 2 * k.b) * zeta, dC = 4 * k.a * dx * zeta + (4 * k.a * x - 2 * k.b);
  const double S = s * w / zeta, dS = ds * w / zeta + s * (dw * zeta - w) / (zeta * zeta);
  return 2 * (C * dC + S * dS);
}

CpInterval compute_cp_interval(const TwoAngleCoefficients& k) {
  const auto AL = [&](double zeta) { return off_diagonal_degenerate_point(zeta, -1, k).A; };
  constexpr int cells = 1000;
  int best = cells;
  for (int i = 1; i < cells; ++i)
    if (AL(double(i) / cells) < AL(double(best) / cells)) best = i;  // NaN (no point) never wins
  CpInterval interval;
  interval.A_star = AL(1);
  if (best == cells || !(AL(double(best) / cells) <= interval.A_star)) {
    interval.zeta0 = 1;  // A_L has no interior minimum: no CP interval
    interval.A_minus = interval.A_star;
    return interval;
  }
  const double lo = double(best - 1) / cells, hi = double(best + 1) / cells;
  interval.zeta0 = bisect([&](double zeta) { return !(squared_A_slope(zeta, -1, k) > 0); }, lo, hi);
  interval.A_minus = AL(interval.zeta0);
  return interval;
}

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

double off_diagonal_cos2chi(double zeta, int sign, const TwoAngleCoefficients& k) {
  return DegeneracyQuadratic(zeta, k).root(sign);
}

DegeneratePoint off_diagonal_degenerate_point(double zeta, int sign, const TwoAngleCoefficients& k) {
  const double x = off_diagonal_cos2chi(zeta, sign, k);
  if (!(x <= 1 && x >= -1)) return {nan, 0, 0, zeta};
  const double chi = 0.5 * std::acos(x);
  const double C = (4 * k.a * x - 2 * k.b) * zeta;
  const double S = (2 * k.a * (2 * zeta * zeta - 1) + k.c) * std::sqrt(1 - x * x) / zeta;
  return {std::hypot(C, S), chi - std::atan2(S, C), chi, zeta};
}

BifurcationPoint off_diagonal_point(double zeta, int sign, const TwoAngleCoefficients& k) {
  const auto p = off_diagonal_degenerate_point(zeta, sign, k);
  return {p.A, fundamental_phase(p.tau), zeta};
}

BifurcationPoint alignment_point(double chi, const TwoAngleCoefficients& k) {
  return from_stationarity(chi, (4 * k.a * std::cos(2 * chi) - 2 * k.b) / std::numbers::sqrt2,
                           std::numbers::sqrt2 * k.c * std::sin(2 * chi), chi);
}

std::vector<BifurcationPoint> sample_curve(Curve curve, int count, double A_max,
                                           const TwoAngleCoefficients& k) {
  std::vector<BifurcationPoint> points;
  points.reserve(count);
  for (int i = 0; i < count; ++i) {
    const double u = count > 1 ? double(i) / (count - 1) : 0.0, chi = 0.5 * pi * u;
    switch (curve) {
      case Curve::fm_tangential:
      case Curve::fm_transverse: {
        const double c = std::cos(2 * chi);
        const double C = curve == Curve::fm_tangential ? (4 * k.a + 2 * k.c) * c : 4 * k.a * c - 2 * k.b;
        points.push_back(from_stationarity(chi, C, (2 * k.a + k.c) * std::sin(2 * chi), chi));
        break;
      }
      case Curve::off_diagonal_plus:
      case Curve::off_diagonal_minus: {
        const double zeta = count > 1 ? (i + 1.0) / count : 1.0;  // ζ = 0 is excluded (A → ∞)
        const auto p = off_diagonal_point(zeta, curve == Curve::off_diagonal_plus ? 1 : -1, k);
        if (std::isfinite(p.A) && p.A <= A_max) points.push_back(p);
        break;
      }
      case Curve::alignment: points.push_back(alignment_point(chi, k)); break;
    }
  }
  return points;
}

const CpInterval& cp_interval(const TwoAngleCoefficients& k) {
  thread_local TwoAngleCoefficients key;
  thread_local CpInterval value = compute_cp_interval(key);
  if (!(key == k)) value = compute_cp_interval(k), key = k;
  return value;
}

std::vector<double> alignment_type_changes(const TwoAngleCoefficients& k) {
  // the ρ = 1/2 point (χ + π/4, χ − π/4) at the curve's (A, τ), τ unfolded
  const auto determinant = [&](double chi) {
    const double C = (4 * k.a * std::cos(2 * chi) - 2 * k.b) / std::numbers::sqrt2;
    const double S = std::numbers::sqrt2 * k.c * std::sin(2 * chi);
    const TwoAngleEnergy h{std::hypot(C, S), chi - std::atan2(S, C), k};
    const auto [ee, eo, oo] = h.hessian(chi + pi / 4, chi - pi / 4);
    return ee * oo - eo * eo;
  };
  std::vector<double> phases;
  constexpr int cells = 2000;
  for (int i = 0; i < cells; ++i) {
    const double lo = 0.5 * pi * i / cells, hi = 0.5 * pi * (i + 1) / cells;
    const bool negative = determinant(lo) < 0;
    if (negative == (determinant(hi) < 0)) continue;
    const double chi = bisect([&](double x) { return (determinant(x) < 0) == negative; }, lo, hi);
    phases.push_back(alignment_point(chi, k).tau);
  }
  return phases;
}

}  // namespace rotorsweep::landscape
