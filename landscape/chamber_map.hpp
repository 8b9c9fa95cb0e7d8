// The chamber map of H_r (any coefficients a, b, c): a raster over (A, τ ∈ [0, π/2]) of Morse signatures
// and alignment classes (model.md §5, §8; paper Fig. "Chamber decomposition"), with its connected zones
// counted.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "landscape/two_angle_energy.hpp"

namespace rotorsweep::landscape {

struct ChamberGrid {
  double A_min = 0, A_max = 12;
  int A_cells = 400, tau_cells = 300;  ///< τ spans [0, π/2]; values at cell centres
  TwoAngleCoefficients k{};            ///< the landscape's coefficients (nearest neighbours by default)
};

/// Counts of the critical points at one cell, on the torus (an exchange pair (θe, θo), (θo, θe)
/// counts twice; the paper counts it once).
struct ChamberCell {
  std::int8_t minima = 0, saddles = 0, maxima = 0, degenerate = 0;
  /// by Morse type (minimum, saddle, maximum) × alignment class (strict FM, FM-like, AFM-like)
  std::array<std::array<std::int8_t, 3>, 3> by_type_and_class{};
  bool operator==(const ChamberCell&) const = default;
  bool same_morse_signature(const ChamberCell& o) const {
    return minima == o.minima && saddles == o.saddles && maxima == o.maxima;
  }
};

struct ChamberMap {
  ChamberGrid grid;
  std::vector<double> A, tau;      ///< cell centres
  std::vector<ChamberCell> cells;  ///< row-major, A_cells × tau_cells
  /// Connected components (4-neighbour) of equal Morse signature ("zones", labelled 0…) and of
  /// equal signature and alignment ("chambers"); −1 where a cell holds a degenerate point.
  std::vector<std::int32_t> zone, chamber;
  int zones = 0, chambers = 0;
  /// Components of at least `min_cells` cells: one-cell slivers along curves that pass close to
  /// cell centres are not chambers.
  int zones_at_least(int min_cells) const;
  int chambers_at_least(int min_cells) const;
  const ChamberCell& at(int i, int j) const { return cells[std::size_t(i) * grid.tau_cells + j]; }
};

ChamberCell chamber_cell(double A, double tau, const TwoAngleCoefficients& k = {});

/// All cells (OpenMP over A rows), then the connected components. `rows_done`, if given, is
/// called (serialised) with the number of finished A rows.
ChamberMap chamber_map(const ChamberGrid& grid, const std::function<void(int)>& rows_done = {});

}  // namespace rotorsweep::landscape
