// Quenched disorder (ensemble/disorder, docs/model.md §7): realizations per replica, CP friction
// converging with the tolerance once the rows differ, explicit per-row values against an
// independent integration of the same equations, and thread-count invariance.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "ensemble/rows/disorder.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"
#include "support/scene_sweep.hpp"

using namespace rotorsweep::ensemble;
using rotorsweep::testing::sweep;

namespace {
/// The paper's CP members (N = 20, g = 0.0011, AFM start) with drawn disorder of the A_j.
std::string cp_scene(double rtol, const std::string& disorder) {
  char numerics[96];
  std::snprintf(numerics, sizeof numerics, "[numerics]\nrtol = %.17g\natol = %.17g\n", rtol, rtol * 1e-3);
  return "[model]\nrows = 20\n[drive]\ng = [0.0011]\n[sweep]\nA = [6.0, 8.0]\n[initial]\nkinds = "
         "[\"AFM\"]\n" +
         disorder + numerics;
}

}  // namespace

TEST_CASE("a replica's disorder is the same array at every A, g and kind, and N rows a prefix",
          "[ensemble][disorder]") {
  Disorder d;
  d.A = 1e-3;
  d.coupling = 0.2;
  d.seed = 5;
  const auto r0 = row_deviations(d, 20, 0), r0_again = row_deviations(d, 20, 0);
  const auto r1 = row_deviations(d, 20, 1), r0_long = row_deviations(d, 40, 0);
  CHECK(r0.A == r0_again.A);
  CHECK(r0.A != r1.A);
  CHECK(r0.anisotropy.empty());
  CHECK(std::equal(r0.A.begin(), r0.A.end(), r0_long.A.begin()));
  CHECK(std::equal(r0.coupling.begin(), r0.coupling.end(), r0_long.coupling.begin()));
  d.seed = 6;
  CHECK(row_deviations(d, 20, 0).A != r0.A);
  // σ ξ with ξ standard normal: moments over many rows
  Disorder unit;
  unit.A = 1.0;
  const auto many = row_deviations(unit, 200000, 3).A;
  double mean = 0, square = 0;
  for (double x : many) {
    mean += x / double(many.size());
    square += x * x / double(many.size());
  }
  CHECK(std::fabs(mean) < 0.01);
  CHECK(std::fabs(square - 1.0) < 0.01);
  // explicit lists repeat over the rows
  Disorder listed;
  listed.anisotropy_rows = {0.1, -0.2};
  CHECK(row_deviations(listed, 6, 0).anisotropy == std::vector<double>{0.1, -0.2, 0.1, -0.2, 0.1, -0.2});
}

TEST_CASE("with disorder CP friction converges as rtol goes to 1e-11", "[ensemble][disorder]") {
  // without it, D at A = 6 and 8 moves by percents between these tolerances (docs/model.md §7)
  std::vector<std::vector<MemberResult>> runs;
  for (double rtol : {1e-9, 1e-10, 1e-11}) runs.push_back(sweep(cp_scene(rtol, "[disorder]\nA = 1e-6\n")));
  for (std::size_t i = 0; i < 2; ++i) {
    INFO("A = " << (i == 0 ? 6 : 8));
    CHECK(runs[0][i].regime == Regime::cp);
    for (std::size_t k = 1; k < runs.size(); ++k) {
      const double now = runs[k][i].dissipation(), before = runs[k - 1][i].dissipation();
      INFO("D " << before << " -> " << now);
      CHECK(std::fabs(now - before) <= 1e-6 * std::fabs(now));
    }
  }
}

namespace {

/// An independent integration of the disordered equations: classical RK4 with fixed steps,
/// the torques written from the energy of docs/model.md §7, R accumulated by Simpson's rule per step.
double reference_dissipation(std::vector<double> theta, double A, double g, const std::vector<double>& dA,
                             const std::vector<double>& da, const std::vector<double>& db, int periods) {
  const std::size_t n = theta.size();
  const auto rhs = [&](const std::vector<double>& y, double t) {
    std::vector<double> f(n);
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t jp = (j + 1) % n, jm = (j + n - 1) % n;
      const double dH = 3 * (1 + da[j % da.size()]) * std::sin(2 * y[j]) -
                        (1 + db[j % db.size()]) * std::sin(y[j] - y[jp]) -
                        (1 + db[jm % db.size()]) * std::sin(y[j] - y[jm]) -
                        A * (1 + dA[j % dA.size()]) * std::sin(y[j] - t);
      f[j] = -dH / g;
    }
    return f;
  };
  const auto drive = [&](const std::vector<double>& y, double t) {
    double r = 0;
    for (std::size_t j = 0; j < n; ++j) r += A * (1 + dA[j % dA.size()]) * std::sin(y[j] - t);
    return r;
  };
  const int steps = 20000;
  const double h = 2 * M_PI / steps;
  double R = 0;
  for (int p = 0; p < periods; ++p) {
    R = 0;
    for (int s = 0; s < steps; ++s) {
      const double t = 2 * M_PI * p + h * s;
      const auto add = [&](const std::vector<double>& y, const std::vector<double>& k, double c) {
        std::vector<double> out(n);
        for (std::size_t j = 0; j < n; ++j) out[j] = y[j] + c * k[j];
        return out;
      };
      const auto k1 = rhs(theta, t), k2 = rhs(add(theta, k1, h / 2), t + h / 2);
      const auto k3 = rhs(add(theta, k2, h / 2), t + h / 2), k4 = rhs(add(theta, k3, h), t + h);
      std::vector<double> next(n), half(n);
      for (std::size_t j = 0; j < n; ++j)
        next[j] = theta[j] + h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
      const auto f_next = rhs(next, t + h);
      // Simpson's rule needs the midpoint: the cubic Hermite interpolant of the step
      for (std::size_t j = 0; j < n; ++j) half[j] = 0.5 * (theta[j] + next[j]) + h / 8 * (k1[j] - f_next[j]);
      R += h / 6 * (drive(theta, t) + 4 * drive(half, t + h / 2) + drive(next, t + h));
      theta = next;
    }
  }
  return R;
}

}  // namespace

TEST_CASE("explicit per-row disorder reproduces an independent integration of the same equations",
          "[ensemble][disorder]") {
  // g = 0.5 keeps the system non-stiff for the reference RK4; one relaxation and one averaged period
  const std::vector<double> dA{0.05, -0.1, 0.02, 0.0}, da{-0.03, 0.04}, db{0.1, -0.05, 0.0, 0.07};
  const auto results = sweep(
      "[model]\nrows = 8\n[drive]\ng = [0.5]\n[sweep]\nA = [3.0]\n[initial]\nkinds = [\"exact\"]\n"
      "angles = [0.1, 3.0, 0.3, 2.9, 0.2, 3.3, 0.0, 3.1]\n[schedule]\nrelax_periods = 1\naverage_periods = "
      "1\n"
      "[disorder]\nA_rows = [0.05, -0.1, 0.02, 0.0]\nanisotropy_rows = [-0.03, 0.04]\n"
      "coupling_rows = [0.1, -0.05, 0.0, 0.07]\n[numerics]\nrtol = 1e-11\natol = 1e-14\n");
  const double reference =
      reference_dissipation({0.1, 3.0, 0.3, 2.9, 0.2, 3.3, 0.0, 3.1}, 3.0, 0.5, dA, da, db, 2);
  INFO("D = " << results[0].dissipation() << ", reference " << reference);
  CHECK(std::fabs(results[0].dissipation() - reference) <= 1e-7 * std::fabs(reference));
}

TEST_CASE("disordered sweeps give the same bits on 1 and 2 threads and scalar lanes",
          "[ensemble][disorder]") {
  const std::string text =
      "[model]\nrows = 12\n[drive]\ng = [0.01]\n[sweep]\nA = { from = 2, to = 12, count = 9 }\n"
      "[initial]\nkinds = [\"AFM\", \"FM\"]\nreplicas = 2\n[disorder]\nA = 1e-3\ncoupling = 1e-2\nseed = 9\n";
  const auto one = sweep(text), two = sweep(text, 2);
  const auto scalar = sweep(text + "[numerics]\nlanes = \"scalar\"\n");
  for (std::size_t i = 0; i < one.size(); ++i) {
    INFO("member " << i);
    CHECK(one[i].dissipation() == two[i].dissipation());
    CHECK(one[i].dissipation() == scalar[i].dissipation());
    CHECK(one[i].theta_final == two[i].theta_final);
    CHECK(one[i].steps_accepted == scalar[i].steps_accepted);
  }
  // replicas are realizations: the two replicas of a point differ
  CHECK(one[0].dissipation() != one[1].dissipation());
}
