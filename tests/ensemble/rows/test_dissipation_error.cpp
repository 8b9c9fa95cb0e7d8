// The dissipation's error estimate (channel dissipation_error): outside the CP regime it bounds
// the actual error of D against a tight-tolerance run with every Rosenbrock stepper (each with its
// swing_error_factor), and D at g = 1e-7 is flagged unresolved.
#include <catch2/catch.hpp>
#include <cmath>
#include <iomanip>

#include "kernels/steppers/step_control.hpp"
#include "support/member_run.hpp"

using namespace rotorsweep::testing;

TEST_CASE("the estimated error of D bounds its actual error outside CP", "[ensemble][dissipation_error]") {
  const struct {
    double A, g;
    Start start;
  } members[] = {{1.0, 0.0011, Start::afm},
                 {11.0, 0.0011, Start::fm},
                 {4.0, 0.1, Start::afm},
                 {12.0, 0.1, Start::fm},
                 {0.5, 0.01, Start::afm}};
  for (const auto& m : members) {
    const auto reference = run_member(20, m.A, m.g, m.start, 2, 2, 1e-11, 1e-14);
    for (const char* stepper : {"rodas4", "rodas4p2", "rodas5p"})
      for (double rtol : {1e-4, 1e-6, 1e-8}) {
        const auto r = run_member(20, m.A, m.g, m.start, 2, 2, rtol, rtol * 1e-3, stepper);
        INFO(std::setprecision(10) << stepper << ", A = " << m.A << ", g = " << m.g << ", rtol " << rtol
                                   << ": D = " << r.dissipation() << " ± " << r.dissipation_error()
                                   << ", reference " << reference.dissipation());
        CHECK(std::fabs(r.dissipation() - reference.dissipation()) <= r.dissipation_error());
        // never below the tolerance R is held to
        CHECK(r.dissipation_error() >=
              rtol / rotorsweep::kernels::remainder_tightening * std::fabs(r.dissipation()));
      }
    CHECK(reference.dissipation_resolved());
  }
}

TEST_CASE("D below its integration noise is flagged unresolved", "[ensemble][dissipation_error]") {
  // g = 1e-7 at the default tolerances: D is a remainder of about 1e-9 of a swing of about 2NA,
  // below what an estimate from the swing can vouch for
  const auto noisy = run_member(20, 1.0, 1e-7, Start::afm, 2, 2, 1e-6, 1e-9);
  INFO("D = " << noisy.dissipation() << " ± " << noisy.dissipation_error());
  CHECK_FALSE(noisy.dissipation_resolved());
  CHECK(noisy.dissipation_error() > 0.1 * std::fabs(noisy.dissipation()));
  const auto resolved = run_member(20, 1.0, 1e-3, Start::afm, 2, 2, 1e-6, 1e-9);
  CHECK(resolved.dissipation_resolved());
}
