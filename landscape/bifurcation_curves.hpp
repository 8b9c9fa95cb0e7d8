// The bifurcation set and the alignment curve of H_r in the (A, τ) plane, in the paper's closed
// parametric forms (model.md §5; paper Eqs. offdiag_xpm, offdiag_param_*, FM_param_curves, alignment_curve).
#pragma once

#include <string_view>
#include <vector>

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
  double parameter = 0;  ///< χ for the strict-FM curves, ζ off-diagonal, τ for the alignment curve
};

/// x±(ζ) = cos 2χ on the off-diagonal degeneracy curves:
/// [4ζ² ± √(160ζ⁶ + 324ζ⁴ + 108ζ² + 9)] / [3(8ζ² + 1)].
double off_diagonal_cos2chi(double zeta, int sign);

/// The degenerate off-diagonal critical point with parameter ζ ∈ (0, 1] and its (A, τ), τ not
/// folded: χ = ½ arccos x±(ζ), A cos(χ − τ) = 2ζ(3x − 2), A sin(χ − τ) = 3(2ζ² − 1) sin 2χ / ζ.
/// A = NaN where x±(ζ) > 1.
struct DegeneratePoint {
  double A = 0, tau = 0, chi = 0, zeta = 0;
};
DegeneratePoint off_diagonal_degenerate_point(double zeta, int sign);

/// The same point on the folded curve.
BifurcationPoint off_diagonal_point(double zeta, int sign);

/// `count` points of a curve, uniform in its parameter: χ ∈ [0, π/2] (strict FM; χ → −χ and
/// χ → χ + π give the same folded points), ζ ∈ (0, 1] (off-diagonal, only where x± ≤ 1 and
/// A ≤ A_max), τ ∈ [0, π/2] (alignment).
std::vector<BifurcationPoint> sample_curve(Curve curve, int count, double A_max = 1e300);

/// A_- = min over ζ of the lower off-diagonal curve A_L(ζ): ζ0² is the root of
/// 256y⁴ − 384y³ + 16y² + 54y − 9 that satisfies the unsquared stationarity condition.
double lower_curve_zeta0();
double A_minus();
/// A_* = A_L(1) = √((1100 + 40√601)/27), where B_off^- meets the transverse strict-FM curve.
double A_star();

/// The alignment curve A = √2 |3 cos 2τ − 2| splits at τ1 = arctan((√41 − 6)/5) and
/// τ2 = arctan((√41 + 6)/5) into maximum, saddle and minimum segments.
double alignment_curve_A(double tau);
double alignment_tau1();
double alignment_tau2();

}  // namespace rotorsweep::landscape
