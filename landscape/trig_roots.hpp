// Every real root of a real trigonometric polynomial P(χ) = Σ_{|k|<=n} c_k e^{ikχ} on [0, 2π):
// the roots of the algebraic polynomial z^n P(z) on the unit circle, from its companion matrix.
#pragma once

#include <functional>
#include <vector>

namespace rotorsweep::landscape {

/// Roots in [0, 2π) of the trigonometric polynomial `p` of degree at most `degree`, each
/// polished by Newton's method and kept only if |p| there is below `tolerance` × max|p|.
/// Complete: the companion matrix yields all 2·degree complex roots, and a real root of p is
/// one of them on the unit circle. Double roots (tangencies) come out once.
std::vector<double> trig_polynomial_roots(const std::function<double(double)>& p, int degree,
                                          double tolerance = 1e-10);

}  // namespace rotorsweep::landscape
