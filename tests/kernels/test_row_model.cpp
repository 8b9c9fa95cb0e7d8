// Tests of the row model (kernels/row_model.hpp, docs/model.md §1 and §3): the Jacobian, ∂f/∂t and
// the integrand gradients against central differences; f = -∇H/g; N = 2 is the two-angle H_r.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/row_model.hpp"
#include "support/kernel_scratch.hpp"

using namespace rotorsweep::kernels;

namespace {

constexpr Integrals every = all_integrals;
using Model = NearestNeighbourRows<double, every>;
constexpr std::size_t nq = Model::quadrature_count;

std::vector<double> random_angles(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-3.0, 9.0);
  std::vector<double> theta(n);
  for (auto& x : theta) x = u(rng);
  return theta;
}

struct Evaluation {
  std::vector<double> f, q;
};

Evaluation evaluate(const Model& m, std::vector<double> theta, double t) {
  auto w = rotorsweep::testing::workspace(m);
  Evaluation e{std::vector<double>(theta.size()), std::vector<double>(nq)};
  m.evaluate(w, theta.data(), t, e.f.data(), e.q.data());
  return e;
}

}  // namespace

TEST_CASE("Jacobian, df/dt and integrand gradients match central differences", "[kernels][model]") {
  for (std::size_t n : {2u, 4u, 7u, 20u}) {
    const Model m(n, 4.3, 0.37);
    const auto theta = random_angles(n, unsigned(n));
    const double t = 1.9, eps = 1e-6;

    auto w = rotorsweep::testing::workspace(m);
    std::vector<double> f(n), q(nq), df_dt(n), dq_dy(nq * n), dq_dt(nq);
    auto J = rotorsweep::testing::jacobian<Model::Jacobian>(n);
    m.linearize(w, theta.data(), t, f.data(), q.data(), J, df_dt.data(), dq_dy.data(), dq_dt.data());

    for (std::size_t k = 0; k < n; ++k) {
      auto plus = theta, minus = theta;
      plus[k] += eps;
      minus[k] -= eps;
      const auto ep = evaluate(m, plus, t), em = evaluate(m, minus, t);
      std::vector<double> unit(n, 0.0), column(n, 0.0);
      unit[k] = 1.0;
      J.multiply_add(unit.data(), column.data());
      for (std::size_t j = 0; j < n; ++j) {
        INFO("n=" << n << " d f_" << j << " / d theta_" << k);
        CHECK(column[j] == Approx((ep.f[j] - em.f[j]) / (2 * eps)).epsilon(1e-6).margin(1e-6));
      }
      for (std::size_t p = 0; p < nq; ++p) {
        INFO("n=" << n << " d q_" << p << " / d theta_" << k);
        CHECK(dq_dy[p * n + k] == Approx((ep.q[p] - em.q[p]) / (2 * eps)).epsilon(1e-6).margin(1e-6));
      }
    }
    const auto ep = evaluate(m, theta, t + eps), em = evaluate(m, theta, t - eps);
    for (std::size_t j = 0; j < n; ++j)
      CHECK(df_dt[j] == Approx((ep.f[j] - em.f[j]) / (2 * eps)).epsilon(1e-6).margin(1e-6));
    for (std::size_t p = 0; p < nq; ++p)
      CHECK(dq_dt[p] == Approx((ep.q[p] - em.q[p]) / (2 * eps)).epsilon(1e-6).margin(1e-6));
  }
}

TEST_CASE("the flow is the gradient of the energy: g f = -dH/dtheta", "[kernels][model]") {
  const std::size_t n = 6;
  const double g = 0.05, t = 0.4, eps = 1e-6;
  const Model m(n, 2.0, g);
  const auto theta = random_angles(n, 3);
  const auto e = evaluate(m, theta, t);
  auto w = rotorsweep::testing::workspace(m);
  for (std::size_t k = 0; k < n; ++k) {
    auto plus = theta, minus = theta;
    plus[k] += eps;
    minus[k] -= eps;
    const double dH = (m.energy(w, plus.data(), t) - m.energy(w, minus.data(), t)) / (2 * eps);
    CHECK(g * e.f[k] == Approx(-dH).epsilon(1e-7).margin(1e-8));
  }
}

TEST_CASE("two rows reduce to the two-angle landscape H_r and its alignment", "[kernels][model]") {
  const double A = 5.5, te = 0.8, to = 2.9, tau = 1.3;
  const Model m(2, A, 1.0);
  auto w = rotorsweep::testing::workspace(m);
  const double theta[2] = {te, to};
  const double H_r = -1.5 * (std::cos(2 * te) + std::cos(2 * to)) + 2 * std::cos(te - to) +
                     A * (std::cos(te - tau) + std::cos(to - tau));
  CHECK(m.energy(w, theta, tau) == Approx(H_r).epsilon(1e-14));
  const double zeta = std::cos((te - to) / 2);
  CHECK(m.alignment(w, theta, tau) == Approx(zeta * zeta).epsilon(1e-14));
}

TEST_CASE("quadrature integrands follow model.md section 3", "[kernels][model]") {
  const std::size_t n = 5;
  const double A = 3.0, g = 0.2, t = 0.7;
  const Model m(n, A, g);
  const auto theta = random_angles(n, 9);
  const auto e = evaluate(m, theta, t);
  double drive = 0, work = 0, stokes = 0, align = 0;
  for (std::size_t j = 0; j < n; ++j) {
    drive += A * std::sin(theta[j] - t);
    work += A * std::sin(theta[j] - t) * e.f[j];
    stokes += g * e.f[j] * e.f[j];
    const double half = std::cos((theta[j] - theta[(j + 1) % n]) / 2);
    align += half * half / n;
  }
  CHECK(e.q[every.drive_index()] == Approx(drive).epsilon(1e-13));
  CHECK(e.q[every.work_index()] == Approx(work).epsilon(1e-13));
  CHECK(e.q[every.stokes_index()] == Approx(stokes).epsilon(1e-13));
  CHECK(e.q[every.alignment_index()] == Approx(align).epsilon(1e-13));
}
