// The matrix-free stiffness (kernels/linear/spectral_stiffness.hpp): its products and solves against the
// dense matrix K = diag(d) − S P S − C Q C, and its inertia test sufficient (never positive where σ − K is
// not) and tight enough to pass where σ clears K's largest eigenvalue by the bound's margin; in SIMD lanes
// too.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/linear/lattice_convolution.hpp"
#include "kernels/linear/spectral_stiffness.hpp"
#include "kernels/models/slider/slider_pairs.hpp"
#include "support/dense_reference.hpp"
#include "support/kernel_scratch.hpp"

using namespace rotorsweep::kernels;
using rotorsweep::testing::scratch;

namespace {

struct Case {
  SliderGrid grid;
  std::vector<double> sin, cos, diagonal;
  Eigen::MatrixXd K;
};

/// A random state of a grid: angles uniform, diagonal entries around `diagonal_mean`, and K dense.
Case random_case(SliderGrid grid, unsigned seed, double diagonal_mean) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(-3.2, 3.2), spread(-3.0, 3.0);
  const std::size_t n = grid.rotors();
  Case c{grid, std::vector<double>(n), std::vector<double>(n), std::vector<double>(n), Eigen::MatrixXd(n, n)};
  for (std::size_t r = 0; r < n; ++r) {
    const double theta = angle(rng);
    c.sin[r] = std::sin(theta);
    c.cos[r] = std::cos(theta);
    c.diagonal[r] = diagonal_mean + spread(rng);
  }
  const DirectPairs<double> pairs = [&] {
    auto arena = scratch<double>(DirectPairs<double>::storage_size(grid));
    return DirectPairs<double>(grid, arena);
  }();
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t k = 0; k < n; ++k) {
      const auto at = pairs.at(r, k);
      c.K(Eigen::Index(r), Eigen::Index(k)) =
          r == k ? c.diagonal[r] : -(pairs.p(at) * c.sin[r] * c.sin[k] + pairs.q(at) * c.cos[r] * c.cos[k]);
    }
  return c;
}

template <class V>
struct Stiffness {
  LatticeConvolution<V> pairs;
  SpectralStiffness<V> K;
};

template <class V>
Stiffness<V> stiffness(const std::vector<Case>& lanes) {
  const SliderGrid grid = lanes.front().grid;
  const std::size_t n = grid.rotors();
  auto arena = scratch<V>(LatticeConvolution<V>::storage_size(grid.columns, grid.rows, 2) +
                          SpectralStiffness<V>::storage_size(n));
  Stiffness<V> s{LatticeConvolution<V>(grid.columns, grid.rows, 2, arena), SpectralStiffness<V>(n, arena)};
  std::vector<double> p(grid.offsets(), 0.0), q(grid.offsets(), 0.0);
  for_each_pair_coupling(grid, [&](std::size_t at, double pa, double qa) {
    p[at] = pa;
    q[at] = qa;
  });
  s.pairs.set_kernel(0, p);
  s.pairs.set_kernel(1, q);
  s.K.set_pairs(&s.pairs);
  const auto lane = [&](std::size_t l) -> const Case& { return lanes[l % lanes.size()]; };
  for (std::size_t r = 0; r < n; ++r)
    s.K.set_rotor(r, lane_from<V>([&](std::size_t l) { return lane(l).sin[r]; }),
                  lane_from<V>([&](std::size_t l) { return lane(l).cos[r]; }),
                  lane_from<V>([&](std::size_t l) { return lane(l).diagonal[r]; }));
  return s;
}

Eigen::VectorXd to_eigen(const std::vector<double>& x) {
  return Eigen::Map<const Eigen::VectorXd>(x.data(), Eigen::Index(x.size()));
}

}  // namespace

TEST_CASE("spectral stiffness: K x equals the dense product", "[kernels][fft][slider]") {
  for (const SliderGrid grid : {SliderGrid{4, 4}, SliderGrid{9, 7}, SliderGrid{16, 3}}) {
    INFO(grid.columns << " x " << grid.rows);
    const Case c = random_case(grid, 3, -5.0);
    auto s = stiffness<double>({c});
    std::vector<double> x(grid.rotors()), y(grid.rotors());
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (auto& v : x) v = value(rng);
    s.K.multiply(x.data(), y.data());
    CHECK((to_eigen(y) - c.K * to_eigen(x)).cwiseAbs().maxCoeff() < 1e-12);
  }
}

TEST_CASE("spectral stiffness: σ − K solved by conjugate gradients as by a dense solve",
          "[kernels][fft][slider]") {
  const SliderGrid grid{12, 10};
  for (const double margin : {1.0, 10.0, 1000.0}) {
    const Case c = random_case(grid, 5, -4.0);
    const double largest = rotorsweep::testing::symmetric_eigenvalues(c.K).maxCoeff();
    // σ above the inertia bound (largest diagonal + at most 5.2 + 2.7 from the pairs' spectra)
    const double sigma = c.K.diagonal().maxCoeff() + 8.0 + margin;
    INFO("margin " << margin << ", largest eigenvalue of K " << largest);
    auto s = stiffness<double>({c});
    s.K.factor(sigma);
    std::vector<double> b(grid.rotors());
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (auto& v : b) v = value(rng);
    std::vector<double> x = b;
    s.K.solve(x.data());
    CHECK(s.K.positive_definite());
    const Eigen::MatrixXd A = sigma * Eigen::MatrixXd::Identity(c.K.rows(), c.K.cols()) - c.K;
    const Eigen::VectorXd exact = rotorsweep::testing::dense_solve(A, to_eigen(b));
    CHECK((to_eigen(x) - exact).norm() <= 1e-10 * exact.norm());
  }
}

TEST_CASE("spectral stiffness: the inertia test is never positive where σ − K is not",
          "[kernels][fft][slider]") {
  std::size_t passed = 0, cases = 0;
  for (unsigned seed = 0; seed < 12; ++seed)
    for (const double diagonal_mean : {-20.0, -3.0, 2.0}) {
      const SliderGrid grid{seed % 2 ? SliderGrid{7, 7} : SliderGrid{10, 5}};
      const Case c = random_case(grid, seed, diagonal_mean);
      const double largest = rotorsweep::testing::symmetric_eigenvalues(c.K).maxCoeff();
      auto s = stiffness<double>({c});
      for (const double offset : {-2.0, -0.1, 0.1, 1.0, 3.0, 6.0, 10.0, 20.0}) {
        const double sigma = largest + offset;
        s.K.factor(sigma);
        std::vector<double> b(grid.rotors(), 1.0);
        s.K.solve(b.data());
        ++cases;
        if (s.K.positive_definite()) {
          ++passed;
          INFO("seed " << seed << ", σ − λ_max(K) = " << offset);
          CHECK(offset > 0.0);
        }
      }
      // well above the bound it passes
      s.K.factor(c.K.diagonal().maxCoeff() + 8.0);
      std::vector<double> b(grid.rotors(), 1.0);
      s.K.solve(b.data());
      CHECK(s.K.positive_definite());
    }
  CHECK(passed > cases / 4);
}

TEST_CASE("spectral stiffness: SIMD lanes solve each lane's system as the scalar lane",
          "[kernels][fft][slider]") {
  using V = simd_lane;
  constexpr std::size_t width = lane_width<V>;
  const SliderGrid grid{9, 8};
  std::vector<Case> cases;
  for (std::size_t l = 0; l < width; ++l)
    cases.push_back(random_case(grid, 40 + unsigned(l), -6.0 + double(l)));
  auto lanes = stiffness<V>(cases);
  V sigma = lane_from<V>([&](std::size_t l) { return cases[l].K.diagonal().maxCoeff() + 9.0 + double(l); });
  lanes.K.factor(sigma);
  lane_vector<V> b(grid.rotors());
  for (std::size_t r = 0; r < grid.rotors(); ++r)
    b[r] = lane_from<V>([&](std::size_t l) { return std::cos(double(r + l)); });
  lanes.K.solve(b.data());
  CHECK(!lane_any(!lanes.K.positive_definite()));
  for (std::size_t l = 0; l < width; ++l) {
    auto scalar = stiffness<double>({cases[l]});
    scalar.K.factor(lane_get(sigma, l));
    std::vector<double> x(grid.rotors());
    for (std::size_t r = 0; r < grid.rotors(); ++r) x[r] = std::cos(double(r + l));
    scalar.K.solve(x.data());
    for (std::size_t r = 0; r < grid.rotors(); ++r) CHECK(lane_get(b[r], l) == Approx(x[r]).margin(1e-10));
  }
}
