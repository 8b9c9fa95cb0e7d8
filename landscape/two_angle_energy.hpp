// The two-angle energy landscape H_r(θe, θo; A, τ) of model.md §5 and §8 (the paper's Sec. "Rigorous
// prediction of the dynamical states", any coupling table): energy, gradient, Hessian, alignment ρ.
#pragma once

#include <array>
#include <cmath>

namespace rotorsweep::landscape {

/// The coefficients of H_r = −a[cos 2θe + cos 2θo] + b cos(θe − θo) − c cos(θe + θo) + A[…]:
/// periodic rows alternating θe, θo with a coupling table reduce to a_M, b_M, c_M (model.md §8);
/// nearest neighbours give (3/2, 2, 0).
struct TwoAngleCoefficients {
  double a = 1.5, b = 2.0, c = 0.0;
  bool operator==(const TwoAngleCoefficients&) const = default;
  /// A bound on the Hessian's entries without the drive (10 for nearest neighbours): the scale of
  /// "singular" in the Morse classification.
  double hessian_scale() const { return 4 * std::fabs(a) + 2 * std::fabs(b) + 2 * std::fabs(c); }
};

/// H_r = −a [cos 2θe + cos 2θo] + b cos(θe − θo) − c cos(θe + θo) + A [cos(θe − τ) + cos(θo − τ)],
/// the N = 2 row model (or the reduction of periodic rows) at drive phase τ.
struct TwoAngleEnergy {
  double A = 0;
  double tau = 0;
  TwoAngleCoefficients k{};

  double energy(double even, double odd) const {
    return -k.a * (std::cos(2 * even) + std::cos(2 * odd)) + k.b * std::cos(even - odd) -
           k.c * std::cos(even + odd) + A * (std::cos(even - tau) + std::cos(odd - tau));
  }

  /// (∂H/∂θe, ∂H/∂θo)
  std::array<double, 2> gradient(double even, double odd) const {
    const double link = k.b * std::sin(even - odd), sum = k.c * std::sin(even + odd);
    return {2 * k.a * std::sin(2 * even) - link + sum - A * std::sin(even - tau),
            2 * k.a * std::sin(2 * odd) + link + sum - A * std::sin(odd - tau)};
  }

  /// ∂H/∂θe = ∂H/∂θo on the diagonal θe = θo = χ: (2a + c) sin 2χ − A sin(χ − τ), the trigonometric
  /// polynomial of degree 2 whose roots are the strict-FM critical points.
  double strict_fm_stationarity(double chi) const {
    return (2 * k.a + k.c) * std::sin(2 * chi) - A * std::sin(chi - tau);
  }

  /// (H_ee, H_eo, H_oo)
  std::array<double, 3> hessian(double even, double odd) const {
    const double link = k.b * std::cos(even - odd), sum = k.c * std::cos(even + odd);
    return {4 * k.a * std::cos(2 * even) - link + sum - A * std::cos(even - tau), link + sum,
            4 * k.a * std::cos(2 * odd) - link + sum - A * std::cos(odd - tau)};
  }
};

/// ρ = cos²((θe - θo)/2): 1 strict FM, > 1/2 FM-like, < 1/2 AFM-like.
inline double alignment(double even, double odd) {
  const double c = std::cos(0.5 * (even - odd));
  return c * c;
}

}  // namespace rotorsweep::landscape
