// The reference members of the paper's table of dissipation integrals (docs/model.md §3): N = 20,
// g = 0.0011, 2 relaxation periods, 2 averaged, and the paper's R = A ∫ Σ sin(θ_j − t) dt.
#pragma once

#include <array>
#include <cstddef>

#include "ensemble/rows/initial_conditions.hpp"

namespace rotorsweep::ensemble::paper_table {

inline constexpr std::size_t rows = 20;
inline constexpr double g = 0.0011;
inline constexpr int relax_periods = 2;
inline constexpr int average_periods = 2;

struct Entry {
  double A;
  InitialKind kind;
  double paper_R;  ///< the paper's value of D (R estimator)
  bool cp;         ///< in the CP regime: the value depends on the noise draw at the percent level
  double paper_W;  ///< the paper's work estimator A ∫ Σ sin(θ_j − t) θ̇_j dt
  double paper_S;  ///< the paper's Stokes estimator g ∫ Σ θ̇_j² dt
};

inline constexpr std::array<Entry, 10> entries{{
    {1, InitialKind::fm, 2.018948e-3, false, 2.018947e-3, 2.018948e-3},
    {1, InitialKind::afm, 7.184589e-4, false, 7.184587e-4, 7.184589e-4},
    {4, InitialKind::fm, 2.296052e-2, false, 2.296053e-2, 2.296052e-2},
    {4, InitialKind::afm, 2.296052e-2, false, 2.296052e-2, 2.296052e-2},
    {6, InitialKind::fm, 3.407353e1, true, 3.398356e1, 3.315224e1},
    {6, InitialKind::afm, 3.410911e1, true, 3.411337e1, 3.414253e1},
    {8, InitialKind::fm, 5.728856, true, 5.743078, 5.779477},
    {8, InitialKind::afm, 5.697104, true, 5.711672, 5.759762},
    {11, InitialKind::fm, 1.654868e-1, false, 1.654722e-1, 1.654868e-1},
    {11, InitialKind::afm, 1.654868e-1, false, 1.654784e-1, 1.654868e-1},
}};

}  // namespace rotorsweep::ensemble::paper_table
