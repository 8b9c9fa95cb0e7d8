// The team solve of the cyclic tridiagonal stage matrix (kernels/linear/team_cyclic_tridiagonal.hpp) on
// a host team: against a dense Eigen LU for rings of 2 … 1024 rows and teams of 1 … 32 ranks (chains of
// every length, empty ones included), its positive-definiteness against M's eigenvalues, and the
// strict-FM closed form; and the host team's blocks and butterfly sums (kernels/lanes/team.hpp).
#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "kernels/lanes/team.hpp"
#include "kernels/linear/team_cyclic_tridiagonal.hpp"
#include "support/dense_reference.hpp"

using rotorsweep::kernels::HostTeam;
using rotorsweep::kernels::LaneArena;
using rotorsweep::kernels::team_rows;
using Solver = rotorsweep::kernels::TeamCyclicTridiagonal<HostTeam>;
using Catch::Detail::Approx;

namespace {

/// A solver over its own storage.
struct Built {
  std::vector<double> storage;
  LaneArena<double> arena;
  Solver solver;
  Built(std::size_t n, std::size_t ranks)
      : storage(Solver::storage_size(n, ranks)),
        arena(storage.data(), storage.size()),
        solver(n, ranks, arena) {}
};

/// shift·I − J as a dense matrix, and J's entries drawn: diagonal −2 + U(−1, 1), links 0.9 U(−1, 1).
Eigen::MatrixXd draw(Solver& J, std::size_t n, double shift, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd m = shift * Eigen::MatrixXd::Identity(Eigen::Index(n), Eigen::Index(n));
  for (std::size_t k = 0; k < n; ++k) {
    J.diag(k) = -2.0 + u(rng);
    J.off(k) = 0.9 * u(rng);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const auto i = Eigen::Index(k), i1 = Eigen::Index((k + 1) % n);
    m(i, i) -= J.diag(k);
    m(i, i1) -= J.off(k);
    m(i1, i) -= J.off(k);
  }
  return m;
}

}  // namespace

TEST_CASE("team rows: contiguous blocks covering the ring, lengths within one", "[kernels][team]") {
  for (std::size_t n : {2u, 7u, 20u, 1024u})
    for (std::size_t size : {1u, 2u, 3u, 8u, 32u}) {
      if (size > n) continue;
      std::size_t next = 0, shortest = n, longest = 0;
      for (std::size_t rank = 0; rank < size; ++rank) {
        const auto rows = team_rows(n, size, rank);
        CHECK(rows.begin == next);
        next = rows.end;
        shortest = std::min(shortest, rows.size());
        longest = std::max(longest, rows.size());
      }
      CHECK(next == n);
      CHECK(longest - shortest <= 1);
      CHECK(shortest >= 1);
    }
}

TEST_CASE("a host team sums in a warp's butterfly order", "[kernels][team]") {
  // values whose sum depends on the order of additions
  const std::vector<double> v{1e16, 1.0, -1e16, 1.0, 3.0, 1e-3, 7.0, -2.5, 1e15, 4.0};
  HostTeam eight(8);
  const double tree = ((v[0] + v[4]) + (v[2] + v[6])) + ((v[1] + v[5]) + (v[3] + v[7]));
  CHECK(eight.sum([&](std::size_t r) { return v[r]; }) == tree);
  HostTeam ten(10);  // ranks 8 and 9 fold onto 0 and 1 first
  const double folded = (((v[0] + v[8]) + v[4]) + (v[2] + v[6])) + (((v[1] + v[9]) + v[5]) + (v[3] + v[7]));
  CHECK(ten.sum([&](std::size_t r) { return v[r]; }) == folded);
  CHECK(HostTeam(1).sum([&](std::size_t r) { return v[r]; }) == v[0]);
}

TEST_CASE("the team solve matches a dense LU for every ring and team size", "[kernels][team][linear]") {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t n : {2u, 3u, 4u, 5u, 7u, 8u, 20u, 21u, 64u, 127u, 1024u})
    for (std::size_t ranks : {1u, 2u, 3u, 4u, 8u, 16u, 32u}) {
      if (ranks > n) continue;
      for (double shift : {3.0, 40.0, 1e4}) {
        Built built(n, ranks);
        Solver& J = built.solver;
        const Eigen::MatrixXd M = draw(J, n, shift, rng);
        Eigen::VectorXd r{Eigen::Index(n)};
        for (auto& x : r) x = u(rng);
        const Eigen::VectorXd expected = rotorsweep::testing::dense_solve(M, r);
        HostTeam team(ranks);
        J.factor(team, shift);
        std::vector<double> x(r.data(), r.data() + n);
        J.solve(team, x.data());
        for (std::size_t k = 0; k < n; ++k) {
          INFO("n = " << n << ", ranks = " << ranks << ", shift = " << shift << ", k = " << k);
          CHECK(x[k] == Approx(expected(Eigen::Index(k))).epsilon(1e-12).margin(1e-14));
        }
        CHECK(J.positive_definite());  // shift > 3 ≥ every eigenvalue of these J
      }
    }
}

TEST_CASE("the team's positive definiteness is M's, by its eigenvalues", "[kernels][team][linear]") {
  std::mt19937_64 rng(23);
  std::size_t indefinite = 0;
  for (int trial = 0; trial < 200; ++trial)
    for (std::size_t n : {2u, 5u, 20u})
      for (std::size_t ranks : {1u, 2u, 4u}) {
        if (ranks > n) continue;
        const double shift = -1.9 + 0.02 * trial / 10.0;  // near J's top eigenvalues: either answer
        Built built(n, ranks);
        const Eigen::MatrixXd M = draw(built.solver, n, shift, rng);
        HostTeam team(ranks);
        built.solver.factor(team, shift);
        const bool definite = rotorsweep::testing::symmetric_eigenvalues(M).minCoeff() > 0;
        INFO("n = " << n << ", ranks = " << ranks << ", trial " << trial);
        CHECK(built.solver.positive_definite() == definite);
        indefinite += !definite;
      }
  CHECK(indefinite > 50);  // both answers were asked for
}

TEST_CASE("a circulant M keeps constant solutions exactly constant", "[kernels][team][linear]") {
  for (std::size_t ranks : {1u, 3u, 8u}) {
    const std::size_t n = 20;
    Built built(n, ranks);
    Solver& J = built.solver;
    for (std::size_t k = 0; k < n; ++k) {
      J.diag(k) = -1.7;
      J.off(k) = 0.3;
    }
    J.keep_constant_solutions(true);
    HostTeam team(ranks);
    J.factor(team, 7.0);
    std::vector<double> x(n, 0.37);
    J.solve(team, x.data());
    for (std::size_t k = 0; k < n; ++k) CHECK(x[k] == 0.37 * (1.0 / (7.0 + 1.7 - 0.6)));
  }
}
