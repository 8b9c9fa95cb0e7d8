// The paper's recipe for J(A): transverse event in closed form, post-jump states selected as the
// lowest minima among all critical points (chamber selection), lower event by inverting A_L(ζ).
#include "landscape/jump_friction.hpp"

#include <cmath>
#include <limits>

#include "landscape/bifurcation_curves.hpp"
#include "landscape/bisection.hpp"
#include "landscape/critical_points.hpp"
#include "landscape/trig_roots.hpp"
#include "landscape/two_angle_energy.hpp"

namespace rotorsweep::landscape {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double lower_curve_zeta(double A) {
  if (!(A >= A_minus() && A <= A_star())) return nan;
  const auto below = [&](double zeta) { return off_diagonal_degenerate_point(zeta, -1).A < A; };
  return bisect(below, lower_curve_zeta0(), 1);
}

JumpEvents jump_events(double A) {
  JumpEvents e{A, nan, nan, nan, nan, nan, nan, nan, nan, nan};
  if (!(A >= A_minus() && A <= A_star())) return e;

  const double root = std::sqrt(3 * A * A - 11);
  const double cT = (8 - root) / 9, chi_T = 0.5 * std::acos(cT);
  e.tau_transverse = chi_T - std::atan2(3 * std::sin(2 * chi_T), 2 * (3 * cT - 2));
  e.energy_fm_transverse = 2 - root;
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& p : critical_points({A, e.tau_transverse}).points)
    if (p.alignment != AlignmentClass::strict_fm && p.type != MorseType::saddle &&
        p.type != MorseType::maximum && p.energy < lowest) {
      lowest = p.energy;
      e.zeta_landing = std::sqrt(p.rho);
    }
  e.landing_transverse = lowest;

  e.zeta_low = lower_curve_zeta(A);
  const auto lower = off_diagonal_degenerate_point(e.zeta_low, -1);
  e.tau_low = lower.tau;
  e.energy_low = (3 * std::cos(2 * lower.chi) - 2) * (1 + 2 * e.zeta_low * e.zeta_low);
  lowest = std::numeric_limits<double>::infinity();
  const TwoAngleEnergy h{A, e.tau_low};
  for (double chi : trig_polynomial_roots([&](double x) { return h.strict_fm_stationarity(x); }, 2))
    lowest = std::min(lowest, h.energy(chi, chi));
  e.landing_low = lowest;

  e.J = (e.energy_fm_transverse - e.landing_transverse) + (e.energy_low - e.landing_low);
  return e;
}

}  // namespace rotorsweep::landscape
