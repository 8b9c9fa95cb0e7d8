// The step-size controllers (docs/numerics.md "Steppers and integration"): the integral factor
// safety·err^(−1/k), the PI factor safety·err^(−(1/k − 0.03))·previous^0.04 after accepted steps,
// bounds, how an error is weighed against the tolerances, and the norm that holds R apart.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "kernels/steppers/step_control.hpp"

using namespace rotorsweep::kernels;
using Catch::Detail::Approx;

TEST_CASE("the integral and PI step factors", "[kernels][controller]") {
  StepLimits integral;
  StepLimits pi;
  pi.controller = StepController::pi;
  const int embedded = 3;  // k = 4
  for (const double err : {0.05, 0.5, 0.9}) {
    INFO("err " << err);
    CHECK(step_factor(integral, embedded, err, 0.3, true) ==
          Approx(0.9 * std::pow(err, -0.25)).epsilon(1e-14));
    CHECK(step_factor(pi, embedded, err, 0.3, true) ==
          Approx(0.9 * std::pow(err, -0.22) * std::pow(0.3, 0.04)).epsilon(1e-14));
    // the integral factor does not depend on the previous error
    CHECK(step_factor(integral, embedded, err, 0.3, true) == step_factor(integral, embedded, err, 1.0, true));
  }
  // after a rejected step both controllers shrink by the integral factor, and never grow
  CHECK(step_factor(pi, embedded, 4.0, 0.01, false) == step_factor(integral, embedded, 4.0, 0.01, false));
  CHECK(step_factor(pi, embedded, 1.05, 1e-4, false) <= 1.0);
  // bounds: growth at most grow_max, shrinking at most shrink_min, non-finite errors shrink most
  CHECK(step_factor(pi, embedded, 1e-12, 1.0, true) == pi.grow_max);
  CHECK(step_factor(pi, embedded, 1e12, 1.0, false) == pi.shrink_min);
  CHECK(step_factor(pi, embedded, std::nan(""), 1.0, false) == pi.shrink_min);
}

TEST_CASE("PI: a previous error below one holds the growth back", "[kernels][controller]") {
  StepLimits pi;
  pi.controller = StepController::pi;
  // the same error after a step that was very accurate (previous 1e-4) grows h less than after
  // one at the tolerance (previous 1): the controller damps the oscillation of h
  CHECK(step_factor(pi, 3, 0.2, pi_error_floor, true) < step_factor(pi, 3, 0.2, 1.0, true));
}

TEST_CASE("errors are weighed absolutely, relatively, or relatively but capped at the absolute scale",
          "[kernels][controller]") {
  const Tolerances tol{1e-6, 1e-9};
  const double inv = 1.0 / (tol.atol + tol.rtol);
  const double error = 3e-7;
  for (const double size : {1e-3, 0.5, 2.0, 40.0}) {
    INFO("size " << size);
    CHECK(scaled_error(StateScale::absolute, tol, inv, error, size, -size) == error * inv);
    CHECK(scaled_error(StateScale::relative, tol, inv, error, size, -0.5 * size) ==
          Approx(error / (tol.atol + tol.rtol * size)).epsilon(1e-15));
    // below one like relative, above one like absolute: never looser than the angles
    CHECK(scaled_error(StateScale::capped_relative, tol, inv, error, 0.5 * size, size) ==
          Approx(error / (tol.atol + tol.rtol * std::min(size, 1.0))).epsilon(1e-15));
  }
}

namespace {
/// Two absolute components and two quadratures: a capped-relative one (R) and a relative one.
struct TwoAnglesAndR {
  bool r_only = false;  ///< only R steers the step (else both quadratures)
  std::size_t quadrature_count() const { return 2; }
  bool error_controlled(std::size_t p) const { return p == 0 || !r_only; }
  std::size_t dimension() const { return 2; }
  StateScale scale(std::size_t) const { return StateScale::absolute; }
  StateScale quadrature_scale(std::size_t p) const {
    return p == 0 ? StateScale::capped_relative : StateScale::relative;
  }
};
}  // namespace

TEST_CASE("the error norm holds R apart, remainder_tightening times tighter", "[kernels][controller]") {
  const Tolerances tol{1e-6, 1e-9};
  const double s = tol.atol + tol.rtol;  // every scale here, with |y| = 1
  TwoAnglesAndR model;
  const double y[2] = {1.0, 1.0};
  const double q[2] = {1.0, 1.0};
  // angles' RMS 1/sqrt(2) of the tolerance, R at 1/16 of it: R (8/16 = 0.5) is below the RMS
  const double y_error[2] = {s, 0.0};
  double q_error[2] = {s / 16, 0.0};
  model.r_only = true;
  CHECK(error_norm(model, tol, y, y, y_error, q, q, q_error) == Approx(std::sqrt(0.5)).epsilon(1e-14));
  // R at a quarter of the tolerance sets the norm: 8/4 = 2, though the RMS with R would be 0.6
  q_error[0] = s / 4;
  CHECK(error_norm(model, tol, y, y, y_error, q, q, q_error) == Approx(2.0).epsilon(1e-14));
  // the relative quadrature enters the RMS: sqrt((1 + 0 + 4) / 3) with R small again
  q_error[0] = 0.0;
  q_error[1] = 2 * s;
  model.r_only = false;
  CHECK(error_norm(model, tol, y, y, y_error, q, q, q_error) == Approx(std::sqrt(5.0 / 3)).epsilon(1e-14));
  // a non-finite error in either part gives a non-finite norm
  q_error[0] = std::nan("");
  CHECK_FALSE(std::isfinite(error_norm(model, tol, y, y, y_error, q, q, q_error)));
  q_error[0] = 0.0;
  const double bad_angle[2] = {INFINITY, 0.0};
  CHECK_FALSE(std::isfinite(error_norm(model, tol, y, y, bad_angle, q, q, q_error)));
}
