// Test support: a row model's linearize() against central differences of evaluate(): the Jacobian
// (through multiply_add), ∂f/∂t, and the quadrature integrands' gradients in θ and t.
#pragma once

#include <catch2/catch.hpp>
#include <cstddef>
#include <vector>

#include "support/kernel_scratch.hpp"

namespace rotorsweep::testing {

/// `margin`: the absolute error allowed beside 1e-6 relative (f's rounding over the difference step: 1e-6
/// for direct sums; more where f's rounding is larger, as after FFTs scaled by 1/I).
template <class Model>
void check_linearization(const Model& m, const std::vector<double>& theta, double t, double margin = 1e-6) {
  const std::size_t nq = m.quadrature_count();
  const std::size_t n = theta.size();
  const double eps = 1e-6;
  struct Evaluation {
    std::vector<double> f, q;
  };
  const auto evaluate = [&](const std::vector<double>& at, double time) {
    auto w = workspace(m);
    Evaluation e{std::vector<double>(n), std::vector<double>(nq)};
    m.evaluate(w, at.data(), time, e.f.data(), e.q.data());
    return e;
  };
  auto w = workspace(m);
  std::vector<double> f(n), q(nq), df_dt(n), dq_dy(nq * n), dq_dt(nq);
  auto J = jacobian<typename Model::Jacobian>(n);
  m.linearize(w, theta.data(), t, f.data(), q.data(), J, df_dt.data(), dq_dy.data(), dq_dt.data());
  for (std::size_t k = 0; k < n; ++k) {
    auto plus = theta, minus = theta;
    plus[k] += eps;
    minus[k] -= eps;
    const auto ep = evaluate(plus, t), em = evaluate(minus, t);
    std::vector<double> unit(n, 0.0), column(n, 0.0);
    unit[k] = 1.0;
    J.multiply_add(unit.data(), column.data());
    for (std::size_t j = 0; j < n; ++j) {
      INFO("n=" << n << " d f_" << j << " / d theta_" << k);
      CHECK(column[j] == Approx((ep.f[j] - em.f[j]) / (2 * eps)).epsilon(1e-6).margin(margin));
    }
    for (std::size_t p = 0; p < nq; ++p) {
      INFO("n=" << n << " d q_" << p << " / d theta_" << k);
      CHECK(dq_dy[p * n + k] == Approx((ep.q[p] - em.q[p]) / (2 * eps)).epsilon(1e-6).margin(1e-6));
    }
  }
  const auto ep = evaluate(theta, t + eps), em = evaluate(theta, t - eps);
  for (std::size_t j = 0; j < n; ++j)
    CHECK(df_dt[j] == Approx((ep.f[j] - em.f[j]) / (2 * eps)).epsilon(1e-6).margin(margin));
  for (std::size_t p = 0; p < nq; ++p)
    CHECK(dq_dt[p] == Approx((ep.q[p] - em.q[p]) / (2 * eps)).epsilon(1e-6).margin(1e-6));
}

}  // namespace rotorsweep::testing
