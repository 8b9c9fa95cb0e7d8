// Real roots of trigonometric polynomials: coefficients by an exact discrete Fourier transform
// of samples, roots of z^n P(z) as eigenvalues of the companion matrix (Eigen), then polishing.
#include "landscape/trig_roots.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>

#include "kernels/lanes/angles.hpp"

namespace rotorsweep::landscape {

namespace {

using complex = std::complex<double>;
using kernels::two_pi;

}  // namespace

std::vector<double> trig_polynomial_roots(const std::function<double(double)>& p, int degree,
                                          double tolerance) {
  // Fourier coefficients c_k, |k| <= n, from M > 2n samples (exact for a polynomial of degree n).
  const int n = degree, samples = 4 * degree + 4;
  std::vector<double> values(samples);
  double scale = 0;
  for (int s = 0; s < samples; ++s) {
    values[s] = p(two_pi * s / samples);
    scale = std::max(scale, std::fabs(values[s]));
  }
  std::vector<complex> c(2 * n + 1);  // c[k + n]
  for (int k = -n; k <= n; ++k) {
    complex sum = 0;
    for (int s = 0; s < samples; ++s) sum += values[s] * std::polar(1.0, -two_pi * k * s / samples);
    c[k + n] = sum / double(samples);
  }
  if (scale == 0) return {};
  // Q(z) = Σ c_k z^{k+n}: drop negligible leading coefficients (roots at infinity) and trailing
  // ones (roots at zero); neither lies on the unit circle.
  int top = 2 * n, bottom = 0;
  while (top > 0 && std::abs(c[top]) < 1e-14 * scale) --top;
  while (bottom < top && std::abs(c[bottom]) < 1e-14 * scale) ++bottom;
  const int order = top - bottom;
  std::vector<double> roots;
  if (order == 0) return roots;
  Eigen::MatrixXcd companion = Eigen::MatrixXcd::Zero(order, order);
  for (int i = 1; i < order; ++i) companion(i, i - 1) = 1.0;
  for (int i = 0; i < order; ++i) companion(i, order - 1) = -c[bottom + i] / c[top];
  const Eigen::VectorXcd z = companion.eigenvalues();

  const auto value = [&](double x) { return p(x); };
  const auto slope = [&](double x) {
    complex sum = 0;
    for (int k = -n; k <= n; ++k) sum += complex(0, k) * c[k + n] * std::polar(1.0, k * x);
    return sum.real();
  };
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    if (std::fabs(std::log(std::abs(z(i)))) > 1e-4) continue;  // off the circle: no real root
    double x = std::arg(z(i));
    for (int iteration = 0; iteration < 50; ++iteration) {
      const double d = slope(x);
      if (d == 0) break;
      const double step = value(x) / d;
      x -= step;
      if (std::fabs(step) < 1e-15) break;
    }
    x = kernels::wrap_2pi(x);
    if (std::fabs(value(x)) > tolerance * scale) continue;
    const bool known = std::any_of(roots.begin(), roots.end(), [&](double r) {
      const double d = std::fabs(r - x);
      return std::min(d, two_pi - d) < 1e-7;
    });
    if (!known) roots.push_back(x);
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

}  // namespace rotorsweep::landscape
