// The field of the slider experiment's substrate, a finite lattice of fixed point dipoles along +x
// (docs/model.md §9 "Substrate field"): exact direct sum with its first two x-derivatives.
#pragma once

#include <cmath>
#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"

namespace rotorsweep::kernels {

/// The substrate in units of the lattice constant a: columns × rows unit moments along +x at
/// (x_offset + k, y_offset + l, −depth) for k < columns, l < rows.
struct SubstrateLattice {
  std::size_t columns = 35;
  std::size_t rows = 35;
  double x_offset = -14.0;
  double y_offset = -14.0;
  double depth = 0.5;  ///< η = h / a
};

/// A field component and its first two derivatives along x.
template <class V = double>
struct FieldJet {
  V value = V(0.0), slope = V(0.0), curvature = V(0.0);
};

/// The field (x and z components, in units of μ0 m_sub / (4π a³)) of the substrate at (x, y, 0):
/// B = Σ [3 r̂ (x̂·r̂) − x̂] / r³ over the lattice, r from each moment to the point.
template <class V = double>
struct SubstrateFieldAt {
  FieldJet<V> x, z;
};

/// The direct sum over every substrate moment: B_x = Σ (2X² − Y² − Z²)/r⁵, B_z = Σ 3XZ/r⁵ with
/// (X, Y, Z) the point minus the moment, and their x-derivatives in closed form; at lane_width<V>
/// points x at once (IEEE-exact operations only, so every lane holds the bits of the scalar sum).
template <class V = double>
ROTORSWEEP_HD inline SubstrateFieldAt<V> substrate_field(const SubstrateLattice& lattice, V x, double y) {
  SubstrateFieldAt<V> field;
  const double Z = lattice.depth;
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
      field.x.value += numerator * q;
      field.x.slope += V(4.0) * X * q + numerator * dq;
      field.x.curvature += V(4.0) * q + V(8.0) * X * dq + numerator * d2q;
      field.z.value += V(3.0 * Z) * X * q;
      field.z.slope += V(3.0 * Z) * (q + X * dq);
      field.z.curvature += V(3.0 * Z) * (V(2.0) * dq + X * d2q);
    }
  }
  return field;
}

}  // namespace rotorsweep::kernels
