// Lattice convolutions (kernels/linear/lattice_convolution.hpp): the FFT's sums against the direct sums over
// square and oblong lattices and single lines, lanes against the scalar lane, and the spectra bounding the
// kernels' matrices (their eigenvalues by a dense eigensolver).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/linear/lattice_convolution.hpp"
#include "kernels/models/slider/slider_pairs.hpp"
#include "support/dense_reference.hpp"
#include "support/kernel_scratch.hpp"

using namespace rotorsweep::kernels;
using rotorsweep::testing::scratch;

namespace {

/// The slider's P and Q tables over a columns × rows lattice.
std::vector<std::vector<double>> pair_tables(std::size_t columns, std::size_t rows) {
  const SliderGrid grid{columns, rows};
  std::vector<std::vector<double>> tables(2, std::vector<double>(grid.offsets(), 0.0));
  for_each_pair_coupling(grid, [&](std::size_t at, double p, double q) {
    tables[0][at] = p;
    tables[1][at] = q;
  });
  return tables;
}

template <class V>
LatticeConvolution<V> convolution(std::size_t columns, std::size_t rows) {
  auto arena = scratch<V>(LatticeConvolution<V>::storage_size(columns, rows, 2));
  LatticeConvolution<V> c(columns, rows, 2, arena);
  const auto tables = pair_tables(columns, rows);
  c.set_kernel(0, tables[0]);
  c.set_kernel(1, tables[1]);
  return c;
}

std::vector<double> random_field(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<double> x(n);
  for (auto& v : x) v = value(rng);
  return x;
}

}  // namespace

TEST_CASE("lattice convolution: torus lengths are powers of two holding every offset", "[kernels][fft]") {
  CHECK(torus_length(1) == 2);
  CHECK(torus_length(7) == 16);
  CHECK(torus_length(64) == 128);
  CHECK(torus_length(65) == 256);
  CHECK(torus_length(24) == 64);
  const auto fft = LatticeConvolution<double>::shape(64, 9, 2);
  CHECK(fft.fft);
  CHECK(fft.torus_columns == 128);
  CHECK(fft.torus_rows == 32);
  CHECK_FALSE(LatticeConvolution<double>::shape(6, 6, 2).fft);
}

TEST_CASE("lattice convolution: the FFT's sums equal the direct sums to rounding", "[kernels][fft]") {
  for (const auto& [columns, rows] : std::vector<std::pair<std::size_t, std::size_t>>{
           {8, 8}, {13, 5}, {5, 13}, {40, 1}, {1, 37}, {24, 24}, {33, 17}}) {
    INFO(columns << " x " << rows);
    const auto c = convolution<double>(columns, rows);
    REQUIRE(c.lattice().fft);
    const std::size_t n = columns * rows;
    const auto a = random_field(n, 1), b = random_field(n, 2);
    std::vector<double> pa(n), qb(n);
    const double* in[2] = {a.data(), b.data()};
    double* out[2] = {pa.data(), qb.data()};
    c.apply(in, out);
    double largest = 0, error = 0;
    for (std::size_t p = 0; p < n; ++p) {
      const double dp = c.direct_at(c.table(0), p, a.data()), dq = c.direct_at(c.table(1), p, b.data());
      largest = std::max({largest, std::fabs(dp), std::fabs(dq)});
      error = std::max({error, std::fabs(pa[p] - dp), std::fabs(qb[p] - dq)});
    }
    CHECK(error <= 1e-14 * std::max(largest, 1.0) * std::log2(double(n) + 2));
  }
}

TEST_CASE("lattice convolution: small lattices sum directly, and apply gives those sums", "[kernels][fft]") {
  const auto c = convolution<double>(6, 5);
  REQUIRE_FALSE(c.lattice().fft);
  const auto a = random_field(30, 4), b = random_field(30, 5);
  std::vector<double> pa(30), qb(30);
  const double* in[2] = {a.data(), b.data()};
  double* out[2] = {pa.data(), qb.data()};
  c.apply(in, out);
  for (std::size_t p = 0; p < 30; ++p) {
    CHECK(pa[p] == c.direct_at(c.table(0), p, a.data()));
    CHECK(qb[p] == c.direct_at(c.table(1), p, b.data()));
  }
}

TEST_CASE("lattice convolution: SIMD lanes give each scalar lane's sums to rounding", "[kernels][fft]") {
  using V = simd_lane;
  constexpr std::size_t width = lane_width<V>;
  const std::size_t columns = 12, rows = 9, n = columns * rows;
  const auto scalar = convolution<double>(columns, rows);
  const auto lanes = convolution<V>(columns, rows);
  std::vector<std::vector<double>> a(width), b(width);
  lane_vector<V> av(n), bv(n), pa(n), qb(n);
  for (std::size_t l = 0; l < width; ++l) {
    a[l] = random_field(n, 10 + unsigned(l));
    b[l] = random_field(n, 30 + unsigned(l));
  }
  for (std::size_t p = 0; p < n; ++p) {
    av[p] = lane_from<V>([&](std::size_t l) { return a[l][p]; });
    bv[p] = lane_from<V>([&](std::size_t l) { return b[l][p]; });
  }
  const V* in[2] = {av.data(), bv.data()};
  V* out[2] = {pa.data(), qb.data()};
  lanes.apply(in, out);
  for (std::size_t l = 0; l < width; ++l) {
    std::vector<double> ps(n), qs(n);
    const double* ins[2] = {a[l].data(), b[l].data()};
    double* outs[2] = {ps.data(), qs.data()};
    scalar.apply(ins, outs);
    for (std::size_t p = 0; p < n; ++p) {
      CHECK(lane_get(pa[p], l) == Approx(ps[p]).margin(1e-13));
      CHECK(lane_get(qb[p], l) == Approx(qs[p]).margin(1e-13));
    }
  }
}

TEST_CASE("lattice convolution: the spectra bound the kernels' eigenvalues on the lattice",
          "[kernels][fft]") {
  for (const auto& [columns, rows] :
       std::vector<std::pair<std::size_t, std::size_t>>{{5, 4}, {9, 7}, {16, 3}, {12, 12}}) {
    INFO(columns << " x " << rows);
    const auto c = convolution<double>(columns, rows);
    const std::size_t n = columns * rows;
    for (std::size_t k = 0; k < 2; ++k) {
      Eigen::MatrixXd matrix(n, n);
      const std::vector<double> unit(n, 0.0);
      for (std::size_t q = 0; q < n; ++q) {
        std::vector<double> e(n, 0.0);
        e[q] = 1.0;
        for (std::size_t p = 0; p < n; ++p)
          matrix(Eigen::Index(p), Eigen::Index(q)) = c.direct_at(c.table(k), p, e.data());
      }
      const Eigen::VectorXd eigenvalues = rotorsweep::testing::symmetric_eigenvalues(matrix);
      CHECK(eigenvalues.minCoeff() >= c.spectrum_min(k) - 1e-12);
      CHECK(eigenvalues.maxCoeff() <= c.spectrum_max(k) + 1e-12);
      // and not loosely: the bounds are within a fraction of the spread of the eigenvalues
      const double spread = eigenvalues.maxCoeff() - eigenvalues.minCoeff();
      CHECK(eigenvalues.minCoeff() - c.spectrum_min(k) < 0.5 * spread);
    }
  }
}
