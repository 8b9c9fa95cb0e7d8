// The chamber map (landscape/chamber_map): the paper's seven zones, the Euler characteristic in
// every cell, and signatures that change across the analytic curves and nowhere else.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "landscape/bifurcation_curves.hpp"
#include "landscape/chamber_map.hpp"
#include "support/dipolar_range_4.hpp"

using namespace rotorsweep::landscape;
using rotorsweep::testing::dipolar_range_4;

namespace {

constexpr double half_pi = std::numbers::pi / 2;
constexpr double A_max = 12;

const ChamberMap& test_map() {
  static const ChamberMap map = chamber_map({0, A_max, 120, 90});
  return map;
}
/// Point-dipole rows with range 4: their CP interval reaches A_* = 13.0, so their map spans A ≤ 16.
const ChamberMap& dipolar_map() {
  static const ChamberMap map = chamber_map({0, 16, 160, 90, dipolar_range_4});
  return map;
}

/// Points of the given curves in coordinates scaled to the unit square (A/A_max, τ/(π/2)).
std::vector<std::array<double, 2>> scaled_points(const std::vector<Curve>& curves, int samples,
                                                 const ChamberGrid& grid = test_map().grid) {
  std::vector<std::array<double, 2>> out;
  for (auto c : curves)
    for (const auto& p : sample_curve(c, samples, grid.A_max + 1, grid.k))
      out.push_back({p.A / grid.A_max, p.tau / half_pi});
  return out;
}

/// Cells that some curve point falls into (boxes widened by a tenth of a cell).
std::vector<char> touched_cells(const ChamberGrid& grid, const std::vector<std::array<double, 2>>& points) {
  std::vector<char> touched(std::size_t(grid.A_cells) * grid.tau_cells, 0);
  for (const auto& [a, t] : points)
    for (double da : {-0.1, 0.0, 0.1})
      for (double dt : {-0.1, 0.0, 0.1}) {
        const int i = int(std::floor(a * grid.A_cells + da)), j = int(std::floor(t * grid.tau_cells + dt));
        if (i >= 0 && i < grid.A_cells && j >= 0 && j < grid.tau_cells)
          touched[std::size_t(i) * grid.tau_cells + j] = 1;
      }
  return touched;
}

/// Every pair of neighbouring cells that `differ` has a curve point in one of the two cells.
template <class Differ>
void check_changes_only_on_curves(const std::vector<Curve>& curves, Differ differ,
                                  const ChamberMap& map = test_map()) {
  const auto touched = touched_cells(map.grid, scaled_points(curves, 400000, map.grid));
  const int rows = map.grid.A_cells, cols = map.grid.tau_cells;
  int changes = 0;
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j)
      for (auto [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (i + di >= rows || j + dj >= cols || !differ(map.at(i, j), map.at(i + di, j + dj))) continue;
        ++changes;
        INFO("cells (A " << map.A[i] << ", tau " << map.tau[j] << ") and (A " << map.A[i + di] << ", tau "
                         << map.tau[j + dj] << ")");
        CHECK((touched[std::size_t(i) * cols + j] || touched[std::size_t(i + di) * cols + j + dj]));
      }
  CHECK(changes > 100);
}

double distance(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

}  // namespace

TEST_CASE("the bifurcation set cuts the plane into the paper's seven zones", "[landscape][chambers]") {
  const auto& map = test_map();
  CHECK(map.zones_at_least(10) == 7);
  for (const auto& cell : map.cells) {
    REQUIRE(cell.degenerate == 0);
    REQUIRE(cell.minima - cell.saddles + cell.maxima == 0);  // Euler characteristic of the torus
  }
  CHECK(map.at(119, 45).minima == 1);  // A ≈ 12: the strict-FM minimum alone
  CHECK(map.at(119, 45).by_type_and_class[0][0] == 1);
}

TEST_CASE("dipolar coefficients: Euler characteristic in every cell, changes only across their curves",
          "[landscape][chambers]") {
  const auto& map = dipolar_map();
  for (const auto& cell : map.cells) {
    REQUIRE(cell.degenerate == 0);
    REQUIRE(cell.minima - cell.saddles + cell.maxima == 0);
  }
  CHECK(map.zones_at_least(10) == 6);  // one fewer than nearest neighbours (docs/model.md §8)
  CHECK(map.at(159, 45).minima == 1);  // A ≈ 16: the strict-FM minimum alone
  CHECK(map.at(159, 45).by_type_and_class[0][0] == 1);
  check_changes_only_on_curves(
      {Curve::fm_tangential, Curve::fm_transverse, Curve::off_diagonal_plus, Curve::off_diagonal_minus},
      [](const ChamberCell& a, const ChamberCell& b) { return !a.same_morse_signature(b); }, map);
  check_changes_only_on_curves(
      {Curve::fm_tangential, Curve::fm_transverse, Curve::off_diagonal_plus, Curve::off_diagonal_minus,
       Curve::alignment},
      [](const ChamberCell& a, const ChamberCell& b) { return !(a == b); }, map);
}

TEST_CASE("Morse signatures change only across bifurcation curves", "[landscape][chambers]") {
  check_changes_only_on_curves(
      {Curve::fm_tangential, Curve::fm_transverse, Curve::off_diagonal_plus, Curve::off_diagonal_minus},
      [](const ChamberCell& a, const ChamberCell& b) { return !a.same_morse_signature(b); });
}

TEST_CASE("alignment classes change only across bifurcation curves and the alignment curve",
          "[landscape][chambers]") {
  check_changes_only_on_curves({Curve::fm_tangential, Curve::fm_transverse, Curve::off_diagonal_plus,
                                Curve::off_diagonal_minus, Curve::alignment},
                               [](const ChamberCell& a, const ChamberCell& b) { return !(a == b); });
}

TEST_CASE("cells on the two sides of each curve differ", "[landscape][chambers]") {
  // each curve sampled once; a curve's neighbours are the other curves' samples
  std::vector<std::vector<std::array<double, 2>>> samples;
  for (auto c : all_curves) samples.push_back(scaled_points({c}, 20000));
  for (std::size_t which = 0; which < std::size(all_curves); ++which) {
    const auto curve = all_curves[which];
    std::vector<std::array<double, 2>> near_others;
    for (std::size_t other = 0; other < samples.size(); ++other)
      if (other != which) near_others.insert(near_others.end(), samples[other].begin(), samples[other].end());
    const auto points = scaled_points({curve}, 401);
    int tested = 0;
    for (std::size_t k = 1; k + 1 < points.size(); ++k) {
      const auto& p = points[k];
      // away from the fold lines τ = 0, π/2, from A = 0 and from crossings with other curves
      if (p[0] < 0.01 || p[1] < 0.01 || p[1] > 0.99) continue;
      const double ta = points[k + 1][0] - points[k - 1][0], tt = points[k + 1][1] - points[k - 1][1];
      const double norm = std::hypot(ta, tt);
      if (norm == 0 || norm > 0.05) continue;
      bool crowded = false;
      for (const auto& q : near_others) crowded = crowded || distance(p, q) < 0.01;
      if (crowded) continue;
      const double delta = 2e-4;
      const std::array<double, 2> n{-tt / norm, ta / norm};
      const auto side = [&](double s) {
        return chamber_cell((p[0] + s * delta * n[0]) * A_max, (p[1] + s * delta * n[1]) * half_pi);
      };
      const auto a = side(1), b = side(-1);
      INFO(curve_name(curve) << " at A = " << p[0] * A_max << ", tau = " << p[1] * half_pi);
      if (curve == Curve::alignment)
        CHECK(!(a == b));
      else
        CHECK(!a.same_morse_signature(b));
      ++tested;
    }
    INFO(curve_name(curve));
    CHECK(tested > 100);
  }
}
