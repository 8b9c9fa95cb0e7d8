// With the drive frozen (t fixed) the row model is a gradient flow: the energy H decreases
// monotonically along every accepted step, for each stepper.
#include <catch2/catch.hpp>

#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/dormand_prince.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "support/kernel_scratch.hpp"
#include "support/member_run.hpp"

using namespace rotorsweep::kernels;

namespace {

using Model = NearestNeighbourRows<double>;

/// The row model seen at one fixed drive phase: an autonomous system (∂f/∂t = 0).
struct FrozenDrive {
  using lane_type = double;
  using Jacobian = Model::Jacobian;
  using Workspace = Model::Workspace;
  using Parameters = Model::Parameters;
  static constexpr double period = Model::period;
  static constexpr std::size_t max_quadratures = Model::max_quadratures;
  static constexpr std::size_t storage_size(std::size_t n) { return Model::storage_size(n); }

  Model model;
  double phase;

  std::size_t dimension() const { return model.dimension(); }
  std::size_t quadrature_count() const { return model.quadrature_count(); }
  bool error_controlled(std::size_t p) const { return model.error_controlled(p); }
  static constexpr StateScale scale(std::size_t k) { return Model::scale(k); }
  StateScale quadrature_scale(std::size_t p) const { return model.quadrature_scale(p); }
  void set_lane(std::size_t lane, const Parameters& p) { model.set_lane(lane, p); }
  void evaluate(Workspace& w, const double* y, double, double* f, double* q) const {
    model.evaluate(w, y, phase, f, q);
  }
  void linearize(Workspace& w, const double* y, double, double* f, double* q, Jacobian& J, double* df_dt,
                 double* dq_dy, double* dq_dt) const {
    model.linearize(w, y, phase, f, q, J, df_dt, dq_dy, dq_dt);
    for (std::size_t k = 0; k < dimension(); ++k) df_dt[k] = 0.0;
    for (std::size_t p = 0; p < quadrature_count(); ++p) dq_dt[p] = 0.0;
  }
};

template <class Stepper>
void check_energy_descent(const typename Stepper::Method& method, double A, double g) {
  const std::size_t rows = 12;
  const FrozenDrive system{rotorsweep::testing::model<Model>(rows, dissipation_only, A, g), 0.9};
  auto integrator =
      rotorsweep::testing::integrator<AdaptiveIntegrator<FrozenDrive, Stepper>>(system, method, {1e-8, 1e-11});
  auto s = rotorsweep::testing::lane_state<double>(rows, FrozenDrive::max_quadratures);
  const auto theta = rotorsweep::testing::initial_angles(rows, rotorsweep::testing::Start::afm, 1.0, 17);
  for (std::size_t j = 0; j < rows; ++j) s.y[j] = theta[j];
  s.t_stop = 5.0;
  auto w = rotorsweep::testing::workspace(system.model);
  double previous = system.model.energy(w, s.y, system.phase);
  const double start = previous;
  int steps = 0;
  while (s.t < s.t_stop) {
    if (!integrator.attempt(system, s)) continue;
    const double now = system.model.energy(w, s.y, system.phase);
    CHECK(now <= previous + 1e-12 * std::fabs(previous));
    previous = now;
    ++steps;
  }
  CHECK(steps > 10);
  CHECK(previous < start - 1e-3);
}

}  // namespace

TEST_CASE("energy decreases along the frozen-drive flow", "[kernels][physics]") {
  for (double A : {0.5, 6.0, 20.0}) {
    check_energy_descent<RosenbrockStepper<FrozenDrive>>(rodas4_tableau, A, 0.001);
    check_energy_descent<RosenbrockStepper<FrozenDrive>>(ros2_tableau, A, 0.001);
    check_energy_descent<DormandPrince5<FrozenDrive>>(dormand_prince5_tableau, A, 1.0);
  }
}
