// The two-angle energy landscape H_r(θe, θo; A, τ) of model.md §5 (paper Sec. "Rigorous
// prediction of the dynamical states"): energy, gradient, Hessian, alignment ρ = cos²((θe-θo)/2).
#pragma once

#include <array>
#include <cmath>

namespace rotorsweep::landscape {

/// H_r = -3/2 [cos 2θe + cos 2θo] + 2 cos(θe - θo) + A [cos(θe - τ) + cos(θo - τ)],
/// the N = 2 row model at drive phase τ.
struct TwoAngleEnergy {
  double A = 0;
  double tau = 0;

  double energy(double even, double odd) const {
    return -1.5 * (std::cos(2 * even) + std::cos(2 * odd)) + 2 * std::cos(even - odd) +
           A * (std::cos(even - tau) + std::cos(odd - tau));
  }

  /// (∂H/∂θe, ∂H/∂θo)
  std::array<double, 2> gradient(double even, double odd) const {
    const double link = 2 * std::sin(even - odd);
    return {3 * std::sin(2 * even) - link - A * std::sin(even - tau),
            3 * std::sin(2 * odd) + link - A * std::sin(odd - tau)};
  }

  /// ∂H/∂θe = ∂H/∂θo on the diagonal θe = θo = χ: 3 sin 2χ − A sin(χ − τ), the trigonometric
  /// polynomial of degree 2 whose roots are the strict-FM critical points.
  double strict_fm_stationarity(double chi) const { return 3 * std::sin(2 * chi) - A * std::sin(chi - tau); }

  /// (H_ee, H_eo, H_oo)
  std::array<double, 3> hessian(double even, double odd) const {
    const double link = 2 * std::cos(even - odd);
    return {6 * std::cos(2 * even) - link - A * std::cos(even - tau), link,
            6 * std::cos(2 * odd) - link - A * std::cos(odd - tau)};
  }
};

/// ρ = cos²((θe - θo)/2): 1 strict FM, > 1/2 FM-like, < 1/2 AFM-like.
inline double alignment(double even, double odd) {
  const double c = std::cos(0.5 * (even - odd));
  return c * c;
}

}  // namespace rotorsweep::landscape
