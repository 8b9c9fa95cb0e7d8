// Point-dipole coupling tables (ensemble/coupling_table, docs/model.md §8) against closed forms
// (ζ(3), a row of one or two rotors, 1/u² far away), the stated sums and the paper's 2-D lattice check.
#include <catch2/catch.hpp>
#include <cmath>
#include <utility>
#include <vector>

#include "ensemble/rows/coupling_table.hpp"

using namespace rotorsweep::ensemble;
using Catch::Detail::Approx;

TEST_CASE("nearest neighbours are today's model", "[ensemble][couplings]") {
  const auto table = nearest_neighbour_table();
  CHECK(table.a == 1.5);
  CHECK(table.b == std::vector<double>{1.0});
  CHECK(table.c == std::vector<double>{0.0});
  const auto reduced = two_angle_coefficients(table);
  CHECK(reduced.a == 1.5);
  CHECK(reduced.b == 2.0);
  CHECK(reduced.c == 0.0);
}

TEST_CASE("an infinite row gives (3/2) zeta(3) and the stated couplings", "[ensemble][couplings]") {
  const auto table = dipolar_table(12, 0);
  CHECK(table.a == Approx(1.5 * 1.2020569031595942).epsilon(1e-12));
  CHECK(table.b[0] == Approx(1.08519).margin(5e-6));
  CHECK(table.c[0] == Approx(0.93968).margin(5e-6));
  CHECK(table.b[1] == Approx(0.25010).margin(5e-6));
  CHECK(table.c[1] == Approx(0.24991).margin(5e-6));
  CHECK(table.b[2] == Approx(1.0 / 9).margin(1e-6));
  CHECK(table.c[2] == Approx(1.0 / 9).margin(1e-6));
  // far rows see a line of dipoles: b_u, c_u → 1/u²
  CHECK(table.b[11] == Approx(1.0 / 144).epsilon(1e-6));
  CHECK(table.c[11] == Approx(1.0 / 144).epsilon(1e-6));
}

TEST_CASE("short rows have closed forms and long rows approach the infinite one", "[ensemble][couplings]") {
  const auto single = dipolar_table(3, 1);  // one rotor per row: only the partner straight across
  CHECK(single.a == 0);
  for (std::size_t u = 1; u <= 3; ++u) {
    CHECK(single.b[u - 1] == Approx(1.0 / double(u * u * u)).epsilon(1e-15));
    CHECK(single.c[u - 1] == 0);
  }
  const auto pair = dipolar_table(1, 2);  // two rotors: offsets ±1 weigh 1/2 each
  const double diagonal = std::pow(2.0, -1.5);
  CHECK(pair.a == Approx(0.75).epsilon(1e-15));
  CHECK(pair.b[0] == Approx(1 + diagonal * 0.25).epsilon(1e-15));
  CHECK(pair.c[0] == Approx(diagonal * 0.75).epsilon(1e-15));
  const auto infinite = dipolar_table(2, 0);
  const auto long_row = dipolar_table(2, 100000);
  CHECK(long_row.a == Approx(infinite.a).margin(1e-4));
  CHECK(long_row.b[0] == Approx(infinite.b[0]).margin(1e-4));
  CHECK(long_row.c[1] == Approx(infinite.c[1]).margin(1e-4));
}

TEST_CASE("the 2-D lattice sums give the paper's deviations from nearest neighbours",
          "[ensemble][couplings]") {
  // relative deviations from the nearest-neighbour energies −2 (FM) and −6 (AFM), square shells
  const auto deviation_fm = [](std::size_t M) { return (lattice_energy_per_moment(M, false) + 2) / -2; };
  const auto deviation_afm = [](std::size_t M) { return (lattice_energy_per_moment(M, true) + 6) / -6; };
  CHECK(deviation_fm(400) == Approx(1.2549).margin(1e-4));
  CHECK(deviation_afm(400) == Approx(-0.1502).margin(1e-4));
  // the FM shell sum converges like 1/M: doubling M halves the step; the limit (Richardson) is 1.2584
  const double f200 = deviation_fm(200), f400 = deviation_fm(400), f800 = deviation_fm(800);
  CHECK((f400 - f200) / (f800 - f400) == Approx(2).margin(0.05));
  CHECK(2 * f800 - f400 == Approx(1.2584).margin(2e-4));
}

TEST_CASE("the two-angle reduction folds even rows into the anisotropy", "[ensemble][couplings]") {
  CouplingTable table{2.0, {1.0, 0.5, 0.25}, {0.1, 0.2, 0.3}};
  const auto reduced = two_angle_coefficients(table);
  CHECK(reduced.a == Approx(2.2));
  CHECK(reduced.b == Approx(2 * (1.0 + 0.25)));
  CHECK(reduced.c == Approx(2 * (0.1 + 0.3)));
}

TEST_CASE("far rows of an infinite row take the line limit 1/u^2, which the direct sums reach",
          "[ensemble][couplings]") {
  // the direct sum over k = -10^6 … 10^6 in long double, with the k^-3 tails, against the table
  const auto direct = [](double u) {
    long double same = 0, opposite = 0;
    for (long k = 1000000; k >= -1000000; --k) {
      const long double r2 = (long double)k * k + (long double)u * u;
      const long double inverse_cube = 1.0L / (r2 * std::sqrt(r2)), axial = 1.5L * k * k / r2;
      same += inverse_cube * (1 - axial);
      opposite += inverse_cube * axial;
    }
    const long double tail = 1.0L / (2.0L * 1e12L);  // Σ_{k>K} k^-3 ≈ 1/(2K²), both sides below
    return std::pair{double(same - tail), double(opposite + 3 * tail)};
  };
  const auto table = dipolar_table(12, 0);
  for (const double u : {6.0, 7.0, 9.0, 12.0}) {
    const auto [same, opposite] = direct(u);
    INFO("u = " << u);
    CHECK(table.b[std::size_t(u) - 1] == Approx(same).epsilon(1e-12));
    CHECK(table.c[std::size_t(u) - 1] == Approx(opposite).epsilon(1e-12));
    if (u >= 7) CHECK(table.b[std::size_t(u) - 1] == 1.0 / (u * u));
  }
  // and a long table is quick: 10^5 row distances
  const auto long_table = dipolar_table(100000, 0);
  CHECK(long_table.b.back() == 1.0 / 1e10);
}

TEST_CASE("a long point-dipole table reports its progress, row distance by row distance",
          "[ensemble][couplings]") {
  std::vector<std::size_t> seen;
  const auto reported = dipolar_table(40, 0, [&](std::size_t u) { seen.push_back(u); });
  REQUIRE(seen.size() == 40);
  for (std::size_t u = 1; u <= 40; ++u) CHECK(seen[u - 1] == u);
  const auto silent = dipolar_table(40, 0);
  CHECK(reported.b == silent.b);  // the same bits with or without it
  CHECK(reported.c == silent.c);
}
