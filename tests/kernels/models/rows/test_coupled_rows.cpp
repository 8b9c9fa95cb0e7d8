// The row model with a coupling table (kernels/models/rows/coupled_rows.hpp, docs/model.md §1 "Extended
// couplings"): Jacobian, ∂f/∂t and integrand gradients against central differences for random
// tables, periodic and open; f = −∇H/g; the nearest-neighbour table against NearestNeighbourRows;
// the dense LDLᵀ solve and its inertia against Eigen; SIMD lanes equal to scalar ones; the range
// forms a team uses, over any split of the rows, give the whole-row bits; per-row disorder of A and
// the anisotropy (docs/model.md §7) written out, and a lane without deviations keeping its bits.
#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "kernels/lanes/team.hpp"
#include "kernels/models/rows/coupled_rows.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "support/dense_reference.hpp"
#include "support/kernel_scratch.hpp"
#include "support/lane_linearization.hpp"
#include "support/linearization_check.hpp"

using namespace rotorsweep::kernels;
using Catch::Detail::Approx;

namespace {

constexpr Integrals every = all_integrals;
using Model = CoupledRows<double>;
constexpr std::size_t nq = every.count();

std::vector<double> random_values(std::size_t n, unsigned seed, double low, double high) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(low, high);
  std::vector<double> x(n);
  for (auto& v : x) v = u(rng);
  return x;
}

/// A random table of `range` rows and its parameters.
struct Table {
  double a;
  std::vector<double> b, c;
  Table(std::size_t range, unsigned seed)
      : a(random_values(1, seed, 1.0, 2.0)[0]),
        b(random_values(range, seed + 1, -0.5, 1.5)),
        c(random_values(range, seed + 2, -0.5, 1.0)) {}
  Model::Parameters parameters(double A, double g, bool open) const {
    return {A, g, false, a, b.data(), c.data(), b.size(), open};
  }
};

struct Evaluation {
  std::vector<double> f, q;
};

Evaluation evaluate(const Model& m, const std::vector<double>& theta, double t) {
  auto w = rotorsweep::testing::workspace(m);
  Evaluation e{std::vector<double>(theta.size()), std::vector<double>(nq)};
  m.evaluate(w, theta.data(), t, e.f.data(), e.q.data());
  return e;
}

/// g f = −∂H/∂θ at (θ, t), by central differences of the model's energy.
void check_force_is_energy_gradient(const Model& m, const std::vector<double>& theta, double t, double g) {
  const double eps = 1e-6;
  const auto e = evaluate(m, theta, t);
  auto w = rotorsweep::testing::workspace(m);
  for (std::size_t k = 0; k < theta.size(); ++k) {
    auto plus = theta, minus = theta;
    plus[k] += eps;
    minus[k] -= eps;
    const double dH = (m.energy(w, plus.data(), t) - m.energy(w, minus.data(), t)) / (2 * eps);
    CHECK(g * e.f[k] == Approx(-dH).epsilon(1e-7).margin(1e-8));
  }
}

}  // namespace

TEST_CASE("coupled rows: Jacobian, df/dt and integrand gradients match central differences",
          "[kernels][model][couplings]") {
  for (std::size_t n : {5u, 8u, 13u})
    for (bool open : {false, true}) {
      const std::size_t range = open ? n - 1 : (n - 1) / 2;
      const Table table(range, unsigned(n));
      const auto m = rotorsweep::testing::model<Model>(n, every, table.parameters(4.3, 0.37, open));
      const auto theta = random_values(n, unsigned(7 * n), -3.0, 9.0);
      INFO("open " << open);
      rotorsweep::testing::check_linearization(m, theta, 1.9);
      auto w = rotorsweep::testing::workspace(m);
      std::vector<double> f(n), q(nq), df_dt(n), dq_dy(nq * n), dq_dt(nq);
      auto J = rotorsweep::testing::jacobian<Model::Jacobian>(n);
      m.linearize(w, theta.data(), 1.9, f.data(), q.data(), J, df_dt.data(), dq_dy.data(), dq_dt.data());
      for (std::size_t j = 0; j < n; ++j)
        for (std::size_t k = 0; k < n; ++k) CHECK(J.entry(j, k) == J.entry(k, j));
    }
}

TEST_CASE("coupled rows: g f = -dH/dtheta, and H written out", "[kernels][model][couplings]") {
  const std::size_t n = 9;
  const double A = 2.0, g = 0.05, t = 0.4;
  for (bool open : {false, true}) {
    const Table table(open ? 5 : 4, 3);
    const auto m = rotorsweep::testing::model<Model>(n, every, table.parameters(A, g, open));
    const auto theta = random_values(n, 5, -3.0, 9.0);
    const auto e = evaluate(m, theta, t);
    auto w = rotorsweep::testing::workspace(m);
    double H = 0;
    for (std::size_t j = 0; j < n; ++j) {
      H += -table.a * std::cos(2 * theta[j]) + A * std::cos(theta[j] - t);
      for (std::size_t u = 1; u <= table.b.size(); ++u) {
        if (open && j + u >= n) continue;
        const std::size_t k = (j + u) % n;
        H += table.b[u - 1] * std::cos(theta[j] - theta[k]) - table.c[u - 1] * std::cos(theta[j] + theta[k]);
      }
    }
    CHECK(m.energy(w, theta.data(), t) == Approx(H).epsilon(1e-13));
    check_force_is_energy_gradient(m, theta, t, g);
  }
}

TEST_CASE("coupled rows with per-row disorder: the equations of docs/model.md section 7, checked derivatives",
          "[kernels][model][couplings]") {
  const std::size_t n = 9;
  const double A = 2.0, g = 0.05, t = 0.4;
  const auto delta = random_values(n, 21, -0.3, 0.3), alpha = random_values(n, 22, -0.3, 0.3);
  for (bool open : {false, true}) {
    INFO("open " << open);
    const Table table(open ? 5 : 4, 3);
    auto p = table.parameters(A, g, open);
    p.A_rows = delta.data();
    p.anisotropy_rows = alpha.data();
    const auto m = rotorsweep::testing::model<Model>(n, every, p);
    const auto theta = random_values(n, 5, -3.0, 9.0);
    rotorsweep::testing::check_linearization(m, theta, t);
    const auto e = evaluate(m, theta, t);
    auto w = rotorsweep::testing::workspace(m);
    double H = 0, drive = 0;
    for (std::size_t j = 0; j < n; ++j) {
      const double A_j = A * (1 + delta[j]), a_j = table.a * (1 + alpha[j]);
      H += -a_j * std::cos(2 * theta[j]) + A_j * std::cos(theta[j] - t);
      drive += A_j * std::sin(theta[j] - t);
      for (std::size_t u = 1; u <= table.b.size(); ++u) {
        if (open && j + u >= n) continue;
        const std::size_t k = (j + u) % n;
        H += table.b[u - 1] * std::cos(theta[j] - theta[k]) - table.c[u - 1] * std::cos(theta[j] + theta[k]);
      }
    }
    CHECK(m.energy(w, theta.data(), t) == Approx(H).epsilon(1e-13));
    CHECK(e.q[every.drive_index()] == Approx(drive).epsilon(1e-13));
    check_force_is_energy_gradient(m, theta, t, g);
  }
}

TEST_CASE("coupled rows: a lane with zero deviations beside a disordered lane keeps the uniform bits",
          "[kernels][model][couplings][simd]") {
  using Simd = CoupledRows<simd_lane>;
  const std::size_t n = 9;
  const double t = 1.1;
  const Table table(4, 8);
  const auto delta = random_values(n, 23, -0.3, 0.3);
  const std::vector<double> zeros(n, 0.0);
  const auto p = table.parameters(4.0, 0.01, false);
  auto simd = rotorsweep::testing::model<Simd>(n, every, Simd::Parameters{p.A, p.g, false, p.a, p.b, p.c, p.range});
  auto disordered = Simd::Parameters{p.A, p.g, false, p.a, p.b, p.c, p.range};
  disordered.A_rows = delta.data();
  disordered.anisotropy_rows = delta.data();
  auto flat = disordered;
  flat.A_rows = flat.anisotropy_rows = zeros.data();
  simd.set_lane(0, disordered);
  simd.set_lane(1, flat);
  const auto uniform = rotorsweep::testing::model<Model>(n, every, p);
  const auto theta = random_values(n, 5, -3.0, 9.0);
  const auto lanes = rotorsweep::testing::linearize_at(simd, theta, t, nq);
  const auto scalar = rotorsweep::testing::linearize_at(uniform, theta, t, nq);
  for (std::size_t l = 1; l < std::min<std::size_t>(3, lane_width<simd_lane>); ++l)  // SSE2: lane 1 only
    rotorsweep::testing::check_lane_bits(lanes, l, scalar, [&](const auto& J_v, const auto& J, std::size_t lane) {
      for (std::size_t j = 0; j < n; ++j)
        for (std::size_t k = 0; k < n; ++k) CHECK(lane_get(J_v.entry(j, k), lane) == J.entry(j, k));
    });
  CHECK(lane_get(lanes.f[0], 0) != scalar.f[0]);  // lane 0 is disordered
}

TEST_CASE("the nearest-neighbour table is the nearest-neighbour model", "[kernels][model][couplings]") {
  using Nearest = NearestNeighbourRows<double>;
  const std::size_t n = 7;
  const double b = 1.0, c = 0.0;
  const auto coupled =
      rotorsweep::testing::model<Model>(n, every, Model::Parameters{3.1, 0.2, false, 1.5, &b, &c, 1, false});
  const auto nearest = rotorsweep::testing::model<Nearest>(n, every, 3.1, 0.2);
  const auto theta = random_values(n, 17, -3.0, 9.0);
  std::vector<double> f1(n), f2(n), q1(nq), q2(nq);
  auto w1 = rotorsweep::testing::workspace(coupled);
  auto w2 = rotorsweep::testing::workspace(nearest);
  coupled.evaluate(w1, theta.data(), 0.8, f1.data(), q1.data());
  nearest.evaluate(w2, theta.data(), 0.8, f2.data(), q2.data());
  for (std::size_t j = 0; j < n; ++j) CHECK(f1[j] == Approx(f2[j]).epsilon(1e-13).margin(1e-13));
  for (std::size_t p = 0; p < nq; ++p) CHECK(q1[p] == Approx(q2[p]).epsilon(1e-13).margin(1e-13));
}

TEST_CASE("dense LDLT solve and inertia agree with Eigen", "[kernels][couplings]") {
  const std::size_t n = 9;
  auto J = rotorsweep::testing::jacobian<DenseSymmetric<double>>(n);
  Eigen::MatrixXd dense(n, n);
  const auto values = random_values(n * n, 23, -1.0, 1.0);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = 0; k <= j; ++k)
      dense(Eigen::Index(j), Eigen::Index(k)) = dense(Eigen::Index(k), Eigen::Index(j)) = values[j * n + k];
  const Eigen::VectorXd eigenvalues = rotorsweep::testing::symmetric_eigenvalues(dense);
  for (double shift : {-3.0, 0.1, 0.7, 5.0}) {
    for (std::size_t j = 0; j < n; ++j)  // anew for each factor, which takes J's place
      for (std::size_t k = 0; k <= j; ++k) J.entry(j, k) = J.entry(k, j) = values[j * n + k];
    J.factor(shift);
    const bool stable = (eigenvalues.array() < shift).all();
    CHECK(bool(J.positive_definite()) == stable);
    auto r = random_values(n, 29, -1.0, 1.0);
    const Eigen::VectorXd rhs = Eigen::Map<Eigen::VectorXd>(r.data(), Eigen::Index(n));
    J.solve(r.data());
    const Eigen::MatrixXd M = shift * Eigen::MatrixXd::Identity(Eigen::Index(n), Eigen::Index(n)) - dense;
    const Eigen::VectorXd x = Eigen::Map<Eigen::VectorXd>(r.data(), Eigen::Index(n));
    CHECK((M * x - rhs).norm() < 1e-10 * (1 + x.norm()));
  }
}

TEST_CASE("the envelope LDLT of banded and ring matrices gives the dense one's bits",
          "[kernels][couplings]") {
  const std::size_t n = 12;
  for (bool wrap : {false, true})
    for (std::size_t band :
         {std::size_t(1), std::size_t(2), std::size_t(3), std::size_t(5), std::size_t(6)}) {
      INFO("band " << band << (wrap ? ", ring" : ", open"));
      auto dense = rotorsweep::testing::jacobian<DenseSymmetric<double>>(n);
      auto banded = rotorsweep::testing::jacobian<DenseSymmetric<double>>(n);
      banded.set_band(band, wrap);
      const auto values = random_values(n * n, 31 + band, -1.0, 1.0);
      for (double shift : {-3.0, 0.4, 1.5, 6.0}) {
        for (std::size_t j = 0; j < n; ++j)  // anew for each factor, which takes J's place
          for (std::size_t k = 0; k <= j; ++k) {
            const bool coupled = j - k <= band || (wrap && j - k >= n - band);
            const double x = coupled ? values[j * n + k] : 0.0;
            dense.entry(j, k) = dense.entry(k, j) = banded.entry(j, k) = banded.entry(k, j) = x;
          }
        dense.factor(shift);
        banded.factor(shift);
        CHECK(bool(dense.positive_definite()) == bool(banded.positive_definite()));
        auto a = random_values(n, 37, -1.0, 1.0), b = a;
        dense.solve(a.data());
        banded.solve(b.data());
        for (std::size_t i = 0; i < n; ++i) REQUIRE(a[i] == b[i]);
      }
    }
}

TEST_CASE("coupled rows: SIMD lanes give the scalar bits", "[kernels][model][couplings][simd]") {
  using Simd = CoupledRows<simd_lane>;
  constexpr std::size_t width = lane_width<simd_lane>;
  const std::size_t n = 11;
  const Table table(5, 31);
  auto simd = rotorsweep::testing::model<Simd>(
      n, every,
      Simd::Parameters{1.0, 1.0, false, table.a, table.b.data(), table.c.data(), table.b.size(), false});
  std::vector<Model> scalars;
  std::vector<std::vector<double>> thetas;
  simd_lane t(0.0);
  std::vector<simd_lane> theta(n);
  for (std::size_t l = 0; l < width; ++l) {
    const auto p = table.parameters(1.0 + double(l), 0.1 + 0.05 * double(l), false);
    simd.set_lane(l, Simd::Parameters{p.A, p.g, false, p.a, p.b, p.c, p.range, p.open});
    scalars.push_back(rotorsweep::testing::model<Model>(n, every, p));
    thetas.push_back(random_values(n, unsigned(40 + l), -3.0, 9.0));
    for (std::size_t j = 0; j < n; ++j) lane_set(theta[j], l, thetas[l][j]);
    lane_set(t, l, 0.3 * double(l));
  }
  auto w = rotorsweep::testing::workspace(simd);
  std::vector<simd_lane> f(n), q(nq);
  simd.evaluate(w, theta.data(), t, f.data(), q.data());
  for (std::size_t l = 0; l < width; ++l) {
    const auto e = evaluate(scalars[l], thetas[l], 0.3 * double(l));
    for (std::size_t j = 0; j < n; ++j) CHECK(lane_get(f[j], l) == e.f[j]);
    for (std::size_t p = 0; p < nq; ++p) CHECK(lane_get(q[p], l) == e.q[p]);
  }
}

TEST_CASE("coupled rows: the range forms over any split of the rows give the whole rows' bits",
          "[kernels][model][couplings][team]") {
  // periodic with 2M < N, and open with every pair, also M = N − 1; every quadrature
  for (const auto& [n, range, open] :
       {std::tuple{7u, 3u, false}, std::tuple{20u, 9u, false}, std::tuple{20u, 2u, false},
        std::tuple{7u, 6u, true}, std::tuple{20u, 5u, true}, std::tuple{2u, 1u, true}}) {
    const Table table(range, unsigned(n + range));
    const auto m = rotorsweep::testing::model<Model>(n, every, table.parameters(4.3, 0.37, open));
    const auto theta = random_values(n, unsigned(3 * n + range), -3.0, 9.0);
    const double t = 1.3;
    auto w = rotorsweep::testing::workspace(m);
    std::vector<double> f(n), q(nq), df_dt(n), dq_dy(nq * n), dq_dt(nq), drive(n), link(n);
    auto J = rotorsweep::testing::jacobian<Model::Jacobian>(n);
    m.linearize(w, theta.data(), t, f.data(), q.data(), J, df_dt.data(), dq_dy.data(), dq_dt.data());
    m.row_profile(w, theta.data(), t, drive.data(), link.data());
    for (std::size_t ranks : {1u, 2u, 3u, 8u}) {
      INFO("N " << n << ", range " << range << ", open " << open << ", ranks " << ranks);
      auto w2 = rotorsweep::testing::workspace(m);
      auto J2 = rotorsweep::testing::jacobian<Model::Jacobian>(n);
      std::vector<double> f2(n), df2(n), dq2(nq * n), scratch(n), time_sums(nq * ranks), drive2(n), link2(n),
          f3(n);
      Model::RowSums sums;
      Model::IntegrandSums more;
      for (std::size_t r = 0; r < ranks; ++r) {  // the phase before: every rank's trigonometry
        const TeamRows rows = team_rows(n, ranks, r);
        m.trigonometry_range(w2, theta.data(), t, rows.begin, rows.end);
      }
      for (std::size_t r = 0; r < ranks; ++r) {
        const TeamRows rows = team_rows(n, ranks, r);
        const Model::RowSums part = m.evaluate_range(w2, theta.data(), t, f2.data(), rows.begin, rows.end);
        const Model::IntegrandSums extra = m.integrand_sums_range(w2, f2.data(), rows.begin, rows.end);
        sums.lag += part.lag;
        sums.cos_link += part.cos_link;
        more.lag_force += extra.lag_force;
        more.force_squares += extra.force_squares;
        more.energy += extra.energy;
      }
      for (std::size_t r = 0; r < ranks; ++r) {  // once every rank's f is in place
        const TeamRows rows = team_rows(n, ranks, r);
        m.jacobian_range(w2, J2, df2.data(), rows.begin, rows.end);
        m.integrand_gradient_range(w2, f2.data(), J2, df2.data(), scratch.data(), dq2.data(),
                                   time_sums.data() + nq * r, t, rows.begin, rows.end);
        m.row_profile_range(w2, theta.data(), t, f3.data(), drive2.data(), link2.data(), rows.begin,
                            rows.end);
      }
      CHECK(f2 == f);
      CHECK(f3 == f);
      CHECK(df2 == df_dt);
      CHECK(dq2 == dq_dy);
      CHECK(drive2 == drive);
      for (std::size_t j = 0; j < m.links(); ++j) CHECK(link2[j] == link[j]);
      for (std::size_t j = 0; j < n; ++j)
        for (std::size_t k = 0; k < n; ++k) REQUIRE(J2.entry(j, k) == J.entry(j, k));
      std::vector<double> q2(nq), totals(nq), dq_dt2(nq);
      m.team_integrands(sums, more, t, q2.data());
      for (std::size_t p = 0; p < nq; ++p) {
        for (std::size_t r = 0; r < ranks; ++r) totals[p] += time_sums[nq * r + p];
        CHECK(q2[p] == Approx(q[p]).epsilon(1e-13).margin(1e-13));
      }
      m.team_time_derivatives(totals.data(), t, q2.data(), dq_dt2.data());
      for (std::size_t p = 0; p < nq; ++p) CHECK(dq_dt2[p] == Approx(dq_dt[p]).epsilon(1e-13).margin(1e-13));
    }
  }
}
