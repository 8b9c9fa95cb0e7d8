// The field of an infinite substrate lattice by its Fourier series (docs/model.md §9 "An infinite
// substrate"): B = Σ_G A_G e^{iG·ρ} e^{−|G|η} over the reciprocal lattice, converging as e^{−2π|G|η/a}.
#pragma once

#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

#include "kernels/models/slider/substrate_field.hpp"
#include "kernels/models/slider/substrate_table.hpp"

namespace rotorsweep::kernels {

/// Unit moments (cos φ, 0, −sin φ) at (x_offset + k, y_offset + l, −η) for every integer k, l (units of a).
/// With S = Σ 1/|r − r_kl| = Σ_{G≠0} (2π/|G|) e^{−|G|(z + η)} e^{iG·(ρ − ρ₀)} (Poisson summation; the G = 0
/// term is linear in z and adds no field), the field B = (m̂·∇)∇S is Σ_G A_G e^{iG·(ρ − ρ₀)} with
///   A_G = (iG_x, iG_y, −|G|) μ_G (2π/|G|) e^{−|G|η},   μ_G = i cos φ G_x + sin φ |G|,   G = 2π (p, q),
/// real since A_{−G} is A_G's conjugate. Terms are kept while e^{−(|G| − 2π)η} (|G|/2π)⁴ exceeds 1e-18 of the
/// first (the curvature's |G|² and the field's |G|² at most), so the sums are exact to rounding. The field
/// is periodic in x and y with period a: every unturned track sees the same field.
class InfiniteSubstrate {
 public:
  InfiniteSubstrate(double depth, double angle, double tilt = 0.0, double x_offset = 0.0,
                    double y_offset = 0.0)
      : depth_(depth), angle_(angle), tilt_(tilt), x_offset_(x_offset), y_offset_(y_offset) {
    const double two_pi = 6.283185307179586;
    for (order_ = 1;; ++order_) {
      const double p = double(order_);
      if (two_pi * (p - 1.0) * depth > std::log(1e18) + 4.0 * std::log(p)) break;
    }
  }

  /// The number of harmonics each way.
  std::size_t order() const { return order_; }

  /// B (x, y and z, with their first two x-derivatives) at (x, y) on the plane η above the moments.
  SubstrateFieldAt<> field_at(double x, double y) const {
    const auto c = coefficients(y);
    SubstrateFieldAt<> f;
    const double two_pi = 6.283185307179586;
    for (std::size_t p = 0; p <= order_; ++p) {
      const double gx = two_pi * double(p);
      const std::complex<double> e = std::polar(1.0, gx * (x - x_offset_));
      const auto add = [&](FieldJet<>& jet, const std::complex<double>& a) {
        const std::complex<double> term = a * e;
        jet.value += term.real();
        jet.slope += (std::complex<double>(0.0, gx) * term).real();
        jet.curvature += -gx * gx * term.real();
      };
      add(f.x, c[3 * p]);
      add(f.y, c[3 * p + 1]);
      add(f.z, c[3 * p + 2]);
    }
    return f;
  }

  /// B_∥ (cos τ B_x + sin τ B_y) and B_z at the nodes x_begin + i/m, i ≤ intervals, on the track at y: one
  /// period of m nodes summed, the others its repeats.
  void track_nodes(double y, double x_begin, std::size_t m, std::vector<TableNode>& nodes) const {
    const double c = std::cos(tilt_), s = std::sin(tilt_);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (i >= m) {
        nodes[i] = nodes[i % m];
        continue;
      }
      const SubstrateFieldAt<> f = field_at(x_begin + double(i) / double(m), y);
      nodes[i].along = {c * f.x.value + s * f.y.value, c * f.x.slope + s * f.y.slope,
                        c * f.x.curvature + s * f.y.curvature};
      nodes[i].z = f.z;
    }
  }

 private:
  /// Per harmonic p ≥ 0 along x, the sums over q of A_(p,q) e^{2πiq(y − y₀)} for B_x, B_y and B_z
  /// ([3p], [3p + 1], [3p + 2]), each pair ±G counted once with weight 2.
  std::vector<std::complex<double>> coefficients(double y) const {
    const double two_pi = 6.283185307179586;
    const int order = int(order_);
    std::vector<std::complex<double>> c(3 * (order_ + 1));
    const std::complex<double> i(0.0, 1.0);
    for (int p = 0; p <= order; ++p)
      for (int q = p == 0 ? 1 : -order; q <= order; ++q) {
        const double gx = two_pi * p, gy = two_pi * q, g = std::sqrt(gx * gx + gy * gy);
        const std::complex<double> mu = i * std::cos(angle_) * gx + std::sin(angle_) * g;
        const std::complex<double> weight =
            2.0 * (two_pi / g) * std::exp(-g * depth_) * mu * std::polar(1.0, gy * (y - y_offset_));
        c[3 * std::size_t(p)] += i * gx * weight;
        c[3 * std::size_t(p) + 1] += i * gy * weight;
        c[3 * std::size_t(p) + 2] += -g * weight;
      }
    return c;
  }

  double depth_, angle_, tilt_, x_offset_, y_offset_;
  std::size_t order_ = 1;
};

}  // namespace rotorsweep::kernels
