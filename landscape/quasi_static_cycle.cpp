// The quasi-static cycle: Newton continuation of a minimum of H_r in τ, bisection of where it ends,
// and the gradient flow (linearly implicit Euler steps) from there to the next minimum.
#include "landscape/quasi_static_cycle.hpp"

#include <cmath>
#include <numbers>
#include <optional>

namespace rotorsweep::landscape {

namespace {

using Point = std::array<double, 2>;
constexpr double two_pi = 2 * std::numbers::pi;

double scale(const TwoAngleEnergy& h) { return h.k.hessian_scale() + std::fabs(h.A); }

bool positive_definite(const std::array<double, 3>& H) { return H[0] > 0 && H[0] * H[2] - H[1] * H[1] > 0; }

/// Newton's method from p: a minimum within `reach` rad of `anchor` (default: of p), if the iterates
/// stay there and converge to a point with a positive definite Hessian.
std::optional<Point> newton_minimum(const TwoAngleEnergy& h, Point p, double reach = 0.3,
                                    std::optional<Point> anchor = std::nullopt) {
  const Point start = anchor.value_or(p);
  for (int i = 0; i < 40; ++i) {
    const auto [ge, go] = h.gradient(p[0], p[1]);
    const auto H = h.hessian(p[0], p[1]);
    const double det = H[0] * H[2] - H[1] * H[1];
    if (det == 0) return std::nullopt;
    const double de = (H[2] * ge - H[1] * go) / det, dodd = (H[0] * go - H[1] * ge) / det;
    p = {p[0] - de, p[1] - dodd};
    if (!(std::hypot(p[0] - start[0], p[1] - start[1]) < reach)) return std::nullopt;
    if (std::hypot(de, dodd) < 1e-13) {
      const auto [fe, fo] = h.gradient(p[0], p[1]);
      if (std::hypot(fe, fo) > 1e-9 * scale(h) || !positive_definite(h.hessian(p[0], p[1])))
        return std::nullopt;
      return p;
    }
  }
  return std::nullopt;
}

/// The minimum p continued from phase `from` to `to`: Newton from the tangent predictor
/// p + (to − from) dθ/dτ, dθ/dτ = −H⁻¹ ∂τ∇H, then from p itself. The minimum may move at most
/// 0.05 rad, so that Newton never slips onto another branch: a larger move is a smaller step's job.
std::optional<Point> continue_minimum(const TwoAngleEnergy& from, double to, Point p) {
  const auto H = from.hessian(p[0], p[1]);
  const double det = H[0] * H[2] - H[1] * H[1];
  const double drive_even = from.A * std::cos(p[0] - from.tau),
               drive_odd = from.A * std::cos(p[1] - from.tau);
  Point move{-(H[2] * drive_even - H[1] * drive_odd) / det * (to - from.tau),
             -(H[0] * drive_odd - H[1] * drive_even) / det * (to - from.tau)};
  const double length = std::hypot(move[0], move[1]);
  if (!(length <= 0.05))
    move = length > 0 ? Point{move[0] * 0.05 / length, move[1] * 0.05 / length} : Point{0, 0};
  TwoAngleEnergy target = from;
  target.tau = to;
  if (const auto m = newton_minimum(target, {p[0] + move[0], p[1] + move[1]}, 0.05, p)) return m;
  return newton_minimum(target, p, 0.05);
}

/// Eigenvalues (ascending) and the unit eigenvector of the smaller one of a symmetric 2×2 matrix.
struct Eigen2 {
  double low, high;
  Point soft;
  explicit Eigen2(const std::array<double, 3>& H) {
    const double mean = 0.5 * (H[0] + H[2]), radius = std::hypot(0.5 * (H[0] - H[2]), H[1]);
    low = mean - radius, high = mean + radius;
    // (H − low) v = 0: v ∝ (H_eo, low − H_ee), or (low − H_oo, H_eo)
    Point v =
        std::fabs(H[0] - low) > std::fabs(H[2] - low) ? Point{H[1], low - H[0]} : Point{low - H[2], H[1]};
    const double n = std::hypot(v[0], v[1]);
    soft = n > 0 ? Point{v[0] / n, v[1] / n} : Point{1, 0};
  }
};

/// The gradient flow θ' = −∇H from p to the minimum it reaches: linearly implicit Euler steps
/// (I/dt + H₊)Δ = −∇H, H₊ the Hessian with negative eigenvalues set to 0, of at most 0.02 rad; a
/// point where the gradient vanishes off a minimum is left along the softest direction, downhill.
Point descend(const TwoAngleEnergy& h, Point p) {
  const double dt = 1e4 / scale(h);  // large: fast along stable directions, the step cap keeps the path
  for (int i = 0; i < 1000000; ++i) {
    const auto [ge, go] = h.gradient(p[0], p[1]);
    const auto H = h.hessian(p[0], p[1]);
    const double gradient = std::hypot(ge, go);
    if (positive_definite(H) && gradient < 1e-4 * scale(h))
      if (const auto m = newton_minimum(h, p)) return *m;
    const Eigen2 e(H);
    if (gradient < 1e-12 * scale(h)) {  // a critical point that is no minimum: leave it downhill
      const Point a{p[0] + 1e-3 * e.soft[0], p[1] + 1e-3 * e.soft[1]};
      const Point b{p[0] - 1e-3 * e.soft[0], p[1] - 1e-3 * e.soft[1]};
      p = h.energy(a[0], a[1]) <= h.energy(b[0], b[1]) ? a : b;
      continue;
    }
    const Point hard{-e.soft[1], e.soft[0]};
    const double gs = ge * e.soft[0] + go * e.soft[1], gh = ge * hard[0] + go * hard[1];
    const double ds = -gs / (1 / dt + std::max(e.low, 0.0)), dh = -gh / (1 / dt + std::max(e.high, 0.0));
    Point step{ds * e.soft[0] + dh * hard[0], ds * e.soft[1] + dh * hard[1]};
    const double length = std::hypot(step[0], step[1]);
    if (length > 0.02) step = {step[0] * 0.02 / length, step[1] * 0.02 / length};
    p = {p[0] + step[0], p[1] + step[1]};
  }
  return p;
}

}  // namespace

QuasiStaticCycle quasi_static_cycle(double A, const TwoAngleCoefficients& k, double even, double odd,
                                    int periods) {
  QuasiStaticCycle cycle;
  cycle.A = A;
  const auto at = [&](double tau) { return TwoAngleEnergy{A, tau, k}; };
  constexpr int steps = 1000;
  const double dtau = two_pi / steps;
  Point p = descend(at(0), {even, odd});
  Point period_start = p;
  double rho_sum = 0, dropped = 0;
  for (int period = 0; period < periods; ++period) {
    const bool recorded = period == periods - 1;
    if (recorded) period_start = p;
    for (int i = 0; i < steps; ++i) {
      double tau = two_pi * period + dtau * i;
      const double target = tau + dtau;
      while (tau < target) {
        if (const auto m = continue_minimum(at(tau), target, p)) {
          p = *m, tau = target;
          break;
        }
        // the followed minimum ends in (tau, target]: bisect to the last phase it is found
        double ok = tau, lost = target;
        while (lost - ok > 1e-13 * (1 + std::fabs(ok))) {
          const double mid = 0.5 * (ok + lost);
          if (const auto m = continue_minimum(at(ok), mid, p))
            ok = mid, p = *m;
          else
            lost = mid;
        }
        const Point reached = descend(at(lost), p);
        const auto polished = newton_minimum(at(ok), reached);
        const Point after = polished ? *polished : reached;
        const QuasiStaticJump jump{ok, at(ok).energy(p[0], p[1]), at(ok).energy(after[0], after[1]),
                                   alignment(p[0], p[1]), alignment(after[0], after[1])};
        // Newton lost the minimum before it ended (near a fold): the flow returns to the same branch
        const bool same_branch = std::hypot(after[0] - p[0], after[1] - p[1]) < 1e-3;
        if (recorded && !same_branch) {
          cycle.jumps.push_back(jump);
          dropped += jump.energy_before - jump.energy_after;
        }
        p = reached, tau = lost;
      }
      if (recorded) rho_sum += alignment(p[0], p[1]);
    }
  }
  const auto same_angle = [](double a, double b) { return std::fabs(std::remainder(a - b, two_pi)) < 1e-6; };
  cycle.periodic = same_angle(p[0], period_start[0]) && same_angle(p[1], period_start[1]);
  cycle.J = 0.5 * dropped;
  cycle.mean_rho = rho_sum / steps;
  return cycle;
}

}  // namespace rotorsweep::landscape
