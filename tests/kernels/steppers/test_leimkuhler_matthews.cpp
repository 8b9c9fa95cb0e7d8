// The Langevin stepper (kernels/steppers/leimkuhler_matthews.hpp) on the Ornstein–Uhlenbeck process
// dθ = −k θ dt + √(2T/g) dW, whose mean and second moment are known: the samples follow the
// scheme's closed-form moments (weak order 1 on paths), its stationary spread is exactly the
// Boltzmann one at any stable step, and SIMD lanes give the scalar lane's bits.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "kernels/lanes/counter_random.hpp"
#include "kernels/linear/diagonal_jacobian.hpp"
#include "kernels/steppers/leimkuhler_matthews.hpp"
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
  double curvature_bound(std::size_t lane) const { return lane_get(k, lane); }
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
// the largest step fraction: h ≤ 1.5 / max(k, 11 T) = 1/3.7, so `steps` per unit time rule from 4 on
constexpr double step_fraction = 1.5;

struct Moments {
  double first = 0, second = 0;
};

/// θ(duration) over `samples` members in `steps` steps per unit time, on lane type V; the members'
/// final values.
template <class V>
std::vector<double> final_values(int steps, std::size_t samples, double duration = 1.0) {
  using Model = OrnsteinUhlenbeck<V>;
  auto arena = rotorsweep::testing::scratch<V>(Model::storage_size(1));
  const Model model(1, arena);
  auto integrator = rotorsweep::testing::built<LeimkuhlerMatthews<Model>, V>(
      model, typename LeimkuhlerMatthews<Model>::Settings{temperature, steps, step_fraction});
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
      integrator.start_lane(l, RandomStream(11, first + l).key(), 1.0, 1.0);
    }
    for (double end = 1.0; end <= duration + 1e-9; end += 1.0) {
      s.t_stop = V(end);
      while (lane_any(s.t < s.t_stop)) integrator.attempt(model, s);
    }
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

TEST_CASE(
    "Leimkuhler-Matthews on the Ornstein-Uhlenbeck process: the scheme's moments, weak order 1 on "
    "paths",
    "[kernels][langevin]") {
  // For this linear problem the scheme θ_{n+1} = a θ_n + b (ξ_n + ξ_{n+1}), a = 1 − h, b = √(2T h)/2,
  // has closed-form moments after n steps: E θ_n = θ0 aⁿ, and θ_n − E θ_n = Σ_i c_i ξ_i with
  // c_0 = b a^(n−1), c_i = b (a^(n−1−i) + a^(n−i)) for 0 < i < n, c_n = b. The samples must match them
  // (the code is that scheme, with the right noise strength), and the mean's error against the
  // exact E θ(1) = θ0 e^-1 falls as h.
  const double exact_first = theta0 * std::exp(-1.0);
  const std::size_t samples = 200000;
  std::vector<double> mean_errors;
  for (int steps : {4, 8, 16, 64}) {
    const double h = 1.0 / steps, a = 1.0 - h, b = std::sqrt(2 * temperature * h) / 2;
    double variance = std::pow(b * std::pow(a, steps - 1), 2) + b * b;
    for (int i = 1; i < steps; ++i)
      variance += std::pow(b * (std::pow(a, steps - 1 - i) + std::pow(a, steps - i)), 2);
    const Moments scheme{theta0 * std::pow(a, steps), theta0 * theta0 * std::pow(a, 2 * steps) + variance};
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
    mean_errors.push_back(scheme.first - exact_first);
  }
  const double order = std::log2(mean_errors[1] / mean_errors[2]);
  INFO("weak order of the mean " << order);
  CHECK(order == Approx(1.0).margin(0.1));
}

TEST_CASE(
    "Leimkuhler-Matthews: the stationary spread is the Boltzmann one at any stable step, and SIMD "
    "equals scalar",
    "[kernels][langevin]") {
  const auto simd = final_values<simd_lane>(64, 4096);
  const auto scalar = final_values<double>(64, 4096);
  CHECK(simd == scalar);
  // stationary (t = 20, 20 relaxation times): E θ² = T/k exactly for the scheme, at h = 1/4 as at
  // 1/64 (the drift-implicit Euler gives T/(1 + kh/2), 11 % low at h = 1/4)
  for (int steps : {4, 64}) {
    const auto values = final_values<simd_lane>(steps, 32000, 20.0);
    const auto m = moments(values);
    double fourth = 0;
    for (double v : values) fourth += v * v * v * v / double(values.size());
    const double se_second = std::sqrt((fourth - m.second * m.second) / double(values.size()));
    INFO(steps << " steps per unit time: E θ² = " << m.second << " ± " << se_second
               << ", T = " << temperature);
    CHECK(std::fabs(m.second - temperature) < 4 * se_second);
    CHECK(se_second < 0.01 * temperature);  // the test resolves a 3 % bias
  }
}
