// Enumeration of the critical points of H_r: strict-FM and off-diagonal families from their
// trigonometric polynomials, deduplicated on the torus, classified by the Hessian's signs.
#include "landscape/critical_points.hpp"

#include <algorithm>
#include <cmath>

#include "kernels/lanes/angles.hpp"
#include "landscape/trig_roots.hpp"

namespace rotorsweep::landscape {

namespace {

using kernels::two_pi;
using kernels::wrap_2pi;

double torus_distance(double a, double b) {
  const double d = std::fabs(wrap_2pi(a - b));
  return std::min(d, two_pi - d);
}

void classify(const TwoAngleEnergy& h, CriticalPoint& p) {
  const auto [ee, eo, oo] = h.hessian(p.even, p.odd);
  const double det = ee * oo - eo * eo, trace = ee + oo;
  const double scale = h.k.hessian_scale() + h.A;
  if (std::fabs(det) < 1e-8 * scale * scale)
    p.type = MorseType::degenerate;
  else if (det < 0)
    p.type = MorseType::saddle;
  else
    p.type = trace > 0 ? MorseType::minimum : MorseType::maximum;
  p.energy = h.energy(p.even, p.odd);
  if (p.alignment != AlignmentClass::strict_fm)
    p.alignment = p.rho > 0.5 ? AlignmentClass::fm_like : AlignmentClass::afm_like;
}

}  // namespace

CriticalSet critical_points(const TwoAngleEnergy& h) {
  const double A = h.A, tau = h.tau;
  CriticalSet set;
  const auto add = [&](double even, double odd, AlignmentClass alignment) {
    even = wrap_2pi(even);
    odd = wrap_2pi(odd);
    for (const auto& p : set.points)
      if (torus_distance(p.even, even) < 1e-7 && torus_distance(p.odd, odd) < 1e-7) return;
    CriticalPoint p{even,
                    odd,
                    0,
                    alignment == AlignmentClass::strict_fm ? 1.0 : landscape::alignment(even, odd),
                    MorseType::degenerate,
                    alignment};
    classify(h, p);
    set.points.push_back(p);
  };

  for (double chi : trig_polynomial_roots([&](double x) { return h.strict_fm_stationarity(x); }, 2))
    add(chi, chi, AlignmentClass::strict_fm);

  const double a = h.k.a, b = h.k.b, c = h.k.c;
  const auto denominator = [&](double x) { return 4 * a * std::cos(2 * x) - 2 * b; };
  const auto off_diagonal = [&](double x) {
    const double d = denominator(x), drive = std::cos(x - tau), s = std::sin(2 * x);
    return 4 * a * s * (2 * A * A * drive * drive - d * d) + 2 * c * s * d * d -
           2 * A * A * std::sin(x - tau) * drive * d;
  };
  for (double chi : trig_polynomial_roots(off_diagonal, 6)) {
    const double d = denominator(chi);
    if (std::fabs(d) < 1e-9) {  // ζ undetermined: a one-parameter family, only at isolated (A, τ)
      ++set.degenerate;
      continue;
    }
    const double zeta = A * std::cos(chi - tau) / d;
    if (std::fabs(zeta) >= 1) continue;  // |ζ| = 1 is the strict-FM point itself (pitchfork)
    const double phi = std::acos(zeta);
    add(chi + phi, chi - phi, AlignmentClass::fm_like);
    add(chi - phi, chi + phi, AlignmentClass::fm_like);
  }

  for (const auto& p : set.points) {
    switch (p.type) {
      case MorseType::minimum: ++set.minima; break;
      case MorseType::saddle: ++set.saddles; break;
      case MorseType::maximum: ++set.maxima; break;
      case MorseType::degenerate: ++set.degenerate; break;
    }
  }
  // Morse theory on the torus: #min − #saddle + #max = 0. A set that breaks it lost points the root
  // finders could not resolve (a = b = 0 makes the off-diagonal polynomial vanish identically, and
  // near-degenerate tables merge roots): it is flagged, never reported as a count.
  if (set.degenerate == 0 && set.minima - set.saddles + set.maxima != 0) set.degenerate = 1;
  std::sort(set.points.begin(), set.points.end(),
            [](const CriticalPoint& a, const CriticalPoint& b) { return a.energy < b.energy; });
  return set;
}

}  // namespace rotorsweep::landscape
