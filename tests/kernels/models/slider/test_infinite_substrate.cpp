// The infinite substrate's Fourier series (kernels/models/slider/infinite_substrate.hpp) against finite
// lattices: the finite field converges to it as 1/S (the edges' magnetic charges, the field's tail), and
// Richardson's extrapolation of S = 80, 160, 320 meets it; its period in x and y; its track nodes.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/models/slider/infinite_substrate.hpp"
#include "kernels/models/slider/substrate_field.hpp"

using namespace rotorsweep::kernels;

namespace {

/// An S × S lattice centred on the origin with a moment at every integer point (S odd: one at the origin).
SubstrateLattice centred(std::size_t size, double depth, double angle) {
  const double offset = -0.5 * double(size - 1);
  return {size, size, offset, offset, depth, angle};
}

}  // namespace

TEST_CASE("infinite substrate: finite lattices converge to it as 1/S", "[kernels][slider][substrate]") {
  for (const double angle : {0.0, 0.7}) {
    INFO("angle " << angle);
    const double depth = 0.56;
    const InfiniteSubstrate infinite(depth, angle);
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0.0, 0.0}, {0.3, 0.2}, {0.71, -0.45}}) {
      const auto exact = infinite.field_at(x, y);
      const auto at = [&](std::size_t size) {
        return substrate_field(centred(size, depth, angle), x, y, true);
      };
      const auto f1 = at(81), f2 = at(161), f3 = at(321);
      const auto check = [&](double a, double b, double c, double limit) {
        // the gap halves as S doubles (the edges' charges, ~ 1/S); Richardson's limit meets the series
        const double gap1 = std::fabs(a - limit), gap2 = std::fabs(b - limit), gap3 = std::fabs(c - limit);
        CHECK(gap2 < 0.6 * gap1 + 1e-9);
        CHECK(gap3 < 0.6 * gap2 + 1e-9);
        const double extrapolated = (8.0 * c - 6.0 * b + a) / 3.0;  // removes the 1/S and 1/S² terms
        CHECK(extrapolated == Approx(limit).margin(2e-5));
      };
      check(f1.x.value, f2.x.value, f3.x.value, exact.x.value);
      check(f1.z.value, f2.z.value, f3.z.value, exact.z.value);
      check(f1.y.value, f2.y.value, f3.y.value, exact.y.value);
      check(f1.x.slope, f2.x.slope, f3.x.slope, exact.x.slope);
      check(f1.z.curvature, f2.z.curvature, f3.z.curvature, exact.z.curvature);
    }
  }
}

TEST_CASE("infinite substrate: periodic with the lattice, its nodes repeat along a track",
          "[kernels][slider][substrate]") {
  const InfiniteSubstrate infinite(0.4, 0.3, 0.2);
  const auto a = infinite.field_at(0.37, 0.21), b = infinite.field_at(3.37, -1.79);
  CHECK(a.x.value == Approx(b.x.value).margin(1e-12));
  CHECK(a.z.slope == Approx(b.z.slope).margin(1e-12));
  std::vector<TableNode> nodes(100);
  infinite.track_nodes(0.21, -0.5, 16, nodes);
  const auto direct = infinite.field_at(-0.5 + 37.0 / 16.0, 0.21);
  CHECK(nodes[37].z.value == Approx(direct.z.value).margin(1e-12));
  CHECK(nodes[37].along.value ==
        Approx(std::cos(0.2) * direct.x.value + std::sin(0.2) * direct.y.value).margin(1e-12));
  // close to the lattice the series needs more harmonics
  CHECK(InfiniteSubstrate(0.05, 0.0).order() > InfiniteSubstrate(0.5, 0.0).order());
}
