// Test support: a stage matrix (sequential, or a team's with its ranks) over storage of its own, and
// the check that a team's solve gives the sequential one's bits, as the stage solves' tests use them.
#pragma once

#include <catch2/catch.hpp>
#include <cstddef>
#include <random>
#include <vector>

#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"

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

/// Forms y + J x with `one` and `team` (the same matrix) for x of `size` values U(−1, 1), factors
/// both at `shift` and solves with x as the right-hand side (the team on a host team of `ranks`), and
/// checks that the team's J x, solution and inertia test are `one`'s bit for bit; returns whether `one`
/// was definite.
template <class One, class Team>
bool check_same_solve(One& one, Team& team, std::size_t ranks, double shift, std::size_t size,
                      std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  kernels::HostTeam crew(ranks);
  std::vector<double> r(size), x(size), y(size, 0.25), y_team(size, 0.25);
  for (double& v : r) v = u(rng);
  one.multiply_add(r.data(), y.data());  // J x before the factor takes J's place
  team.multiply_add(crew, r.data(), y_team.data());
  one.factor(shift);
  team.factor(crew, shift);
  x = r;
  one.solve(x.data());
  team.solve(crew, r.data());
  CHECK(r == x);
  CHECK(y_team == y);
  CHECK(team.positive_definite() == bool(one.positive_definite()));
  return bool(one.positive_definite());
}

}  // namespace rotorsweep::testing
