// The bifurcation set and the alignment curve of H_r in the (A, τ) plane for any coefficients (a, b, c)
// (model.md §5, §8): parametric forms (paper Eqs. offdiag_xpm, FM_param_curves, alignment_curve for
// nearest neighbours) and the CP interval [A_-, A_*] on the lower off-diagonal curve.
#pragma once

#include <string_view>
#include <vector>

#include "landscape/two_angle_energy.hpp"

namespace rotorsweep::landscape {

/// τ folded into the fundamental domain [0, π/2] with H_r's symmetries τ → τ + π (θ → θ + π)
/// and τ → −τ (θ → −θ). The fold is continuous, so folded curves stay connected.
double fundamental_phase(double tau);

enum class Curve { fm_tangential, fm_transverse, off_diagonal_plus, off_diagonal_minus, alignment };
inline constexpr Curve all_curves[] = {Curve::fm_tangential, Curve::fm_transverse, Curve::off_diagonal_plus,
                                       Curve::off_diagonal_minus, Curve::alignment};
std::string_view curve_name(Curve curve);

/// A point of one of the curves in the folded (A, τ) plane.
struct BifurcationPoint {
  double A = 0;
  double tau = 0;        ///< in [0, π/2]
  double parameter = 0;  ///< χ for the strict-FM and alignment curves, ζ off-diagonal
};

/// x±(ζ) = cos 2χ on the off-diagonal degeneracy curves: the roots of the quadratic
/// (Px + Q)(Rx − 4b) + K(1 − x²) = 0, P = 8aζ² − 8a + 4c, Q = 4bζ², R = 8a, K = (8aζ² + 4a − 2c)²/ζ²,
/// that the Hessian's determinant at an off-diagonal critical point gives (model.md §8); nearest
/// neighbours: [4ζ² ± √(160ζ⁶ + 324ζ⁴ + 108ζ² + 9)] / [3(8ζ² + 1)].
double off_diagonal_cos2chi(double zeta, int sign, const TwoAngleCoefficients& k = {});

/// The degenerate off-diagonal critical point with parameter ζ ∈ (0, 1] and its (A, τ), τ not
/// folded: χ = ½ arccos x±(ζ), A cos(χ − τ) = (4ax − 2b)ζ, A sin(χ − τ) = [2a(2ζ² − 1) + c] sin 2χ / ζ.
/// A = NaN where |x±(ζ)| > 1.
struct DegeneratePoint {
  double A = 0, tau = 0, chi = 0, zeta = 0;
};
DegeneratePoint off_diagonal_degenerate_point(double zeta, int sign, const TwoAngleCoefficients& k = {});

/// The same point on the folded curve.
BifurcationPoint off_diagonal_point(double zeta, int sign, const TwoAngleCoefficients& k = {});

/// `count` points of a curve, uniform in its parameter: χ ∈ [0, π/2] (strict FM and alignment;
/// χ → −χ and χ → χ + π give the same folded points), ζ ∈ (0, 1] (off-diagonal, only where
/// |x±| ≤ 1 and A ≤ A_max).
std::vector<BifurcationPoint> sample_curve(Curve curve, int count, double A_max = 1e300,
                                           const TwoAngleCoefficients& k = {});

/// The CP interval on the lower off-diagonal curve A_L(ζ) = A of x_−: A_- = A_L(ζ0), its minimum
/// (ζ0 from the sign change of dA_L/dζ, differentiated in closed form), and A_* = A_L(1), where
/// B_off^- meets the transverse strict-FM curve. Nearest neighbours: 4.6345834669803, 8.7783657758836.
struct CpInterval {
  double zeta0 = 0, A_minus = 0, A_star = 0;
};
/// Computed once per thread and coefficients (the last ones asked for are kept).
const CpInterval& cp_interval(const TwoAngleCoefficients& k = {});
inline double lower_curve_zeta0(const TwoAngleCoefficients& k = {}) { return cp_interval(k).zeta0; }
inline double A_minus(const TwoAngleCoefficients& k = {}) { return cp_interval(k).A_minus; }
inline double A_star(const TwoAngleCoefficients& k = {}) { return cp_interval(k).A_star; }

/// The alignment curve (a critical point with ρ = 1/2) at χ: A cos(χ − τ) = (4a cos 2χ − 2b)/√2,
/// A sin(χ − τ) = √2 c sin 2χ; nearest neighbours: A = √2 |3 cos 2τ − 2|, χ = τ.
BifurcationPoint alignment_point(double chi, const TwoAngleCoefficients& k = {});

/// Folded phases where the alignment curve's ρ = 1/2 point changes Morse type (its Hessian is
/// singular), in increasing χ; nearest neighbours: τ1 = arctan((√41 − 6)/5), τ2 = arctan((√41 + 6)/5)
/// split it into maximum, saddle and minimum segments.
std::vector<double> alignment_type_changes(const TwoAngleCoefficients& k = {});

}  // namespace rotorsweep::landscape
