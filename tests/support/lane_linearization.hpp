// Test support: a row model's linearize() at one point (f, the integrands, J, ∂f/∂t and the
// integrands' gradients), and a lane of a SIMD model's compared with a scalar model's bit for bit.
#pragma once

#include <catch2/catch.hpp>
#include <cstddef>
#include <vector>

#include "kernels/lanes/lane.hpp"
#include "support/kernel_scratch.hpp"

namespace rotorsweep::testing {

template <class Model>
struct Linearization {
  using V = typename Model::lane_type;
  std::vector<V> f, q, df_dt, dq_dy, dq_dt;
  typename Model::Jacobian J;
};

/// `model`'s linearize() at (θ, t) with `quadratures` integrands, every lane at the same θ and t.
template <class Model>
Linearization<Model> linearize_at(const Model& model, const std::vector<double>& theta, double t,
                                  std::size_t quadratures) {
  using V = typename Model::lane_type;
  const std::size_t n = theta.size();
  Linearization<Model> out{std::vector<V>(n),     std::vector<V>(quadratures),     std::vector<V>(n),
                           std::vector<V>(quadratures * n), std::vector<V>(quadratures),
                           jacobian<typename Model::Jacobian>(n)};
  std::vector<V> theta_v(n);
  for (std::size_t j = 0; j < n; ++j) theta_v[j] = V(theta[j]);
  auto w = workspace(model);
  model.linearize(w, theta_v.data(), V(t), out.f.data(), out.q.data(), out.J, out.df_dt.data(),
                  out.dq_dy.data(), out.dq_dt.data());
  return out;
}

/// Lane `lane` of `simd` has `scalar`'s bits: f, ∂f/∂t, the integrands and their gradients, and J
/// as `same_jacobian(simd J, scalar J, lane)` says.
template <class Simd, class Scalar, class SameJacobian>
void check_lane_bits(const Linearization<Simd>& simd, std::size_t lane, const Linearization<Scalar>& scalar,
                     SameJacobian&& same_jacobian) {
  INFO("lane " << lane);
  for (std::size_t j = 0; j < scalar.f.size(); ++j) {
    CHECK(kernels::lane_get(simd.f[j], lane) == scalar.f[j]);
    CHECK(kernels::lane_get(simd.df_dt[j], lane) == scalar.df_dt[j]);
  }
  same_jacobian(simd.J, scalar.J, lane);
  for (std::size_t p = 0; p < scalar.q.size(); ++p) CHECK(kernels::lane_get(simd.q[p], lane) == scalar.q[p]);
  for (std::size_t k = 0; k < scalar.dq_dy.size(); ++k)
    CHECK(kernels::lane_get(simd.dq_dy[k], lane) == scalar.dq_dy[k]);
}

}  // namespace rotorsweep::testing
