// Scalar and SIMD instantiations of the same kernel source agree: right-hand side, Jacobian,
// one step of every stepper, and whole adaptive runs with different parameters in each lane.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/lanes/angles.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/dormand_prince.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "support/kernel_scratch.hpp"
#include "support/member_run.hpp"

using namespace rotorsweep::kernels;
using rotorsweep::testing::initial_angles;
using rotorsweep::testing::Start;

namespace {

constexpr Integrals every = all_integrals;
using Scalar = NearestNeighbourRows<double>;
using Simd = NearestNeighbourRows<simd_lane>;
constexpr std::size_t W = lane_width<simd_lane>;
constexpr std::size_t nq = every.count();
constexpr std::size_t rows = 20;

double lane_A(std::size_t l) { return 0.5 + 1.7 * double(l); }
double lane_g(std::size_t l) { return 0.01 * double(l + 1); }
double lane_t(std::size_t l) { return 0.2 + 0.9 * double(l); }

std::vector<double> lane_theta(std::size_t l) {
  return initial_angles(rows, l % 2 ? Start::afm : Start::fm, 0.5, unsigned(l + 1));
}

lane_vector<simd_lane> gather_theta() {
  lane_vector<simd_lane> theta(rows);
  for (std::size_t j = 0; j < rows; ++j)
    theta[j] = lane_from<simd_lane>([&](std::size_t l) { return lane_theta(l)[j]; });
  return theta;
}

Simd simd_model() {
  return rotorsweep::testing::model<Simd>(rows, every, lane_from<simd_lane>(lane_A),
                                          lane_from<simd_lane>(lane_g));
}

void check_close(double simd, double scalar, double tol) {
  INFO("simd " << simd << " scalar " << scalar << " difference " << simd - scalar);
  CHECK(std::fabs(simd - scalar) <= tol * std::max(1.0, std::fabs(scalar)));
}

template <template <class> class Stepper, class Method>
void check_one_step(const Method& method) {
  const Simd vm = simd_model();
  auto vs = rotorsweep::testing::built<Stepper<Simd>, simd_lane>(vm, method);
  auto theta = gather_theta();
  lane_vector<simd_lane> q(nq, simd_lane(0.1)), y_new(rows), q_new(nq), y_err(rows), q_err(nq);
  const simd_lane t = lane_from<simd_lane>(lane_t), h(0.05);
  vs.attempt(vm, t, h, theta.data(), q.data(), y_new.data(), q_new.data(), y_err.data(), q_err.data());
  for (std::size_t l = 0; l < W; ++l) {
    const auto sm = rotorsweep::testing::model<Scalar>(rows, every, lane_A(l), lane_g(l));
    auto ss = rotorsweep::testing::built<Stepper<Scalar>, double>(sm, method);
    auto y = lane_theta(l);
    std::vector<double> sq(nq, 0.1), sy_new(rows), sq_new(nq), sy_err(rows), sq_err(nq);
    ss.attempt(sm, lane_t(l), 0.05, y.data(), sq.data(), sy_new.data(), sq_new.data(), sy_err.data(),
               sq_err.data());
    for (std::size_t j = 0; j < rows; ++j) {
      check_close(lane_get(y_new[j], l), sy_new[j], 1e-13);
      check_close(lane_get(y_err[j], l), sy_err[j], 1e-13);
    }
    for (std::size_t p = 0; p < nq; ++p) check_close(lane_get(q_new[p], l), sq_new[p], 1e-13);
  }
}

}  // namespace

TEST_CASE("SIMD right-hand side and Jacobian equal the scalar ones lane by lane", "[kernels][simd]") {
  const Simd vm = simd_model();
  auto vw = rotorsweep::testing::workspace(vm);
  auto theta = gather_theta();
  lane_vector<simd_lane> f(rows), q(nq), df_dt(rows), dq_dy(nq * rows), dq_dt(nq);
  auto J = rotorsweep::testing::jacobian<Simd::Jacobian>(rows);
  const simd_lane t = lane_from<simd_lane>(lane_t);
  vm.linearize(vw, theta.data(), t, f.data(), q.data(), J, df_dt.data(), dq_dy.data(), dq_dt.data());
  const simd_lane energy = vm.energy(vw, theta.data(), t);

  for (std::size_t l = 0; l < W; ++l) {
    const auto sm = rotorsweep::testing::model<Scalar>(rows, every, lane_A(l), lane_g(l));
    auto sw = rotorsweep::testing::workspace(sm);
    const auto y = lane_theta(l);
    std::vector<double> sf(rows), sq(nq), sdf(rows), sdq(nq * rows), sdqt(nq);
    auto sJ = rotorsweep::testing::jacobian<Scalar::Jacobian>(rows);
    sm.linearize(sw, y.data(), lane_t(l), sf.data(), sq.data(), sJ, sdf.data(), sdq.data(), sdqt.data());
    for (std::size_t j = 0; j < rows; ++j) {
      check_close(lane_get(f[j], l), sf[j], 1e-13);
      check_close(lane_get(J.diag(j), l), sJ.diag(j), 1e-13);
      check_close(lane_get(J.off(j), l), sJ.off(j), 1e-13);
      check_close(lane_get(df_dt[j], l), sdf[j], 1e-13);
    }
    for (std::size_t k = 0; k < nq * rows; ++k) check_close(lane_get(dq_dy[k], l), sdq[k], 1e-13);
    for (std::size_t p = 0; p < nq; ++p) check_close(lane_get(q[p], l), sq[p], 1e-13);
    check_close(lane_get(energy, l), sm.energy(sw, y.data(), lane_t(l)), 1e-13);
  }
}

TEST_CASE("one SIMD step equals one scalar step for every stepper", "[kernels][simd]") {
  check_one_step<RosenbrockStepper>(rodas4_tableau);
  check_one_step<RosenbrockStepper>(rodas4p2_tableau);
  check_one_step<RosenbrockStepper>(ros2_tableau);
  check_one_step<DormandPrince5>(dormand_prince5_tableau);
}

TEST_CASE("adaptive SIMD runs reproduce scalar runs member by member", "[kernels][simd]") {
  const Simd vm = simd_model();
  auto vi = rotorsweep::testing::integrator<AdaptiveIntegrator<Simd, RosenbrockStepper<Simd>>>(vm, rodas4_tableau,
                                                                                               {1e-7, 1e-10});
  auto vs = rotorsweep::testing::lane_state<simd_lane>(rows, nq);
  const auto theta = gather_theta();
  std::copy(theta.begin(), theta.end(), vs.y);
  vs.t_stop = simd_lane(2 * two_pi);
  vi.advance(vm, vs);
  for (std::size_t l = 0; l < W; ++l) {
    const auto sm = rotorsweep::testing::model<Scalar>(rows, every, lane_A(l), lane_g(l));
    auto si = rotorsweep::testing::integrator<AdaptiveIntegrator<Scalar, RosenbrockStepper<Scalar>>>(
        sm, rodas4_tableau, {1e-7, 1e-10});
    auto ss = rotorsweep::testing::lane_state<double>(rows, nq);
    const auto y = lane_theta(l);
    for (std::size_t j = 0; j < rows; ++j) ss.y[j] = y[j];
    ss.t_stop = 2 * two_pi;
    si.advance(sm, ss);
    INFO("lane " << l);
    CHECK(lane_get(vs.steps_accepted, l) == ss.steps_accepted);
    CHECK(lane_get(vs.steps_rejected, l) == ss.steps_rejected);
    for (std::size_t j = 0; j < rows; ++j) CHECK(lane_get(vs.y[j], l) == ss.y[j]);
    for (std::size_t p = 0; p < nq; ++p) CHECK(lane_get(vs.quad[p], l) == ss.quad[p]);
  }
}
