// The dense stage solve on a host team (kernels/linear/team_dense_symmetric.hpp) against DenseSymmetric
// itself: the same solution, inertia test and J x bit for bit, dense and banded, for teams of 1 … 32.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/lanes/team.hpp"
#include "kernels/linear/dense_symmetric.hpp"
#include "kernels/linear/team_dense_symmetric.hpp"
#include "support/built_matrix.hpp"

using rotorsweep::kernels::DenseSymmetric;
using rotorsweep::kernels::HostTeam;
using Team = rotorsweep::kernels::TeamDenseSymmetric<HostTeam>;
using rotorsweep::testing::BuiltMatrix;
using rotorsweep::testing::check_same_solve;

namespace {

/// A symmetric J within `band` of the diagonal (with `wrap` also in the ring's corners), entries U(−1, 1)
/// and a diagonal −2 + U(−1, 1), into both matrices.
template <class A, class B>
void draw(A& a, B& b, std::size_t n, std::size_t band, bool wrap, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = j; k < n; ++k) {
      const std::size_t distance = k - j;
      const bool inside = distance <= band || (wrap && distance >= n - band);
      const double x = !inside ? 0.0 : j == k ? -2.0 + u(rng) : u(rng);
      a.entry(j, k) = a.entry(k, j) = x;
      b.entry(j, k) = b.entry(k, j) = x;
    }
}

}  // namespace

TEST_CASE("a team's dense LDLᵀ gives DenseSymmetric's bits: solution, inertia and J x", "[kernels][team]") {
  std::mt19937_64 rng(11);
  std::size_t indefinite = 0, cases = 0;
  for (std::size_t n : {2u, 7u, 20u, 49u})
    for (const auto& [band, wrap] : {std::pair{std::size_t(1000), false}, std::pair{std::size_t(3), true},
                                     std::pair{std::size_t(2), false}})
      for (std::size_t ranks : {1u, 2u, 3u, 8u, 32u})
        for (int draw_index = 0; draw_index < 4; ++draw_index) {
          BuiltMatrix<DenseSymmetric<double>> sequential(n);
          BuiltMatrix<Team, std::size_t> team(n, ranks);
          sequential.matrix.set_band(band, wrap);
          team.matrix.set_band(band, wrap);
          draw(sequential.matrix, team.matrix, n, band, wrap, rng);
          const double shift = draw_index % 2 == 0 ? 4.0 : 0.5;  // definite, or likely not
          INFO("N = " << n << ", band " << band << (wrap ? " (ring)" : "") << ", ranks " << ranks);
          indefinite += !check_same_solve(sequential.matrix, team.matrix, ranks, shift, n, rng);
          ++cases;
        }
  CHECK(indefinite > cases / 8);  // both kinds were tested
}

TEST_CASE("a team's dense solve keeps a strict-FM member's rows equal", "[kernels][team]") {
  const std::size_t n = 12;
  BuiltMatrix<Team, std::size_t> team(n, std::size_t(4));
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t distance = j > k ? j - k : k - j,
                        ring = distance < n - distance ? distance : n - distance;
      team.matrix.entry(j, k) = ring == 0 ? -1.5 : std::ldexp(1.0, -int(ring));  // circulant, exact row sums
    }
  team.matrix.keep_constant_solutions(true);
  HostTeam crew(4);
  team.matrix.factor(crew, 3.0);
  std::vector<double> r(n, 0.7);
  team.matrix.solve(crew, r.data());
  for (std::size_t j = 1; j < n; ++j) CHECK(r[j] == r[0]);
}
