// The row model in registers (kernels/models/rows/warp_rows.hpp, on the host's emulation of a warp)
// against NearestNeighbourRows at the same point: f, J, ∂f/∂t, every integrand and its gradient and
// time derivative, and an evaluation at a stage's displacement, for every lane count and fill.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/lanes/warp.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/models/rows/warp_rows.hpp"
#include "support/kernel_scratch.hpp"

using namespace rotorsweep::kernels;

namespace {

using Lanes = NearestNeighbourRows<double>;

template <std::size_t L, std::size_t R, bool PerRow>
void check_against_lanes(std::size_t n) {
  using W = HostWarp<L>;
  using Model = WarpRows<W, R, PerRow, all_integrals>;
  using V = typename W::value;
  std::vector<double> disorder(n), theta(n), delta(n);
  for (std::size_t j = 0; j < n; ++j) {
    disorder[j] = PerRow ? 0.05 * std::sin(2.3 * double(j) + 0.4) : 0.0;
    theta[j] = 3.0 * std::sin(1.3 * double(j) + 0.2);
    delta[j] = 1e-3 * std::cos(0.7 * double(j));
  }
  Lanes::Parameters p{4.5, 0.0011, false};
  if (PerRow) p.A_rows = p.anisotropy_rows = p.coupling_rows = disorder.data();
  const double t = 0.7, tau = 2e-3;

  const Lanes lanes = rotorsweep::testing::model<Lanes>(n, all_integrals, p);
  auto work = rotorsweep::testing::workspace(lanes);
  auto J = rotorsweep::testing::jacobian<Lanes::Jacobian>(n);
  std::vector<double> f(n), q(8), df_dt(n), dq_dy(8 * n), dq_dt(8), f_displaced(n), q_displaced(8);
  lanes.linearize(work, theta.data(), t, f.data(), q.data(), J, df_dt.data(), dq_dy.data(), dq_dt.data());
  lanes.evaluate_displaced(work, theta.data(), delta.data(), t, tau, f_displaced.data(), q_displaced.data());

  const WarpRowSlots<W, R> slots(n);
  Model model(slots, all_integrals, {p.A, p.g, p.strict_fm, p.A_rows, p.anisotropy_rows, p.coupling_rows});
  V y[R], d[R], wf[R], wdf[R], wf_displaced[R], wgrad[8][R];
  double wq[8], wdq[8], wq_displaced[8];
  typename Model::Jacobian wJ;
  const auto each = [&](auto&& f) {
    for (std::size_t r = 0; r < R; ++r)
      for (std::size_t l = 0; l < L; ++l)
        f(r, l, std::size_t(lane_get(slots.row(r), l)), mask_get(slots.real(r), l));
  };
  each([&](std::size_t r, std::size_t l, std::size_t j, bool real) {
    lane_set(y[r], l, real ? theta[j] : 0.0);
    lane_set(d[r], l, real ? delta[j] : 0.0);
  });
  model.linearize(y, t, wf, wq, wJ, wdf, wgrad, wdq);
  model.evaluate_displaced(y, d, t, tau, wf_displaced, wq_displaced);

  const auto close = [](double a, double b) { return a == Approx(b).epsilon(1e-12).margin(1e-12); };
  each([&](std::size_t r, std::size_t l, std::size_t j, bool real) {
    INFO("L = " << L << ", R = " << R << ", N = " << n << ", slot " << r << ", lane " << l << ", row " << j);
    if (!real) {
      CHECK(lane_get(wf[r], l) == 0.0);
      CHECK(lane_get(wJ.diag[r], l) == 0.0);
      CHECK(lane_get(wJ.off[r], l) == 0.0);
      return;
    }
    CHECK(close(lane_get(wf[r], l), f[j]));
    CHECK(close(lane_get(wf_displaced[r], l), f_displaced[j]));
    CHECK(close(lane_get(wJ.diag[r], l), J.diag(j)));
    CHECK(close(lane_get(wJ.off[r], l), J.off(j)));
    CHECK(close(lane_get(wdf[r], l), df_dt[j]));
    for (std::size_t k = 0; k < 8; ++k) {
      INFO("quadrature " << k);
      CHECK(close(lane_get(wgrad[k][r], l), dq_dy[k * n + j]));
    }
  });
  for (std::size_t k = 0; k < 8; ++k) {
    INFO("L = " << L << ", R = " << R << ", N = " << n << ", quadrature " << k);
    CHECK(wq[k] == Approx(q[k]).epsilon(1e-12).margin(1e-12));
    CHECK(wdq[k] == Approx(dq_dt[k]).epsilon(1e-12).margin(1e-12));
    CHECK(wq_displaced[k] == Approx(q_displaced[k]).epsilon(1e-12).margin(1e-12));
  }
}

template <std::size_t L, std::size_t R, bool PerRow>
void check_fills() {
  for (std::size_t n = L > 2 ? L : 2; n <= L * R; ++n) check_against_lanes<L, R, PerRow>(n);
}

}  // namespace

TEST_CASE("the row model in registers gives NearestNeighbourRows' values for every lane count and fill",
          "[kernels][warp][model]") {
  check_fills<1, 4, false>();
  check_fills<2, 3, true>();
  check_fills<4, 2, true>();
  check_fills<8, 3, false>();
  check_fills<8, 3, true>();
  check_against_lanes<32, 4, true>(100);
}
