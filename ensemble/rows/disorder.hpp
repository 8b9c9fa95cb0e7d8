// Quenched disorder of a member (docs/model.md §7): per-row relative deviations of the substrate
// strength, the anisotropy and the row coupling, drawn or given by the scene's [disorder] section.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rotorsweep::ensemble {

/// What the scene asks for. Each quantity is either drawn (σ > 0: δ_j = σ ξ_j, ξ_j standard
/// normal) or given per row (a list whose length divides N, repeated), never both.
struct Disorder {
  double A = 0, anisotropy = 0, coupling = 0;  ///< σ of each quantity
  std::uint64_t seed = 1;                      ///< the realizations' own seed
  std::vector<double> A_rows, anisotropy_rows, coupling_rows;

  /// Whether a realization depends on the replica (some σ > 0).
  bool drawn() const { return A > 0 || anisotropy > 0 || coupling > 0; }
  bool any() const {
    return A > 0 || anisotropy > 0 || coupling > 0 || !A_rows.empty() || !anisotropy_rows.empty() ||
           !coupling_rows.empty();
  }
};

/// The deviations of one array: δ_j (A), α_j (anisotropy), β_j (coupling of rows j and j+1);
/// empty where that quantity has no disorder.
struct RowDeviations {
  std::vector<double> A, anisotropy, coupling;
};

/// The realization of `replica` for N = rows: drawn ones come from the counter-based stream
/// (disorder.seed, replica), row j of quantity q from draws 2(3j + q) and 2(3j + q) + 1 (Box–Muller),
/// so replica r is the same array at every A, g and initial kind, and N rows are the first N of
/// a longer array.
RowDeviations row_deviations(const Disorder& disorder, std::size_t rows, int replica);

}  // namespace rotorsweep::ensemble
