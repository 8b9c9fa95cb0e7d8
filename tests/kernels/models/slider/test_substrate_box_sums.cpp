// Box sums of the finite substrate's field (kernels/models/slider/substrate_box_sums.hpp) against the direct
// sums, node by node, for in-plane and turned moments, shifted tracks and a deeper lattice; SIMD = scalar.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/models/slider/substrate_box_sums.hpp"
#include "kernels/models/slider/substrate_field.hpp"

using namespace rotorsweep::kernels;

namespace {

/// The largest difference between box sums and direct sums over every node, relative to the largest field.
double largest_difference(const SubstrateLattice& lattice, double y_first, std::size_t tracks, double x_begin,
                          std::size_t m, std::size_t intervals) {
  const auto nodes = box_sum_nodes(lattice, y_first, tracks, x_begin, m, intervals);
  double largest = 0, difference = 0;
  for (std::size_t t = 0; t < tracks; ++t)
    for (std::size_t i = 0; i <= intervals; ++i) {
      const auto direct =
          substrate_field(lattice, x_begin + double(i) / double(m), y_first + double(t), false);
      const TableNode& n = nodes[t][i];
      const double pairs[6][2] = {{n.along.value, direct.x.value},
                                  {n.along.slope, direct.x.slope},
                                  {n.along.curvature, direct.x.curvature},
                                  {n.z.value, direct.z.value},
                                  {n.z.slope, direct.z.slope},
                                  {n.z.curvature, direct.z.curvature}};
      for (const auto& [box, sum] : pairs) {
        largest = std::max(largest, std::fabs(sum));
        difference = std::max(difference, std::fabs(box - sum));
      }
    }
  return difference / largest;
}

}  // namespace

TEST_CASE("substrate box sums: every node equals the direct sum to rounding",
          "[kernels][slider][substrate]") {
  // 6 tracks over a 17 × 13 lattice at η = 0.5, 9 nodes per a over 4.4 a
  SubstrateLattice lattice{17, 13, -5.0, -4.0, 0.5, 0.0};
  CHECK(largest_difference(lattice, 0.0, 6, -0.5, 9, 40) < 1e-13);
  SECTION("turned moments, shifted tracks, a lattice farther away") {
    lattice.angle = 0.6;
    CHECK(largest_difference(lattice, 0.37, 6, -0.31, 9, 40) < 1e-13);
    lattice.depth = 0.9;
    CHECK(largest_difference(lattice, -0.2, 3, 1.1, 5, 31) < 1e-13);
  }
  SECTION("close to the lattice, more nodes than a lattice row") {
    lattice.depth = 0.1;
    CHECK(largest_difference(lattice, 0.0, 4, -3.0, 160, 3000) < 1e-12);
  }
}

TEST_CASE("substrate box sums: SIMD lanes give the scalar lane's bits", "[kernels][slider][substrate]") {
  const SubstrateLattice lattice{23, 19, -8.0, -6.0, 0.45, 0.4};
  const auto scalar = box_sum_nodes<double>(lattice, 0.0, 5, -0.5, 7, 50);
  const auto lanes = box_sum_nodes<simd_lane>(lattice, 0.0, 5, -0.5, 7, 50);
  for (std::size_t t = 0; t < 5; ++t)
    for (std::size_t i = 0; i <= 50; ++i) {
      CHECK(lanes[t][i].along.value == scalar[t][i].along.value);
      CHECK(lanes[t][i].z.curvature == scalar[t][i].z.curvature);
    }
}
