// Observed convergence orders of every stepper (Rodas4, Rodas4P2: 4, Rodas5P: 5, ROS2: 2, Dormand–Prince: 5)
// in the angles and in all quadrature states, from fixed-step runs on a smooth, mildly stiff case.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/dormand_prince.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "support/kernel_scratch.hpp"
#include "support/member_run.hpp"

using namespace rotorsweep::kernels;

namespace {

using Model = NearestNeighbourRows<double>;
constexpr std::size_t nq = all_integrals.count();

// Fixed-step integration over [0.3, 1.3]; returns the angles followed by the quadratures.
template <class Stepper>
std::vector<double> fixed_steps(const Model& m, const typename Stepper::Method& method, int steps) {
  auto stepper = rotorsweep::testing::built<Stepper, double>(m, method);
  const std::size_t n = m.dimension();
  auto y = rotorsweep::testing::initial_angles(n, rotorsweep::testing::Start::afm, 0.4);
  std::vector<double> q(nq, 0.0), y_new(n), q_new(nq), y_err(n), q_err(nq);
  const double h = 1.0 / steps;
  double t = 0.3;
  for (int i = 0; i < steps; ++i) {
    stepper.attempt(m, t, h, y.data(), q.data(), y_new.data(), q_new.data(), y_err.data(), q_err.data());
    y.swap(y_new);
    q.swap(q_new);
    t += h;
  }
  y.insert(y.end(), q.begin(), q.end());
  return y;
}

double max_error(const std::vector<double>& a, const std::vector<double>& b, std::size_t from,
                 std::size_t to) {
  double e = 0;
  for (std::size_t k = from; k < to; ++k) e = std::max(e, std::fabs(a[k] - b[k]));
  return e;
}

template <class Stepper>
void check_order(const typename Stepper::Method& method, int expected, std::vector<int> steps) {
  const auto m = rotorsweep::testing::model<Model>(6, all_integrals, 2.5, 3.0);
  const auto reference = fixed_steps<DormandPrince5<Model>>(m, dormand_prince5_tableau, 4096);
  const std::size_t n = m.dimension();
  const auto coarse = fixed_steps<Stepper>(m, method, steps[0]), fine = fixed_steps<Stepper>(m, method, steps[1]);
  const double refinement = std::log2(double(steps[1]) / steps[0]);
  // the angles, then all quadrature states together (one error can cross zero by accident)
  const double angle_order =
      std::log2(max_error(coarse, reference, 0, n) / max_error(fine, reference, 0, n)) / refinement;
  const double quad_order =
      std::log2(max_error(coarse, reference, n, n + nq) / max_error(fine, reference, n, n + nq)) / refinement;
  INFO(method.name << ": angle order " << angle_order << ", quadrature order " << quad_order);
  CHECK(angle_order == Approx(expected).margin(0.25));
  CHECK(quad_order >= expected - 0.25);  // their own error terms may vanish faster
  CHECK(quad_order <= expected + 2.5);
}

}  // namespace

using Rosenbrock = RosenbrockStepper<Model>;
TEST_CASE("Rodas4 converges with order 4", "[kernels][order]") { check_order<Rosenbrock>(rodas4_tableau, 4, {64, 128}); }
TEST_CASE("Rodas4P2 converges with order 4", "[kernels][order]") {
  check_order<Rosenbrock>(rodas4p2_tableau, 4, {64, 128});
}
TEST_CASE("Rodas5P converges with order 5", "[kernels][order]") {
  check_order<Rosenbrock>(rodas5p_tableau, 5, {32, 64});
}
TEST_CASE("ROS2 converges with order 2", "[kernels][order]") { check_order<Rosenbrock>(ros2_tableau, 2, {128, 256}); }
TEST_CASE("Dormand-Prince converges with order 5", "[kernels][order]") {
  check_order<DormandPrince5<Model>>(dormand_prince5_tableau, 5, {16, 32});
}
