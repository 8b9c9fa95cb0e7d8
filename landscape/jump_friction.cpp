// The paper's recipe for J(A), any coefficients (a, b, c): transverse event in closed form, post-jump
// states selected as the lowest minima among all critical points (chamber selection), lower event
// by inverting A_L(ζ).
#include "landscape/jump_friction.hpp"

#include <cmath>
#include <limits>

#include "landscape/bifurcation_curves.hpp"
#include "landscape/bisection.hpp"
#include "landscape/critical_points.hpp"
#include "landscape/trig_roots.hpp"

namespace rotorsweep::landscape {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

bool in_cp_interval(double A, const TwoAngleCoefficients& k) {
  const auto& interval = cp_interval(k);
  return A >= interval.A_minus && A <= interval.A_star && interval.A_minus < interval.A_star;
}

}  // namespace

double lower_curve_zeta(double A, const TwoAngleCoefficients& k) {
  if (!in_cp_interval(A, k)) return nan;
  const auto below = [&](double zeta) { return off_diagonal_degenerate_point(zeta, -1, k).A < A; };
  return bisect(below, lower_curve_zeta0(k), 1);
}

JumpEvents jump_events(double A, const TwoAngleCoefficients& k) {
  JumpEvents e{A, nan, nan, nan, nan, nan, nan, nan, nan, nan};
  if (!in_cp_interval(A, k)) return e;

  // (16a² − (2a + c)²) x² − 16ab x + 4b² + (2a + c)² − A² = 0, smaller root
  const double fm = 2 * k.a + k.c, lead = 16 * k.a * k.a - fm * fm, half_linear = 8 * k.a * k.b;
  const double constant = 4 * k.b * k.b + fm * fm - A * A;
  const double cT = (half_linear - std::sqrt(half_linear * half_linear - lead * constant)) / lead;
  const double chi_T = 0.5 * std::acos(cT);
  e.tau_transverse = chi_T - std::atan2(fm * std::sin(2 * chi_T), 4 * k.a * cT - 2 * k.b);
  e.energy_fm_transverse = (6 * k.a - k.c) * cT - 3 * k.b;
  // landing: the lowest off-diagonal minimum below the strict-FM point (the branches that the
  // pitchfork itself sprouts start at its energy and are no landing)
  const double drop_floor = e.energy_fm_transverse - 1e-12 * (k.hessian_scale() + A);
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& p : critical_points({A, e.tau_transverse, k}).points)
    if (p.alignment != AlignmentClass::strict_fm && p.type != MorseType::saddle &&
        p.type != MorseType::maximum && p.energy < lowest && p.energy < drop_floor) {
      lowest = p.energy;
      e.zeta_landing = std::sqrt(p.rho);
    }
  e.landing_transverse = lowest;

  e.zeta_low = lower_curve_zeta(A, k);
  const auto lower = off_diagonal_degenerate_point(e.zeta_low, -1, k);
  e.tau_low = lower.tau;
  const double x = std::cos(2 * lower.chi), z2 = e.zeta_low * e.zeta_low;
  e.energy_low = x * (4 * k.a * z2 + 2 * k.a - k.c) - k.b * (2 * z2 + 1);
  lowest = std::numeric_limits<double>::infinity();
  const TwoAngleEnergy h{A, e.tau_low, k};
  for (double chi : trig_polynomial_roots([&](double y) { return h.strict_fm_stationarity(y); }, 2))
    lowest = std::min(lowest, h.energy(chi, chi));
  e.landing_low = lowest;

  // no off-diagonal minimum to land on at the transverse event: the recipe's sequence does not occur
  // (quasi_static_cycle follows what does)
  if (!std::isfinite(e.landing_transverse)) {
    if (A == cp_interval(k).A_star) e.J = 0;  // at A_* both events coalesce on the strict-FM point
    return e;
  }
  e.J = (e.energy_fm_transverse - e.landing_transverse) + (e.energy_low - e.landing_low);
  return e;
}

}  // namespace rotorsweep::landscape
