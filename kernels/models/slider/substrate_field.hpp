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

/// One moment's field at (X, Y, Z), the point minus the moment, added to the sums `along_x` (an x̂ moment's:
/// B_x = (2X² − Y² − Z²)/r⁵, B_y = 3XY/r⁵, B_z = 3XZ/r⁵) and, where `turned` (a substrate angle φ ≠ 0),
/// `along_z` (a ẑ moment's B_y = 3YZ/r⁵, B_z = (2Z² − X² − Y²)/r⁵; its B_x, 3XZ/r⁵, is along_x's B_z), each
/// with its first two x-derivatives in closed form; B_y only `with_y`. IEEE-exact operations only.
template <class V>
ROTORSWEEP_HD inline void add_moment_field(const V& X, double Y, double Z, bool turned, bool with_y,
                                           SubstrateFieldAt<V>& along_x, SubstrateFieldAt<V>& along_z) {
  const double rho2 = Y * Y + Z * Z;
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

/// The field of moments (cos φ, 0, −sin φ) from the sums of x̂ and ẑ moments' fields (add_moment_field).
template <class V>
ROTORSWEEP_HD inline SubstrateFieldAt<V> mixed_moment_field(double angle, SubstrateFieldAt<V> along_x,
                                                            SubstrateFieldAt<V> along_z) {
  if (angle == 0.0) return along_x;
  along_z.x = along_x.z;  // 3XZ/r⁵ both ways
  const V c(std::cos(angle)), s(std::sin(angle));
  const auto mix = [&](const FieldJet<V>& a, const FieldJet<V>& b) {
    return FieldJet<V>{c * a.value - s * b.value, c * a.slope - s * b.slope,
                       c * a.curvature - s * b.curvature};
  };
  return {mix(along_x.x, along_z.x), mix(along_x.y, along_z.y), mix(along_x.z, along_z.z)};
}

/// The direct sum over every substrate moment (add_moment_field, then mixed_moment_field) at lane_width<V>
/// points x at once (IEEE-exact operations only, so every lane holds the bits of the scalar sum). B_y
/// (needed by a turned slider only) is summed where `with_y`, and 0 otherwise.
template <class V = double>
ROTORSWEEP_HD inline SubstrateFieldAt<V> substrate_field(const SubstrateLattice& lattice, V x, double y,
                                                         bool with_y = true) {
  SubstrateFieldAt<V> along_x, along_z;  // the fields of x̂ and of ẑ moments
  const double Z = lattice.depth;
  const bool turned = lattice.angle != 0.0;
  for (std::size_t l = 0; l < lattice.rows; ++l) {
    const double Y = y - (lattice.y_offset + double(l));
    for (std::size_t k = 0; k < lattice.columns; ++k)
      add_moment_field(x - V(lattice.x_offset + double(k)), Y, Z, turned, with_y, along_x, along_z);
  }
  return mixed_moment_field(lattice.angle, along_x, along_z);
}

}  // namespace rotorsweep::kernels
