// Every critical point of H_r(·; A, τ) on the torus with its Morse type and alignment class
// (model.md §5), found by reducing the gradient equations to two trigonometric polynomials.
#pragma once

#include <vector>

#include "landscape/two_angle_energy.hpp"

namespace rotorsweep::landscape {

enum class MorseType { minimum, saddle, maximum, degenerate };
enum class AlignmentClass { strict_fm, fm_like, afm_like };

struct CriticalPoint {
  double even = 0, odd = 0;  ///< θe, θo in [0, 2π)
  double energy = 0;
  double rho = 1;  ///< alignment cos²((θe - θo)/2)
  MorseType type = MorseType::degenerate;
  AlignmentClass alignment = AlignmentClass::strict_fm;
};

struct CriticalSet {
  std::vector<CriticalPoint> points;
  int minima = 0, saddles = 0, maxima = 0, degenerate = 0;
  /// #min − #saddle + #max = 0, the Euler characteristic of the torus (Morse theory); only
  /// binding when no point is degenerate, and critical_points() flags a set that breaks it as
  /// degenerate (unresolved), so this holds for every set it returns.
  bool euler_consistent() const { return degenerate > 0 || minima - saddles + maxima == 0; }
};

/// All critical points. With θe = χ + φ, θo = χ − φ the gradient splits into
///   sin φ · [(4a cos 2χ − 2b) cos φ − A cos(χ − τ)] = 0   and
///   (4a cos 2φ + 2c) sin 2χ − 2A sin(χ − τ) cos φ = 0
/// (nearest neighbours: 4a cos 2χ − 2b = 6 cos 2χ − 4, c = 0).
/// Strict FM (sin φ = 0): (2a + c) sin 2χ = A sin(χ − τ), a trigonometric polynomial of degree 2.
/// Off-diagonal: ζ = cos φ = A cos(χ − τ) / (4a cos 2χ − 2b), and the second equation times
/// (4a cos 2χ − 2b)² is a trigonometric polynomial of degree 6 in χ; each root with |ζ| < 1
/// gives the two points (χ ± φ, χ ∓ φ). Both polynomials are solved completely
/// (trig_polynomial_roots), so no critical point is missed.
CriticalSet critical_points(const TwoAngleEnergy& h);

}  // namespace rotorsweep::landscape
