// Coupling tables of the row model beyond nearest neighbours (docs/model.md §8): the anisotropy a
// and the row couplings b_u, c_u of H = Σ_j[−a cos 2θ_j] + Σ_j Σ_u [b_u cos(θ_j − θ_{j+u}) − c_u cos(θ_j +
// θ_{j+u})].
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "landscape/two_angle_energy.hpp"

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
/// cos(θ1 + θ2)]; a finite row weighs offset k by its share of pairs, (L − |k|)/L. `progress(u)`
/// is called after row distance u (long tables: each u sums every offset of a row).
CouplingTable dipolar_table(std::size_t range, std::size_t row_length,
                            const std::function<void(std::size_t)>& progress = {});

/// The model section's couplings as a scene gives them (docs/model.md §1 "Extended couplings"):
/// nearest neighbours, point dipoles over a range of rows, or an explicit table; periodic or open rows.
struct RowCouplings {
  enum class Kind { nearest, dipolar, table };
  Kind kind = Kind::nearest;
  std::size_t range = 1;       ///< dipolar: rows u = 1 .. range apart
  bool all_rows = false;       ///< dipolar: range "all" (every row of the array)
  std::size_t row_length = 0;  ///< dipolar: rotors per row; 0 is an infinite row
  CouplingTable table;         ///< kind table: as given
  bool open = false;           ///< open rows: pairs across an edge are dropped

  /// The largest range `rows` rows allow: N − 1 open, N/2 periodic (minimum image).
  static std::size_t largest_range(std::size_t rows, bool open) { return open ? rows - 1 : rows / 2; }
  /// The table for N = rows: range "all" resolved to largest_range. Periodic rows are a ring, each
  /// pair at its shortest distance: a partner exactly N/2 away is reached both ways round, so its
  /// b and c are halved (each pair once). Nearest neighbours keep today's model as it is (at N = 2
  /// its two links join the same rows: the two-angle reduction).
  CouplingTable for_rows(std::size_t rows) const;
};

/// The two-angle reduction with periodic rows alternating θe, θo: H_r = −a_M[cos 2θe + cos 2θo] +
/// b_M cos(θe − θo) − c_M cos(θe + θo) + A[…], with a_M = a + Σ_{u even} c_u, b_M = 2 Σ_{u odd} b_u,
/// c_M = 2 Σ_{u odd} c_u (nearest neighbours: 3/2, 2, 0).
using landscape::TwoAngleCoefficients;
TwoAngleCoefficients two_angle_coefficients(const CouplingTable& table);

/// The interaction energy of one moment with every other moment of the 2-D lattice inside the square
/// of half-width `half_width` (in units of the nearest-neighbour pair energy), all moments along the
/// rows (FM) or rows alternating (AFM): the check against the nearest-neighbour values −2 and −6.
double lattice_energy_per_moment(std::size_t half_width, bool antiferromagnetic);

}  // namespace rotorsweep::ensemble
