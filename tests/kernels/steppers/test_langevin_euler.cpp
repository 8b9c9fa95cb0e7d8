// The Langevin stepper (kernels/steppers/langevin_euler.hpp) on the Ornstein–Uhlenbeck process
// dθ = −k θ dt + √(2T/g) dW, whose mean and second moment are known: the observed weak order is 1,
// SIMD lanes give the scalar lane's bits, and the noise has the right strength.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/lanes/counter_random.hpp"
#include "kernels/linear/diagonal_jacobian.hpp"
#include "kernels/steppers/langevin_euler.hpp"
#include "support/kernel_scratch.hpp"

using namespace rotorsweep::kernels;

namespace {

/// g dθ/dt = −k g θ, i.e. f = −k θ; unit period, no quadratures. Satisfies LaneModel.
template <class V>
struct OrnsteinUhlenbeck {
  using lane_type = V;
  using Jacobian = DiagonalJacobian<V>;
  static constexpr double period = 1.0;
  static constexpr std::size_t max_quadratures = 0;
  static constexpr std::size_t quadrature_count() { return 0; }
  static constexpr bool error_controlled(std::size_t) { return false; }
  struct Parameters {
    double k = 1.0;
  };
  struct Workspace {
    static constexpr std::size_t storage_size(std::size_t) { return 0; }
    Workspace(std::size_t, LaneArena<V>&) {}
  };
  static constexpr std::size_t storage_size(std::size_t) { return 0; }
  OrnsteinUhlenbeck(std::size_t, LaneArena<V>&) {}

  void set_lane(std::size_t lane, const Parameters& p) { lane_set(k, lane, p.k); }
  std::size_t dimension() const { return 1; }
  static constexpr StateScale scale(std::size_t) { return StateScale::absolute; }
  static constexpr StateScale quadrature_scale(std::size_t) { return StateScale::relative; }
  void evaluate(Workspace&, const V* theta, V, V* f, V*) const { f[0] = lane_neg(k) * theta[0]; }
  void linearize(Workspace& w, const V* theta, V t, V* f, V* q, Jacobian& J, V* df_dt, V*, V*) const {
    evaluate(w, theta, t, f, q);
    J.diag(0) = lane_neg(k);
    df_dt[0] = V(0.0);
  }
  V k = V(1.0);
};

constexpr double temperature = 0.5, theta0 = 1.0;  // g = 1, k = 1: σ² = 2T = 1

struct Moments {
  double first = 0, second = 0;
};

/// θ(1) over `samples` members in `steps` steps each, on lane type V; the members' final values.
template <class V>
std::vector<double> final_values(int steps, std::size_t samples) {
  using Model = OrnsteinUhlenbeck<V>;
  auto arena = rotorsweep::testing::scratch<V>(Model::storage_size(1));
  const Model model(1, arena);
  auto integrator = rotorsweep::testing::built<LangevinEuler<Model>, V>(
      model, typename LangevinEuler<Model>::Settings{temperature, steps});
  auto s = rotorsweep::testing::lane_state<V>(1, 0);
  std::vector<double> out;
  constexpr std::size_t W = lane_width<V>;
  for (std::size_t first = 0; first < samples; first += W) {
    for (std::size_t l = 0; l < W; ++l) {
      lane_set(s.y[0], l, theta0);
      lane_set(s.t, l, 0.0);
      lane_set(s.t_stop, l, 1.0);
      lane_set(s.steps_accepted, l, 0.0);
      s.status[l] = LaneStatus::ok;
      integrator.start_lane(l, RandomStream(11, first + l).key(), 1.0);
    }
    while (lane_any(s.t < s.t_stop)) integrator.attempt(model, s);
    for (std::size_t l = 0; l < W; ++l) out.push_back(lane_get(s.y[0], l));
  }
  return out;
}

Moments moments(const std::vector<double>& x) {
  Moments m;
  for (double v : x) {
    m.first += v / double(x.size());
    m.second += v * v / double(x.size());
  }
  return m;
}

}  // namespace

TEST_CASE("Langevin Euler has weak order 1 on the Ornstein-Uhlenbeck process", "[kernels][langevin]") {
  // For this linear problem the scheme's moments after n steps of h are known in closed form:
  //   E θ_n = θ0 (1 + h)^-n,  E θ_n² = θ0² (1 + h)^-2n + 2T h Σ_{i=1..n} (1 + h)^-2i.
  // The samples must match them (the code is that scheme, with the right noise strength), and
  // their errors against the exact E θ(1) = θ0 e^-1, E θ(1)² = θ0² e^-2 + T (1 - e^-2) fall as h.
  const double exact_first = theta0 * std::exp(-1.0);
  const double exact_second = std::exp(-2.0) * theta0 * theta0 + temperature * (1 - std::exp(-2.0));
  const std::size_t samples = 200000;
  std::vector<Moments> errors;
  for (int steps : {4, 8, 16, 64}) {
    const double h = 1.0 / steps, decay = 1.0 / (1.0 + h);
    double noise = 0;
    for (int i = 1; i <= steps; ++i) noise += 2 * temperature * h * std::pow(decay, 2 * i);
    const Moments scheme{theta0 * std::pow(decay, steps),
                         theta0 * theta0 * std::pow(decay, 2 * steps) + noise};
    const auto values = final_values<simd_lane>(steps, samples);
    const auto m = moments(values);
    double fourth = 0;
    for (double v : values) fourth += v * v * v * v / double(samples);
    const double se_first = std::sqrt((m.second - m.first * m.first) / double(samples));
    const double se_second = std::sqrt((fourth - m.second * m.second) / double(samples));
    INFO(steps << " steps: E θ " << m.first << " (scheme " << scheme.first << " ± " << se_first << "), E θ² "
               << m.second << " (scheme " << scheme.second << " ± " << se_second << ")");
    CHECK(std::fabs(m.first - scheme.first) < 4 * se_first);
    CHECK(std::fabs(m.second - scheme.second) < 4 * se_second);
    errors.push_back({scheme.first - exact_first, scheme.second - exact_second});
  }
  // weak order of the scheme: the error ratio per halving of h tends to 2
  const double order_first = std::log2(errors[1].first / errors[2].first);
  const double order_second = std::log2(errors[2].second / errors[3].second) / 2;  // h from 1/16 to 1/64
  INFO("weak orders " << order_first << " (mean), " << order_second << " (second moment)");
  CHECK(order_first == Approx(1.0).margin(0.1));
  CHECK(order_second == Approx(1.0).margin(0.1));
  // and the samples show it too, for the mean (the second moment's sampling error is too large)
  const double sampled_order = std::log2((moments(final_values<simd_lane>(4, samples)).first - exact_first) /
                                         (moments(final_values<simd_lane>(8, samples)).first - exact_first));
  CHECK(sampled_order == Approx(1.0).margin(0.2));
}

TEST_CASE("Langevin Euler: the stationary spread is the Boltzmann one and SIMD equals scalar",
          "[kernels][langevin]") {
  // 64 steps per unit time: the stationary variance of the scheme is T/(1 + kh/2) (docs/numerics.md)
  const auto simd = final_values<simd_lane>(64, 4096);
  const auto scalar = final_values<double>(64, 4096);
  CHECK(simd == scalar);
  const auto m = moments(final_values<simd_lane>(1024, 16000));  // t = 1, not yet stationary
  const double exact_second = std::exp(-2.0) + temperature * (1 - std::exp(-2.0));
  CHECK(m.second == Approx(exact_second).epsilon(0.02));
}
