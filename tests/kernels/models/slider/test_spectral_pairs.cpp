// The slider over spectral pairs (kernels/models/slider/spectral_pairs.hpp): f, the integrands and the energy
// equal the direct pairs' to rounding over square, oblong, shifted and turned grids (a rigid turn leaves P
// and Q as they are); its linearisation against central differences; a Rosenbrock run beside the dense one.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/models/slider/slider_model.hpp"
#include "kernels/models/slider/spectral_pairs.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "support/kernel_scratch.hpp"
#include "support/linearization_check.hpp"
#include "support/slider_fixture.hpp"

using namespace rotorsweep::kernels;
using namespace rotorsweep::testing::slider_fixture;

namespace {

template <bool Inertial>
using Direct = SliderModel<double, Inertial>;
template <bool Inertial>
using Spectral = SliderModel<double, Inertial, SpectralPairs<double>>;

/// f, the integrands and E of both pair sums at (y, t): equal to rounding.
template <bool Inertial>
void check_same_evaluation(SliderGrid grid, const SliderPlacement& placement, double eta, unsigned seed) {
  INFO(grid.columns << " x " << grid.rows << ", tilt " << placement.tilt << (Inertial ? ", inertial" : ""));
  const Substrate s(grid, eta, 3 * std::max(grid.columns, grid.rows), placement);
  const auto direct = make_model<Direct<Inertial>>(grid, parameters<Direct<Inertial>>(s, 0.5), placement);
  const auto spectral =
      make_model<Spectral<Inertial>>(grid, parameters<Spectral<Inertial>>(s, 0.5), placement);
  const std::size_t dim = direct.dimension();
  const auto y = random_state(dim, seed, Inertial ? 1.0 : 0.0);
  auto wd = rotorsweep::testing::workspace(direct);
  auto ws = rotorsweep::testing::workspace(spectral);
  std::vector<double> fd(dim), fs(dim), qd(2), qs(2);
  direct.evaluate(wd, y.data(), 3.7, fd.data(), qd.data());
  spectral.evaluate(ws, y.data(), 3.7, fs.data(), qs.data());
  const double scale = Inertial ? 1.0 / inertia : 1.0 / damping;
  for (std::size_t k = 0; k < dim; ++k) CHECK(fs[k] == Approx(fd[k]).margin(1e-12 * scale * 50));
  CHECK(qs[0] == Approx(qd[0]).epsilon(1e-12).margin(1e-11));
  CHECK(qs[1] == Approx(qd[1]).epsilon(1e-11));
  CHECK(spectral.energy(ws, y.data(), 3.7) == Approx(direct.energy(wd, y.data(), 3.7)).epsilon(1e-12));
}

}  // namespace

TEST_CASE("spectral pairs: the slider's f, integrands and energy equal the direct sums'",
          "[kernels][slider][fft]") {
  check_same_evaluation<false>({8, 8}, {}, 0.5, 1);
  check_same_evaluation<true>({8, 8}, {}, 0.5, 2);
  check_same_evaluation<false>({13, 6}, {}, 0.45, 3);
  check_same_evaluation<false>({5, 11}, {0.0, 0.3, -0.2}, 0.6, 4);
  check_same_evaluation<true>({9, 7}, {0.4, 0.3, -0.2}, 0.5, 5);  // turned: P and Q stay the grid's
  check_same_evaluation<false>({4, 3}, {}, 0.5, 6);               // a lattice this small sums directly
}

TEST_CASE("spectral pairs: Jacobian, df/dt and integrand gradients match central differences",
          "[kernels][slider][fft]") {
  const SliderGrid grid{8, 7};
  const Substrate s(grid, 0.4);
  SECTION("with inertia") {
    const auto m = make_model<Spectral<true>>(grid, parameters<Spectral<true>>(s, 0.5));
    // the FFT's rounding in θ̈ = τ/I (1e-16 of |τ| over I = 1.4e-4) over the difference step 1e-6
    rotorsweep::testing::check_linearization(m, random_state(2 * grid.rotors(), 7, 2.0), 3.1, 1e-8 / inertia);
  }
  SECTION("overdamped") {
    const auto m = make_model<Spectral<false>>(grid, parameters<Spectral<false>>(s, 0.5));
    rotorsweep::testing::check_linearization(m, random_state(grid.rotors(), 8, 0.0), 3.1);
  }
}

namespace {

/// A run from rows alternately near 0 and π over [0, t1] by rodas5p at rtol = atol = tol: the state, the
/// impulse and the dissipation, and the attempts it took.
template <class Model>
std::vector<double> run(const Model& m, double t1, double tol) {
  using Integrator = AdaptiveIntegrator<Model, RosenbrockStepper<Model>>;
  const auto method = stepper_method<RosenbrockTableau>(*parse_stepper("rodas5p"));
  auto integrator = rotorsweep::testing::integrator<Integrator>(m, method, Tolerances{tol, tol});
  auto s = rotorsweep::testing::lane_state<double>(m.dimension(), Model::max_quadratures);
  const std::size_t rotors = m.rotors(), columns = m.grid().columns;
  for (std::size_t r = 0; r < rotors; ++r)
    s.y[r] = ((r / columns) % 2 ? 3.0 : 0.0) + 0.01 * std::sin(double(7 * r));
  s.t_stop = t1;
  integrator.advance(m, s);
  REQUIRE(s.status[0] == LaneStatus::ok);
  std::vector<double> result(s.y, s.y + m.dimension());
  result.push_back(s.quad[0]);
  result.push_back(s.quad[1]);
  return result;
}

/// Both pair sums over the rest and a substrate period of sliding at rtol 1e-9: the angles, the impulse and
/// the dissipation agree to the tolerance's order.
template <bool Inertial>
void check_same_run(SliderGrid grid, double eta) {
  INFO(grid.columns << " x " << grid.rows << (Inertial ? ", inertial" : ", overdamped"));
  const Substrate s(grid, eta, 3 * grid.columns);
  const auto direct = make_model<Direct<Inertial>>(grid, parameters<Direct<Inertial>>(s, 1.0));
  const auto spectral = make_model<Spectral<Inertial>>(grid, parameters<Spectral<Inertial>>(s, 1.0));
  const double t1 = 1.0 + two_pi;
  const auto a = run(direct, t1, 1e-9), b = run(spectral, t1, 1e-9);
  for (std::size_t k = 0; k < grid.rotors(); ++k) CHECK(b[k] == Approx(a[k]).margin(1e-6));
  CHECK(b[b.size() - 2] == Approx(a[a.size() - 2]).epsilon(1e-6));  // the impulse
  CHECK(b.back() == Approx(a.back()).epsilon(1e-6));                // the dissipation
}

}  // namespace

TEST_CASE("spectral pairs: a Rosenbrock run follows the dense pairs' to the tolerance",
          "[kernels][slider][fft]") {
  check_same_run<false>({8, 8}, 0.56);
  check_same_run<true>({7, 6}, 0.56);
}
