// The field of the slider experiment's substrate, a finite lattice of fixed point dipoles in the xz-plane
// (docs/model.md §9 "Substrate field"): exact direct sum with its first two x-derivatives.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"

namespace rotorsweep::kernels {

/// The substrate in units of the lattice constant a: columns × rows unit moments (cos φ, 0, −sin φ) at
/// (x_offset + k, y_offset + l, −depth) for k < columns, l < rows (φ = angle; 0: along +x).
struct SubstrateLattice {
  std::size_t columns = 35;
  std::size_t rows = 35;
  double x_offset = -14.0;
  double y_offset = -14.0;
  double depth = 0.5;  ///< η = h / a
  double angle = 0.0;  ///< φ, the moments' direction in the xz-plane
};

/// A field component and its first two derivatives along x.
template <class V = double>
struct FieldJet {
  V value = V(0.0), slope = V(0.0), curvature = V(0.0);
};

/// The field (x, y and z components, in units of μ0 m_sub / (4π a³)) of the substrate at (x, y, 0):
/// B = Σ [3 r̂ (m̂·r̂) − m̂] / r³ over the lattice, r from each moment to the point.
template <class V = double>
struct SubstrateFieldAt {
  FieldJet<V> x, y, z;
};

/// The direct sum over every substrate moment, with (X, Y, Z) the point minus the moment and
/// m̂ = cos φ x̂ − sin φ ẑ: the x̂ moments give B_x = Σ (2X² − Y² − Z²)/r⁵, B_y = Σ 3XY/r⁵,
/// B_z = Σ 3XZ/r⁵, the ẑ moments (only summed where φ ≠ 0) B_x = Σ 3XZ/r⁵, B_y = Σ 3YZ/r⁵,
/// B_z = Σ (2Z² − X² − Y²)/r⁵; their x-derivatives in closed form. At lane_width<V> points x at once
/// (IEEE-exact operations only, so every lane holds the bits of the scalar sum). B_y (needed by a turned
/// slider only) is summed where `with_y`, and 0 otherwise.
template <class V = double>
ROTORSWEEP_HD inline SubstrateFieldAt<V> substrate_field(const SubstrateLattice& lattice, V x, double y,
                                                         bool with_y = true) {
  SubstrateFieldAt<V> along_x, along_z;  // the fields of x̂ and of ẑ moments
  const double Z = lattice.depth;
  const bool turned = lattice.angle != 0.0;
  for (std::size_t l = 0; l < lattice.rows; ++l) {
    const double Y = y - (lattice.y_offset + double(l));
    const double rho2 = Y * Y + Z * Z;
    for (std::size_t k = 0; k < lattice.columns; ++k) {
      const V X = x - V(lattice.x_offset + double(k));
      const V r2 = X * X + V(rho2);
      const V inv_r2 = V(1.0) / r2;
      const V q = inv_r2 * inv_r2 / lane_sqrt(r2);  // r⁻⁵
      const V dq = V(-5.0) * X * q * inv_r2;        // d(r⁻⁵)/dX
      const V d2q = (V(-5.0) + V(35.0) * X * X * inv_r2) * q * inv_r2;
      const V numerator = V(2.0) * X * X - V(rho2);
      along_x.x.value += numerator * q;
      along_x.x.slope += V(4.0) * X * q + numerator * dq;
      along_x.x.curvature += V(4.0) * q + V(8.0) * X * dq + numerator * d2q;
      along_x.z.value += V(3.0 * Z) * X * q;
      along_x.z.slope += V(3.0 * Z) * (q + X * dq);
      along_x.z.curvature += V(3.0 * Z) * (V(2.0) * dq + X * d2q);
      if (with_y) {
        along_x.y.value += V(3.0 * Y) * X * q;
        along_x.y.slope += V(3.0 * Y) * (q + X * dq);
        along_x.y.curvature += V(3.0 * Y) * (V(2.0) * dq + X * d2q);
      }
      if (turned) {
        const V z_numerator = V(2.0 * Z * Z - Y * Y) - X * X;
        along_z.z.value += z_numerator * q;
        along_z.z.slope += V(-2.0) * X * q + z_numerator * dq;
        along_z.z.curvature += V(-2.0) * q + V(-4.0) * X * dq + z_numerator * d2q;
        if (with_y) {
          along_z.y.value += V(3.0 * Y * Z) * q;
          along_z.y.slope += V(3.0 * Y * Z) * dq;
          along_z.y.curvature += V(3.0 * Y * Z) * d2q;
        }
      }
    }
  }
  if (!turned) return along_x;
  along_z.x = along_x.z;  // 3XZ/r⁵ both ways
  const V c(std::cos(lattice.angle)), s(std::sin(lattice.angle));
  const auto mix = [&](const FieldJet<V>& a, const FieldJet<V>& b) {
    return FieldJet<V>{c * a.value - s * b.value, c * a.slope - s * b.slope,
                       c * a.curvature - s * b.curvature};
  };
  return {mix(along_x.x, along_z.x), mix(along_x.y, along_z.y), mix(along_x.z, along_z.z)};
}

}  // namespace rotorsweep::kernels
