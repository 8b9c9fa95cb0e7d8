// Coupling tables of the row model beyond nearest neighbours (docs/model.md §8): the anisotropy a
// and the row couplings b_u, c_u of H = Σ_j[−a cos 2θ_j] + Σ_j Σ_u [b_u cos(θ_j − θ_{j+u}) − c_u cos(θ_j +
// θ_{j+u})].
#pragma once

#include <cstddef>
#include <vector>

namespace rotorsweep::ensemble {

struct CouplingTable {
  double a = 1.5;
  std::vector<double> b{1.0}, c{0.0};  ///< b[u − 1], c[u − 1] for u = 1 .. range
  std::size_t range() const { return b.size(); }
};

/// Today's model: a = 3/2, b_1 = 1, c_1 = 0.
CouplingTable nearest_neighbour_table();

/// Point dipoles on a square lattice of spacing 1, moments in the xz-plane, rows uniform along x:
/// the energy per rotor of a row of `row_length` rotors (0: an infinite row), for rows u = 1 .. range
/// apart. A pair offset by (k, u), r² = k² + u², has r⁻³[(1 − 3k²/2r²) cos(θ1 − θ2) − (3k²/2r²)
/// cos(θ1 + θ2)]; a finite row weighs offset k by its share of pairs, (L − |k|)/L.
CouplingTable dipolar_table(std::size_t range, std::size_t row_length);

/// The two-angle reduction with periodic rows alternating θe, θo: H_r = −a_M[cos 2θe + cos 2θo] +
/// b_M cos(θe − θo) − c_M cos(θe + θo) + A[…], with a_M = a + Σ_{u even} c_u, b_M = 2 Σ_{u odd} b_u,
/// c_M = 2 Σ_{u odd} c_u (nearest neighbours: 3/2, 2, 0).
struct TwoAngleCoefficients {
  double a = 1.5, b = 2.0, c = 0.0;
};
TwoAngleCoefficients two_angle_coefficients(const CouplingTable& table);

/// The interaction energy of one moment with every other moment of the 2-D lattice inside the square
/// of half-width `half_width` (in units of the nearest-neighbour pair energy), all moments along the
/// rows (FM) or rows alternating (AFM): the check against the nearest-neighbour values −2 and −6.
double lattice_energy_per_moment(std::size_t half_width, bool antiferromagnetic);

}  // namespace rotorsweep::ensemble
