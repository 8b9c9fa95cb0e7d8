// The paper's table of dissipation integrals (model.md §3; N = 20, g = 0.0011, two relaxation
// periods, two averaged), and agreement of the three estimators W, S, R outside the CP regime.
#include <catch2/catch.hpp>

#include "kernels/rosenbrock.hpp"
#include "support/member_run.hpp"

using namespace rotorsweep::kernels;
using rotorsweep::testing::mean_period_integrals;
using rotorsweep::testing::Start;

namespace {

constexpr Integrals estimators{true, true, true, false, false};

double dissipation(double A, Start start, double rtol) {
  return mean_period_integrals<dissipation_only, Rodas4>(20, A, 0.0011, start, 2, 2, rtol, rtol * 1e-3)[0];
}

}  // namespace

TEST_CASE("paper table, FM and AFM regimes, to 1e-5 relative", "[kernels][paper]") {
  CHECK(dissipation(1.0, Start::fm, 1e-9) == Approx(2.018948e-3).epsilon(1e-5));
  CHECK(dissipation(1.0, Start::afm, 1e-9) == Approx(7.184589e-4).epsilon(1e-5));
  CHECK(dissipation(4.0, Start::afm, 1e-9) == Approx(2.296052e-2).epsilon(1e-5));
  CHECK(dissipation(11.0, Start::afm, 1e-9) == Approx(0.1654868).epsilon(1e-5));
  CHECK(dissipation(11.0, Start::fm, 1e-9) == Approx(0.1654868).epsilon(1e-5));
}

TEST_CASE("paper table, CP regime, within 3 percent", "[kernels][paper]") {
  CHECK(dissipation(6.0, Start::afm, 1e-9) == Approx(34.1).epsilon(0.03));
  CHECK(dissipation(8.0, Start::afm, 1e-9) == Approx(5.75).epsilon(0.03));
}

TEST_CASE("work, Stokes and drive estimators agree in the periodic steady state", "[kernels][paper]") {
  for (auto [A, start] :
       {std::pair{1.0, Start::fm}, {1.0, Start::afm}, {4.0, Start::afm}, {11.0, Start::afm}}) {
    const auto q = mean_period_integrals<estimators, Rodas4>(20, A, 0.0011, start, 2, 2, 1e-11, 1e-14);
    const double R = q[estimators.drive_index()];
    INFO("A = " << A);
    CHECK(q[estimators.work_index()] == Approx(R).epsilon(1e-6));
    CHECK(q[estimators.stokes_index()] == Approx(R).epsilon(1e-6));
  }
}
