// The step-size controllers (docs/numerics.md "Step-size control"): the integral factor
// safety·err^(−1/k), the PI factor safety·err^(−(1/k − 0.03))·previous^0.04 after accepted steps,
// bounds, and how an error is weighed against the tolerances.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "kernels/step_control.hpp"

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
