// Tests of the row model (kernels/models/rows/nearest_neighbour_rows.hpp, docs/model.md §1, §3, §7): the
// Jacobian, ∂f/∂t and the integrand gradients against central differences, uniform and with per-row disorder;
// f = -∇H/g; N = 2 is the two-angle H_r; the disordered equations written out; zero deviations
// give the uniform model's bits; a displaced stage evaluation agrees with evaluate(); models that
// carry fewer integrals (and store no trigonometry) give the same bits.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "support/kernel_scratch.hpp"
#include "support/lane_linearization.hpp"
#include "support/linearization_check.hpp"

using namespace rotorsweep::kernels;

namespace {

constexpr Integrals every = all_integrals;
using Model = NearestNeighbourRows<double>;
constexpr std::size_t nq = every.count();

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

/// Per-row deviations of size 0.1–0.3 in all three quantities, different for each.
struct Deviations {
  std::vector<double> A, anisotropy, coupling;
  explicit Deviations(std::size_t n) {
    for (std::size_t j = 0; j < n; ++j) {
      A.push_back(0.3 * std::sin(1.0 + double(j)));
      anisotropy.push_back(0.2 * std::cos(2.0 * double(j)));
      coupling.push_back(0.25 * std::sin(0.5 + 3.0 * double(j)));
    }
  }
  Model::Parameters parameters(double A_value, double g) const {
    return {A_value, g, false, A.data(), anisotropy.data(), coupling.data()};
  }
};

}  // namespace

TEST_CASE("Jacobian, df/dt and integrand gradients match central differences", "[kernels][model]") {
  for (std::size_t n : {2u, 4u, 7u, 20u})
    for (bool disordered : {false, true}) {
      const Deviations d(n);
      const auto m = disordered ? rotorsweep::testing::model<Model>(n, every, d.parameters(4.3, 0.37))
                                : rotorsweep::testing::model<Model>(n, every, 4.3, 0.37);
      INFO("disordered " << disordered);
      const auto theta = random_angles(n, unsigned(n));
      rotorsweep::testing::check_linearization(m, theta, 1.9);
    }
}

TEST_CASE("the flow is the gradient of the energy: g f = -dH/dtheta", "[kernels][model]") {
  const std::size_t n = 6;
  const double g = 0.05, t = 0.4, eps = 1e-6;
  const Deviations d(n);
  for (const auto& m : {rotorsweep::testing::model<Model>(n, every, 2.0, g),
                        rotorsweep::testing::model<Model>(n, every, d.parameters(2.0, g))}) {
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
}

TEST_CASE("per-row disorder: the equations of docs/model.md section 7 written out", "[kernels][model]") {
  const std::size_t n = 5;
  const double A = 3.0, g = 0.2, t = 0.7;
  const Deviations d(n);
  const auto m = rotorsweep::testing::model<Model>(n, every, d.parameters(A, g));
  const auto theta = random_angles(n, 11);
  const auto e = evaluate(m, theta, t);
  auto w = rotorsweep::testing::workspace(m);
  double H = 0, drive = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t jp = (j + 1) % n, jm = (j + n - 1) % n;
    const double A_j = A * (1 + d.A[j]), a_j = 1.5 * (1 + d.anisotropy[j]);
    const double b_j = 1 + d.coupling[j], b_jm = 1 + d.coupling[jm];
    const double torque = -2 * a_j * std::sin(2 * theta[j]) + b_j * std::sin(theta[j] - theta[jp]) +
                          b_jm * std::sin(theta[j] - theta[jm]) + A_j * std::sin(theta[j] - t);
    CHECK(e.f[j] == Approx(torque / g).epsilon(1e-13));
    H += -a_j * std::cos(2 * theta[j]) + b_j * std::cos(theta[j] - theta[jp]) + A_j * std::cos(theta[j] - t);
    drive += A_j * std::sin(theta[j] - t);
  }
  CHECK(m.energy(w, theta.data(), t) == Approx(H).epsilon(1e-13));
  CHECK(e.q[every.drive_index()] == Approx(drive).epsilon(1e-13));
}

TEST_CASE("a lane with zero deviations beside a disordered lane keeps the uniform bits", "[kernels][model]") {
  using Simd = NearestNeighbourRows<simd_lane>;
  const std::size_t n = 9;
  const double t = 1.1;
  const Deviations d(n);
  const std::vector<double> zeros(n, 0.0);
  auto simd = rotorsweep::testing::model<Simd>(n, every, Simd::Parameters{4.0, 0.01});
  simd.set_lane(0, {4.0, 0.01, false, d.A.data(), d.anisotropy.data(), d.coupling.data()});
  simd.set_lane(1, {4.0, 0.01, false, zeros.data(), zeros.data(), zeros.data()});
  const auto uniform = rotorsweep::testing::model<Model>(n, every, 4.0, 0.01);
  const auto theta = random_angles(n, 5);
  const auto lanes = rotorsweep::testing::linearize_at(simd, theta, t, nq);
  const auto scalar = rotorsweep::testing::linearize_at(uniform, theta, t, nq);
  for (std::size_t l = 1; l < std::min<std::size_t>(3, lane_width<simd_lane>); ++l)  // SSE2: lane 1 only
    rotorsweep::testing::check_lane_bits(lanes, l, scalar, [&](const auto& J_v, const auto& J, std::size_t lane) {
      for (std::size_t j = 0; j < n; ++j) {
        CHECK(lane_get(J_v.diag(j), lane) == J.diag(j));
        CHECK(lane_get(J_v.off(j), lane) == J.off(j));
      }
    });
  CHECK(lane_get(lanes.f[0], 0) != scalar.f[0]);  // lane 0 is disordered
}

TEST_CASE("a stage evaluation displaced from the linearisation point is evaluate() there",
          "[kernels][model]") {
  // within the Taylor reach to rounding; beyond it (every |δ| > 1/16) the same bits, since then each
  // sincos is lane_sincos(θ_j + δ_j) and lane_sincos(t + τ)
  const std::size_t n = 20;
  const double t = 7.9;
  const Deviations d(n);
  for (bool disordered : {false, true})
    for (double size : {1e-9, 3e-3, 0.06, 0.3}) {
      INFO("disordered " << disordered << ", |delta| up to " << size);
      const auto m = disordered ? rotorsweep::testing::model<Model>(n, every, d.parameters(4.3, 0.01))
                                : rotorsweep::testing::model<Model>(n, every, 4.3, 0.01);
      const auto theta = random_angles(n, 17);
      std::vector<double> delta(n), moved(n);
      for (std::size_t j = 0; j < n; ++j) {
        delta[j] = size * (j % 2 ? 1.0 : -1.0) * (0.5 + 0.5 * std::fabs(std::sin(double(j))));
        if (size > displaced_sincos_reach) delta[j] = std::copysign(size, delta[j]);
        moved[j] = theta[j] + delta[j];
      }
      const double tau = -0.7 * size;
      auto w = rotorsweep::testing::workspace(m);
      auto J = rotorsweep::testing::jacobian<Model::Jacobian>(n);
      std::vector<double> f(n), q(nq), df_dt(n), dq_dy(nq * n), dq_dt(nq);
      m.linearize(w, theta.data(), t, f.data(), q.data(), J, df_dt.data(), dq_dy.data(), dq_dt.data());
      m.evaluate_displaced(w, theta.data(), delta.data(), t, tau, f.data(), q.data());
      const auto e = evaluate(m, moved, t + tau);
      const double scale = (4.3 * 1.3 + 6.0) / 0.01;  // bound on |f|
      for (std::size_t j = 0; j < n; ++j) {
        if (size > displaced_sincos_reach)
          CHECK(f[j] == e.f[j]);
        else
          CHECK(std::fabs(f[j] - e.f[j]) <= 1e-14 * scale);
      }
      for (std::size_t p = 0; p < nq; ++p) {
        if (size > displaced_sincos_reach)
          CHECK(q[p] == e.q[p]);
        else
          CHECK(q[p] == Approx(e.q[p]).epsilon(1e-12).margin(1e-12));
      }
    }
}

TEST_CASE("two rows reduce to the two-angle landscape H_r and its alignment", "[kernels][model]") {
  const double A = 5.5, te = 0.8, to = 2.9, tau = 1.3;
  const auto m = rotorsweep::testing::model<Model>(2, every, A, 1.0);
  auto w = rotorsweep::testing::workspace(m);
  const double theta[2] = {te, to};
  const double H_r = -1.5 * (std::cos(2 * te) + std::cos(2 * to)) + 2 * std::cos(te - to) +
                     A * (std::cos(te - tau) + std::cos(to - tau));
  CHECK(m.energy(w, theta, tau) == Approx(H_r).epsilon(1e-14));
  // ρ̄ as the ∫ρ̄ quadrature's integrand: the mean over the two links of cos²((θ_e − θ_o)/2)
  const double zeta = std::cos((te - to) / 2);
  CHECK(evaluate(m, {te, to}, tau).q[every.alignment_index()] == Approx(zeta * zeta).epsilon(1e-14));
}

TEST_CASE("two disordered rows reduce to the two-angle energy with per-row parameters", "[kernels][model]") {
  // H_r = -a0 cos 2θe - a1 cos 2θo + (b0 + b1) cos(θe - θo) + A0 cos(θe - τ) + A1 cos(θo - τ)
  const double A = 5.5, te = 0.8, to = 2.9, tau = 1.3;
  const Deviations d(2);
  const auto m = rotorsweep::testing::model<Model>(2, every, d.parameters(A, 1.0));
  auto w = rotorsweep::testing::workspace(m);
  const double theta[2] = {te, to};
  const double H_r = -1.5 * (1 + d.anisotropy[0]) * std::cos(2 * te) -
                     1.5 * (1 + d.anisotropy[1]) * std::cos(2 * to) +
                     (2 + d.coupling[0] + d.coupling[1]) * std::cos(te - to) +
                     A * ((1 + d.A[0]) * std::cos(te - tau) + (1 + d.A[1]) * std::cos(to - tau));
  CHECK(m.energy(w, theta, tau) == Approx(H_r).epsilon(1e-14));
}

TEST_CASE("quadrature integrands follow model.md section 3", "[kernels][model]") {
  const std::size_t n = 5;
  const double A = 3.0, g = 0.2, t = 0.7;
  const auto m = rotorsweep::testing::model<Model>(n, every, A, g);
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

namespace {

/// f and the quadratures at θ (evaluate), and at θ + δ, t + τ (evaluate_displaced after
/// linearize, whose f must be evaluate's), for a model carrying `carried`.
struct FourEvaluations {
  std::vector<double> f, q, f_displaced, q_displaced;
};

FourEvaluations four_evaluations(Integrals carried, const Model::Parameters& p,
                                 const std::vector<double>& theta, const std::vector<double>& delta, double t,
                                 double tau) {
  const std::size_t n = theta.size();
  const std::size_t count = carried.count();
  const auto m = rotorsweep::testing::model<Model>(n, carried, p);
  auto w = rotorsweep::testing::workspace(m);
  auto J = rotorsweep::testing::jacobian<Model::Jacobian>(n);
  FourEvaluations e{std::vector<double>(n), std::vector<double>(count), std::vector<double>(n),
                    std::vector<double>(count)};
  std::vector<double> f(n), q(count), df_dt(n), dq_dy(count * n), dq_dt(count);
  m.evaluate(w, theta.data(), t, e.f.data(), e.q.data());
  m.linearize(w, theta.data(), t, f.data(), q.data(), J, df_dt.data(), dq_dy.data(), dq_dt.data());
  CHECK(f == e.f);
  m.evaluate_displaced(w, theta.data(), delta.data(), t, tau, e.f_displaced.data(), e.q_displaced.data());
  return e;
}

}  // namespace

TEST_CASE("models carrying fewer integrals give the same torques, R, S and rho-bar bits",
          "[kernels][model]") {
  // without W and H an evaluation stores nothing in the workspace and takes the sums of R and ρ̄
  // in its one pass over the rows; with them it stores every row's trigonometry: the bits agree.
  // S alone (docs/architecture.md's stokes_power example) is carried without W.
  constexpr Integrals drive_and_alignment{true, false, false, true, false, false};
  constexpr Integrals drive_and_stokes{true, false, true, false, false, false};
  const double t = 2.3, tau = 4e-3;
  for (std::size_t n : {2u, 3u, 20u})
    for (bool disordered : {false, true}) {
      INFO("n " << n << ", disordered " << disordered);
      const Deviations d(n);
      const double* A_rows = disordered ? d.A.data() : nullptr;
      const double* anisotropy_rows = disordered ? d.anisotropy.data() : nullptr;
      const double* coupling_rows = disordered ? d.coupling.data() : nullptr;
      const auto theta = random_angles(n, 23);
      std::vector<double> delta(n);
      for (std::size_t j = 0; j < n; ++j) delta[j] = 1e-3 * std::sin(3.0 * double(j) + 1.0);
      const auto full = four_evaluations(every, {4.1, 0.02, false, A_rows, anisotropy_rows, coupling_rows},
                                         theta, delta, t, tau);
      const auto lean =
          four_evaluations(drive_and_alignment, {4.1, 0.02, false, A_rows, anisotropy_rows, coupling_rows},
                           theta, delta, t, tau);
      const auto leanest = four_evaluations(
          dissipation_only, {4.1, 0.02, false, A_rows, anisotropy_rows, coupling_rows}, theta, delta, t, tau);
      const auto stokes = four_evaluations(
          drive_and_stokes, {4.1, 0.02, false, A_rows, anisotropy_rows, coupling_rows}, theta, delta, t, tau);
      CHECK(lean.f == full.f);
      CHECK(leanest.f == full.f);
      CHECK(lean.f_displaced == full.f_displaced);
      CHECK(leanest.f_displaced == full.f_displaced);
      for (const auto* e : {&full, &lean, &leanest}) CHECK(e->f_displaced != e->f);  // δ moved them
      const std::size_t R = every.drive_index(), rho = every.alignment_index();
      CHECK(lean.q[drive_and_alignment.drive_index()] == full.q[R]);
      CHECK(lean.q[drive_and_alignment.alignment_index()] == full.q[rho]);
      CHECK(leanest.q[0] == full.q[R]);
      CHECK(lean.q_displaced[drive_and_alignment.drive_index()] == full.q_displaced[R]);
      CHECK(lean.q_displaced[drive_and_alignment.alignment_index()] == full.q_displaced[rho]);
      CHECK(leanest.q_displaced[0] == full.q_displaced[R]);
      const std::size_t S = every.stokes_index();
      CHECK(stokes.f == full.f);
      CHECK(stokes.q[drive_and_stokes.stokes_index()] == full.q[S]);
      CHECK(stokes.q_displaced[drive_and_stokes.stokes_index()] == full.q_displaced[S]);
      CHECK(stokes.q[drive_and_stokes.stokes_index()] != 0.0);
    }
}
