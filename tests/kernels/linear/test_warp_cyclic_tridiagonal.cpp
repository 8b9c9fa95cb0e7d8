// Tests of the stage solve in registers (kernels/linear/warp_cyclic_tridiagonal.hpp) on the host's
// emulation of a warp: against a dense LU of the same ring for every lane count and every way N rows
// fill the lanes' slots, its definiteness against the matrix's eigenvalues, and strict-FM invariance.
#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "kernels/lanes/warp.hpp"
#include "kernels/linear/warp_cyclic_tridiagonal.hpp"
#include "support/dense_reference.hpp"

using namespace rotorsweep::kernels;

namespace {

/// A ring of n rows: J's diagonal and the links j → j + 1 (mod n).
struct Ring {
  std::vector<double> diag, off;
  Eigen::MatrixXd stage_matrix(double shift) const {
    const auto n = Eigen::Index(diag.size());
    Eigen::MatrixXd m = shift * Eigen::MatrixXd::Identity(n, n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const Eigen::Index k1 = (k + 1) % n;
      m(k, k) -= diag[std::size_t(k)];
      m(k, k1) -= off[std::size_t(k)];
      m(k1, k) -= off[std::size_t(k)];
    }
    return m;
  }
};

Ring random_ring(std::size_t n, std::mt19937_64& rng, double coupling = 0.9) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Ring ring;
  for (std::size_t j = 0; j < n; ++j) {
    ring.diag.push_back(-2.0 + u(rng));
    ring.off.push_back(coupling * u(rng));
  }
  return ring;
}

/// The ring's solve in a member of L lanes with R slots each; returns x by ring index.
template <std::size_t L, std::size_t R>
struct WarpSolve {
  using W = HostWarp<L>;
  using V = typename W::value;
  WarpRowSlots<W, R> slots;
  WarpCyclicTridiagonal<W, R> matrix;

  WarpSolve(const Ring& ring, double shift, bool keep_constant = false) : slots(ring.diag.size()) {
    each_slot([&](std::size_t r, std::size_t l, std::size_t j, bool real) {
      lane_set(matrix.diag[r], l, real ? ring.diag[j] : 0.0);
      lane_set(matrix.off[r], l, real ? ring.off[j] : 0.0);
    });
    matrix.keep_constant_solutions(keep_constant);
    matrix.factor(slots, V(shift));
  }

  std::vector<double> solve(const std::vector<double>& rhs) const {
    V x[R];
    for (auto& v : x) v = V(0.0);
    each_slot([&](std::size_t r, std::size_t l, std::size_t j, bool real) { lane_set(x[r], l, real ? rhs[j] : 0.0); });
    matrix.solve(slots, x);
    std::vector<double> out(rhs.size());
    each_slot([&](std::size_t r, std::size_t l, std::size_t j, bool real) {
      if (real) out[j] = lane_get(x[r], l);
      else CHECK(lane_get(x[r], l) == 0.0);  // padding stays 0
    });
    return out;
  }

  /// f(slot, lane, ring index, real) over every slot of every lane.
  template <class F>
  void each_slot(F&& f) const {
    for (std::size_t l = 0; l < L; ++l)
      for (std::size_t r = 0; r < R; ++r)
        f(r, l, std::size_t(lane_get(slots.row(r), l)), mask_get(slots.real(r), l));
  }
};

template <std::size_t L, std::size_t R>
void check_against_dense(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t n = L; n <= L * R; ++n) {
    for (double shift : {3.0, 40.0, 1e4}) {
      const Ring ring = random_ring(n, rng);
      std::vector<double> rhs(n);
      for (auto& x : rhs) x = u(rng);
      const Eigen::VectorXd expected =
          rotorsweep::testing::dense_solve(ring.stage_matrix(shift), Eigen::Map<const Eigen::VectorXd>(rhs.data(), Eigen::Index(n)));
      const WarpSolve<L, R> warp(ring, shift);
      CHECK(warp.matrix.positive_definite());  // shift > 3 ≥ every eigenvalue of J here
      const auto x = warp.solve(rhs);
      for (std::size_t j = 0; j < n; ++j) {
        INFO("L = " << L << ", R = " << R << ", N = " << n << ", shift " << shift << ", row " << j);
        CHECK(x[j] == Approx(expected(Eigen::Index(j))).epsilon(1e-12).margin(1e-14));
      }
    }
  }
}

template <std::size_t L, std::size_t R>
void check_definiteness(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int definite = 0, indefinite = 0;
  for (std::size_t n = L; n <= L * R; ++n) {
    for (int trial = 0; trial < 6; ++trial) {
      const Ring ring = random_ring(n, rng, 2.0);
      const double shift = u(rng);  // near J's spectrum: some stage matrices indefinite
      const Eigen::VectorXd eigenvalues = rotorsweep::testing::symmetric_eigenvalues(ring.stage_matrix(shift));
      if (std::fabs(eigenvalues.minCoeff()) < 1e-6) continue;  // too close to call
      const bool expected = eigenvalues.minCoeff() > 0;
      (expected ? definite : indefinite) += 1;
      INFO("L = " << L << ", R = " << R << ", N = " << n << ", smallest eigenvalue " << eigenvalues.minCoeff());
      CHECK(WarpSolve<L, R>(ring, shift).matrix.positive_definite() == expected);
    }
  }
  CHECK(indefinite > 0);
  CHECK(definite + indefinite > 0);
}

}  // namespace

TEST_CASE("the stage solve in registers matches a dense LU for every way rows fill the lanes",
          "[kernels][linear][warp]") {
  std::mt19937_64 rng(23);
  check_against_dense<1, 2>(rng);
  check_against_dense<1, 4>(rng);
  check_against_dense<2, 3>(rng);
  check_against_dense<4, 5>(rng);
  check_against_dense<8, 3>(rng);
  check_against_dense<16, 4>(rng);
  check_against_dense<32, 2>(rng);
}

TEST_CASE("the stage solve in registers reports an indefinite stage matrix", "[kernels][linear][warp]") {
  std::mt19937_64 rng(31);
  check_definiteness<1, 3>(rng);
  check_definiteness<2, 2>(rng);
  check_definiteness<4, 3>(rng);
  check_definiteness<8, 3>(rng);
}

TEST_CASE("the stage solve in registers keeps all-equal rows equal where asked", "[kernels][linear][warp]") {
  // every row alike (a strict-FM member): a constant right-hand side gives the constant r / (σ - d - 2o)
  const std::size_t n = 20;
  const Ring ring{std::vector<double>(n, -1.7), std::vector<double>(n, 0.6)};
  const double shift = 12.5, r0 = 0.3;
  const WarpSolve<8, 3> kept(ring, shift, true);
  for (const double x : kept.solve(std::vector<double>(n, r0))) CHECK(x == r0 * (1.0 / (shift + 1.7 - 1.2)));
  // a right-hand side that is not constant takes the general solve
  std::vector<double> rhs(n, r0);
  rhs[7] = 0.31;
  const Eigen::VectorXd expected =
      rotorsweep::testing::dense_solve(ring.stage_matrix(shift), Eigen::Map<const Eigen::VectorXd>(rhs.data(), Eigen::Index(n)));
  const auto x = kept.solve(rhs);
  for (std::size_t j = 0; j < n; ++j) CHECK(x[j] == Approx(expected(Eigen::Index(j))).epsilon(1e-12));
}
