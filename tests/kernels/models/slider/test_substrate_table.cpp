// The substrate field (kernels/models/slider/substrate_field.hpp, substrate_table.hpp; docs/model.md §9
// "Substrate field"): the direct sum against a plain vector sum of dipole fields (moments along x and turned
// in the xz-plane), its x-derivatives against differences, and the quintic Hermite table against the direct
// sum at random points (error ∝ dx⁶); SIMD and scalar builds of a table equal.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <tuple>
#include <type_traits>
#include <vector>

#include "kernels/models/slider/substrate_field.hpp"
#include "kernels/models/slider/substrate_table.hpp"

using namespace rotorsweep::kernels;

namespace {

/// The tracks of a 7 × 7 slider's rows.
const std::vector<double> rows7{0, 1, 2, 3, 4, 5, 6};

/// The experiment's substrate (35 × 35 under a 7 × 7 slider) at separation h = eta·a.
SubstrateLattice experiment_substrate(double eta) { return {35, 35, -14.0, -14.0, eta}; }

/// B at (x, y, 0) summed as vectors, (3 r̂ (m·r̂) − m)/r³ with m = (cos φ, 0, −sin φ), without the
/// closed forms.
std::array<double, 3> vector_sum(const SubstrateLattice& lattice, double x, double y) {
  const std::array<double, 3> m{std::cos(lattice.angle), 0.0, -std::sin(lattice.angle)};
  std::array<double, 3> b{0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < lattice.columns; ++k)
    for (std::size_t l = 0; l < lattice.rows; ++l) {
      const std::array<double, 3> r{x - (lattice.x_offset + double(k)), y - (lattice.y_offset + double(l)),
                                    lattice.depth};
      const double d = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
      const double m_dot_rhat = (m[0] * r[0] + m[1] * r[1] + m[2] * r[2]) / d;
      for (int c = 0; c < 3; ++c) b[c] += (3.0 * (r[c] / d) * m_dot_rhat - m[c]) / (d * d * d);
    }
  return b;
}

/// The largest error of the table against the direct sum over random points of the slider's path,
/// relative to the largest |B| on the path.
double table_error(double eta, double dx, unsigned seed) {
  const auto lattice = experiment_substrate(eta);
  const SubstrateTable table(lattice, rows7, -0.5, 11.5, dx);
  const auto view = table.view();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x_on_path(-0.5, 11.5);
  double error = 0.0, scale = 0.0;
  for (int i = 0; i < 300; ++i) {
    const std::size_t row = std::size_t(i % 7);
    const double x = x_on_path(rng);
    const auto exact = substrate_field(lattice, x, double(row));
    const TrackField<> f = field_in_lanes(&view, row, x);
    error = std::max({error, std::fabs(f.bx - exact.x.value), std::fabs(f.bz - exact.z.value)});
    scale = std::max({scale, std::fabs(exact.x.value), std::fabs(exact.z.value)});
  }
  return error / scale;
}

}  // namespace

TEST_CASE("substrate field: the closed-form sum equals the vector sum of dipole fields",
          "[kernels][slider]") {
  auto lattice = experiment_substrate(0.45);
  for (const double angle : {0.0, 0.6, -2.0})  // moments along x, and turned in the xz-plane
    for (const auto& [x, y] : {std::pair{0.3, 0.0}, {3.71, 2.0}, {10.2, 6.3}, {-0.4, 4.0}}) {
      lattice.angle = angle;
      const auto closed = substrate_field(lattice, x, y);
      const auto vec = vector_sum(lattice, x, y);
      CHECK(closed.x.value == Catch::Detail::Approx(vec[0]).epsilon(1e-12));
      CHECK(closed.y.value == Catch::Detail::Approx(vec[1]).epsilon(1e-12).margin(1e-14));
      CHECK(closed.z.value == Catch::Detail::Approx(vec[2]).epsilon(1e-12));
    }
}

TEST_CASE("substrate field: slope and curvature equal central differences", "[kernels][slider]") {
  auto lattice = experiment_substrate(0.6);
  const double e = 1e-4;
  for (const double angle : {0.0, 0.9})
    for (const double x : {0.13, 2.5, 5.77}) {
      lattice.angle = angle;
      const auto at = substrate_field(lattice, x, 3.3);
      const auto plus = substrate_field(lattice, x + e, 3.3), minus = substrate_field(lattice, x - e, 3.3);
      const double scale = std::fabs(at.x.value) + std::fabs(at.y.value) + std::fabs(at.z.value);
      for (const auto& [jet, up, down] :
           {std::tuple{at.x, plus.x, minus.x}, {at.y, plus.y, minus.y}, {at.z, plus.z, minus.z}}) {
        CHECK(std::fabs(jet.slope - (up.value - down.value) / (2 * e)) < 1e-6 * scale);
        CHECK(std::fabs(jet.curvature - (up.slope - down.slope) / (2 * e)) < 1e-5 * scale);
      }
    }
}

TEST_CASE("substrate table: the quintic Hermite table against the direct sum at random points",
          "[kernels][slider]") {
  // The field varies on the scale of the separation η: nodes every η/16 (the default) hold it to a few
  // 1e-8 of its largest value, at the closest (h = 5 mm) and the farthest (13 mm) separation of the scan.
  for (const double eta : {0.3125, 0.8125}) {
    const double coarse = table_error(eta, eta / 16.0, 1);
    const double fine = table_error(eta, eta / 32.0, 1);
    INFO("eta " << eta << ": relative error at dx = eta/16: " << coarse << ", at eta/32: " << fine);
    CHECK(coarse < 5e-8);
    CHECK(coarse / fine > 40.0);  // sixth order: 2⁶ = 64 in the asymptotic range
  }
}

TEST_CASE("substrate table: slopes and curvatures follow the polynomial's derivatives", "[kernels][slider]") {
  const auto lattice = experiment_substrate(0.4);
  const SubstrateTable table(lattice, rows7, -0.5, 11.5, 1.0 / 32.0);
  const auto view = table.view();
  for (const double x : {0.0, 1.0 / 64.0, 4.321, 11.49}) {
    const auto exact = substrate_field(lattice, x, 5.0);
    const TrackField<> f = field_in_lanes(&view, std::size_t(5), x);
    const double scale = std::fabs(exact.x.slope) + std::fabs(exact.z.slope) + 1.0;
    CHECK(std::fabs(f.dbx - exact.x.slope) < 1e-6 * scale);
    CHECK(std::fabs(f.dbz - exact.z.slope) < 1e-6 * scale);
    CHECK(std::fabs(f.d2bx - exact.x.curvature) < 1e-4 * (std::fabs(exact.x.curvature) + 1.0));
    CHECK(std::fabs(f.d2bz - exact.z.curvature) < 1e-4 * (std::fabs(exact.z.curvature) + 1.0));
  }
}

TEST_CASE("a table built with SIMD lanes holds the scalar build's bits", "[kernels][slider][substrate]") {
  const auto lattice = experiment_substrate(0.5);
  // 601 nodes: the last SIMD group of nodes is partly filled
  const SubstrateTable scalar(lattice, rows7, -0.5, 11.5, 0.02);
  const SubstrateTable simd(lattice, rows7, -0.5, 11.5, 0.02, 0.0, std::type_identity<simd_lane>{});
  const auto a = scalar.view(), b = simd.view();
  REQUIRE(a.intervals == b.intervals);
  CHECK(std::equal(a.coefficients, a.coefficients + a.tracks * a.intervals * 12, b.coefficients));
}
