// Test support: a stage matrix (sequential, or a team's with its ranks) over storage of its own, as
// the stage solves' tests build them side by side.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels/lanes/lane_arena.hpp"

namespace rotorsweep::testing {

/// Matrix(size, ranks..., arena) over a fresh vector of Matrix::storage_size(size) values.
template <class Matrix, class... Ranks>
struct BuiltMatrix {
  std::vector<double> storage;
  kernels::LaneArena<double> arena;
  Matrix matrix;
  explicit BuiltMatrix(std::size_t size, Ranks... ranks)
      : storage(Matrix::storage_size(size)),
        arena(storage.data(), storage.size()),
        matrix(size, ranks..., arena) {}
};

}  // namespace rotorsweep::testing
