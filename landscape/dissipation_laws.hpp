// The small-A (AFM) and large-A (FM) dissipation laws of model.md §4 (paper Sec. "Magnetic
// friction and asymptotic behavior"): energy dissipated per drive period by N rows.
#pragma once

#include <numbers>

namespace rotorsweep::landscape {

/// AFM state, A → 0: D ≈ N π A² g / (100 + g²).
inline double small_A_dissipation(double A, double g, double rows) {
  return rows * std::numbers::pi * A * A * g / (100 + g * g);
}

/// FM state, A → ∞: D ≈ 2π N g + 36 π N g / A².
inline double large_A_dissipation(double A, double g, double rows) {
  return 2 * std::numbers::pi * rows * g + 36 * std::numbers::pi * rows * g / (A * A);
}

}  // namespace rotorsweep::landscape
