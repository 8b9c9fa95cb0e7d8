// Tests of the cyclic tridiagonal solve (kernels/linear/cyclic_tridiagonal.hpp) against a dense
// Eigen LU on the same matrix, for every size down to the two-row case (where the two-chain
// elimination has no chains) and for chains of equal and unequal length.
#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <random>

#include "kernels/linear/cyclic_tridiagonal.hpp"
#include "support/kernel_scratch.hpp"
#include "support/dense_reference.hpp"

using rotorsweep::kernels::CyclicTridiagonal;

namespace {

Eigen::MatrixXd dense_jacobian(const CyclicTridiagonal<double>& J) {
  const auto n = Eigen::Index(J.size());
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index k1 = (k + 1) % n;
    m(k, k) += J.diag(std::size_t(k));
    m(k, k1) += J.off(std::size_t(k));
    m(k1, k) += J.off(std::size_t(k));
  }
  return m;
}

}  // namespace

TEST_CASE("cyclic tridiagonal solve matches a dense LU", "[kernels][linear]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t n : {2u, 3u, 4u, 5u, 6u, 7u, 8u, 20u, 21u, 64u}) {  // both chains empty, one, uneven, even
    for (double shift : {3.0, 40.0, 1e4}) {
      auto J = rotorsweep::testing::jacobian<CyclicTridiagonal<double>>(n);
      for (std::size_t k = 0; k < n; ++k) {
        J.diag(k) = -2.0 + u(rng);  // negative definite-ish, as near stable states
        J.off(k) = 0.9 * u(rng);
      }
      const Eigen::MatrixXd M =
          shift * Eigen::MatrixXd::Identity(Eigen::Index(n), Eigen::Index(n)) - dense_jacobian(J);
      Eigen::VectorXd r{Eigen::Index(n)};
      for (auto& x : r) x = u(rng);
      const Eigen::VectorXd expected = rotorsweep::testing::dense_solve(M, r);

      J.factor(shift);
      std::vector<double> x(r.data(), r.data() + n);
      J.solve(x.data());
      for (std::size_t k = 0; k < n; ++k) {
        INFO("n=" << n << " shift=" << shift << " k=" << k);
        CHECK(x[k] == Approx(expected(Eigen::Index(k))).epsilon(1e-12).margin(1e-14));
      }
    }
  }
}

TEST_CASE("cyclic tridiagonal product matches the dense matrix", "[kernels][linear]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t n : {2u, 3u, 6u}) {
    auto J = rotorsweep::testing::jacobian<CyclicTridiagonal<double>>(n);
    for (std::size_t k = 0; k < n; ++k) {
      J.diag(k) = u(rng);
      J.off(k) = u(rng);
    }
    Eigen::VectorXd x{Eigen::Index(n)};
    for (auto& v : x) v = u(rng);
    const Eigen::VectorXd expected = dense_jacobian(J) * x;
    std::vector<double> y(n, 0.0);
    J.multiply_add(x.data(), y.data());
    for (std::size_t k = 0; k < n; ++k) CHECK(y[k] == Approx(expected(Eigen::Index(k))).epsilon(1e-14));
  }
}

TEST_CASE("marked lanes keep all-equal solutions exactly equal", "[kernels][linear][symmetry]") {
  for (std::size_t n : {2u, 3u, 20u, 1024u}) {
    auto J = rotorsweep::testing::jacobian<CyclicTridiagonal<double>>(n);
    for (std::size_t k = 0; k < n; ++k) {
      J.diag(k) = -2.7;
      J.off(k) = 0.3;
    }
    const double shift = 1e3 / 7;
    std::vector<double> plain(n, 0.1), kept(n, 0.1);
    J.factor(shift);
    J.solve(plain.data());
    J.keep_constant_solutions(true);
    J.factor(shift);
    J.solve(kept.data());
    INFO("n=" << n);
    const double exact = 0.1 / (shift + 2.7 - 2 * 0.3);
    for (std::size_t k = 0; k < n; ++k) {
      CHECK(kept[k] == kept[0]);                        // bitwise equal rows
      CHECK(kept[k] == Approx(exact).epsilon(1e-15));   // the closed form
      CHECK(plain[k] == Approx(exact).epsilon(1e-13));  // elimination: equal to rounding only
    }
    // a right-hand side that is not constant takes the ordinary elimination
    std::vector<double> varied(n, 0.1), expected(n, 0.1);
    varied[n / 2] = expected[n / 2] = 0.2;
    J.solve(varied.data());
    J.keep_constant_solutions(false);
    J.factor(shift);
    J.solve(expected.data());
    CHECK(varied == expected);
  }
}

TEST_CASE("negative pivots flag eigenvalues of J above the shift (Sylvester inertia)", "[kernels][linear]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int indefinite = 0, definite = 0;
  for (std::size_t n : {2u, 3u, 8u, 33u}) {
    for (int trial = 0; trial < 40; ++trial) {
      auto J = rotorsweep::testing::jacobian<CyclicTridiagonal<double>>(n);
      for (std::size_t k = 0; k < n; ++k) {
        J.diag(k) = 2.0 * u(rng);
        J.off(k) = u(rng);
      }
      const double shift = 1.5 + u(rng);
      const Eigen::MatrixXd M =
          shift * Eigen::MatrixXd::Identity(Eigen::Index(n), Eigen::Index(n)) - dense_jacobian(J);
      const double smallest = rotorsweep::testing::symmetric_eigenvalues(M).minCoeff();
      if (std::fabs(smallest) < 1e-9) continue;  // singular to rounding: either answer is fine
      J.factor(shift);
      INFO("n=" << n << " smallest eigenvalue of M " << smallest);
      CHECK(J.positive_definite() == (smallest > 0));
      (smallest > 0 ? definite : indefinite) += 1;
    }
  }
  CHECK(definite > 20);
  CHECK(indefinite > 20);
}
