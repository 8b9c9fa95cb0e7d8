// `rotorsweep bench kernels`: single-thread throughput of the kernels, scalar and SIMD: RHS
// evaluations (at a new point and at a stage's displacement), the bare vectorised sincos that
// bounds them, step attempts per stepper with their share of that bound (the sincos bound over the
// RHS evaluations an attempt takes), and the cost of per-row disorder (docs/model.md §7).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "commands.hpp"
#include "ensemble/engine/instruction_set.hpp"
#include "ensemble/rows/initial_conditions.hpp"
#include "kernels/lanes/lane_math.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::apps {

namespace {

using kernels::lane_vector;
using kernels::simd_lane;

volatile double sink;

/// Median over `repeats` of the rate (work units per second) of `body`, which does `units`
/// units per call; each repeat runs about 0.2 s.
template <class Body>
double median_rate(int repeats, double units, Body&& body) {
  using clock = std::chrono::steady_clock;
  long calls = 1;
  for (;;) {  // calibrate
    const auto t0 = clock::now();
    for (long i = 0; i < calls; ++i) body();
    if (std::chrono::duration<double>(clock::now() - t0).count() > 0.05) break;
    calls *= 2;
  }
  calls *= 4;
  std::vector<double> rates;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = clock::now();
    for (long i = 0; i < calls; ++i) body();
    rates.push_back(units * double(calls) / std::chrono::duration<double>(clock::now() - t0).count());
  }
  std::nth_element(rates.begin(), rates.begin() + rates.size() / 2, rates.end());
  return rates[rates.size() / 2];
}

template <class V>
lane_vector<V> afm_angles(std::size_t rows) {
  const auto theta = ensemble::initial_angles({ensemble::InitialKind::afm, 0.01, 0.0, {}}, rows, 1, 0);
  lane_vector<V> out(rows);
  for (std::size_t j = 0; j < rows; ++j) out[j] = V(theta[j]);
  return out;
}

/// Per-row deviations of relative size 1e-6 in all three quantities (or none).
/// The model every measurement steps: the row model carrying only the drive's integral.
template <class V>
using BenchModel = kernels::NearestNeighbourRows<V>;
inline constexpr kernels::Integrals bench_integrals = kernels::dissipation_only;

struct BenchDisorder {
  std::vector<double> deviations;
  BenchDisorder(std::size_t rows, bool on) {
    for (std::size_t j = 0; on && j < rows; ++j) deviations.push_back(1e-6 * std::sin(double(j)));
  }
  template <class Parameters>
  Parameters parameters() const {
    const double* d = deviations.empty() ? nullptr : deviations.data();
    return {4.0, 0.0011, false, d, d, d};
  }
};

/// RHS evaluations per second at a new point, or (displaced) at a Rosenbrock stage's distance
/// 1e-3 from the last linearisation point, where each sincos comes by angle addition.
template <class V>
double rhs_rate(std::size_t rows, int repeats, bool disordered = false, bool displaced = false) {
  using Model = BenchModel<V>;
  lane_vector<V> storage(Model::storage_size(rows) + Model::Workspace::storage_size(rows) +
                         Model::Jacobian::storage_size(rows));
  kernels::LaneArena<V> arena(storage.data(), storage.size());
  const Model model(rows, arena, bench_integrals,
                    BenchDisorder(rows, disordered).parameters<typename Model::Parameters>());
  typename Model::Workspace work(rows, arena);
  typename Model::Jacobian jacobian(rows, arena);
  auto theta = afm_angles<V>(rows);
  lane_vector<V> f(rows), q(2), df_dt(rows), dq_dtheta(2 * rows), dq_dt(2), delta(rows, V(1e-3));
  model.linearize(work, theta.data(), V(0.3), f.data(), q.data(), jacobian, df_dt.data(), dq_dtheta.data(),
                  dq_dt.data());
  return median_rate(repeats, double(kernels::lane_width<V>), [&] {
    if (displaced)
      model.evaluate_displaced(work, theta.data(), delta.data(), V(0.3), V(1e-3), f.data(), q.data());
    else
      model.evaluate(work, theta.data(), V(0.3), f.data(), q.data());
    sink = kernels::lane_get(f[0], 0);
  });
}

double sincos_rate(std::size_t rows, int repeats) {
  auto theta = afm_angles<simd_lane>(rows + 1);
  lane_vector<simd_lane> s(rows + 1), c(rows + 1);
  return median_rate(repeats, double((rows + 1) * kernels::lane_width<simd_lane>), [&] {
    for (std::size_t j = 0; j <= rows; ++j) kernels::lane_sincos(theta[j], s[j], c[j]);
    sink = kernels::lane_get(s[0], 0) + kernels::lane_get(c[rows], 0);
  });
}

template <class V>
double step_rate(kernels::StepperId id, std::size_t rows, int repeats, bool disordered = false) {
  using Model = BenchModel<V>;
  lane_vector<V> model_storage(Model::storage_size(rows));
  kernels::LaneArena<V> model_arena(model_storage.data(), model_storage.size());
  const Model model(rows, model_arena, bench_integrals,
                    BenchDisorder(rows, disordered).parameters<typename Model::Parameters>());
  return kernels::with_stepper<Model>(id, [&]<class Stepper>(const typename Stepper::Method& method) {
    using Integrator = kernels::AdaptiveIntegrator<Model, Stepper>;
    lane_vector<V> storage(kernels::counted_storage<V>([&](kernels::LaneArena<V>& counter) {
      const Integrator integrator(model, method, {1e-6, 1e-9}, {}, counter);
      const kernels::LaneState<V> state(rows, Model::max_quadratures, counter);
    }));
    kernels::LaneArena<V> arena(storage.data(), storage.size());
    Integrator integrator(model, method, {1e-6, 1e-9}, {}, arena);
    kernels::LaneState<V> state(rows, Model::max_quadratures, arena);
    const auto theta = afm_angles<V>(rows);
    std::copy(theta.begin(), theta.end(), state.y);
    state.t_stop = V(1e300);
    return median_rate(repeats, double(kernels::lane_width<V>), [&] { integrator.attempt(model, state); });
  });
}

}  // namespace

int run_bench_kernels(const BenchKernelOptions& options) {
  const auto rows = std::size_t(options.rows);
  const auto W = kernels::lane_width<simd_lane>;
  const auto isa = ensemble::instruction_set();
  std::printf(
      "rotorsweep bench kernels: N = %zu rows, SIMD width %zu doubles (%s, %s), 1 thread, median of %d\n",
      rows, W, isa.name.c_str(), isa.simd.c_str(), options.repeats);
  const double sincos = sincos_rate(rows, options.repeats);
  const double bound = sincos / double(rows + 1);  // an RHS needs N + 1 sincos
  const double scalar = rhs_rate<double>(rows, options.repeats);
  const double simd = rhs_rate<simd_lane>(rows, options.repeats);
  std::printf("  bare SIMD sincos            %12.4g values/s  -> RHS bound %.4g evaluations/s\n", sincos,
              bound);
  std::printf("  RHS scalar                  %12.4g evaluations/s (%.2f of bound)\n", scalar, scalar / bound);
  std::printf("  RHS SIMD                    %12.4g evaluations/s (%.2f of bound, %.1fx scalar)\n", simd,
              simd / bound, simd / scalar);
  const double stage = rhs_rate<simd_lane>(rows, options.repeats, false, true);
  std::printf("  stage RHS SIMD (displaced)  %12.4g evaluations/s (%.2f of bound, %.2fx RHS)\n", stage,
              stage / bound, stage / simd);
  for (std::size_t k = 0; k < kernels::stepper_names.size(); ++k) {
    const double s = step_rate<double>(k, rows, options.repeats);
    const double v = step_rate<simd_lane>(k, rows, options.repeats);
    const int evaluations = kernels::with_stepper<BenchModel<simd_lane>>(
        k, []<class Stepper>(const typename Stepper::Method& method) { return method.stages; });
    std::printf(
        "  steps %-8s scalar %10.4g /s   SIMD %10.4g member-steps/s (%.1fx; %.2f of the bound for %d RHS)\n",
        kernels::stepper_names[k].data(), s, v, v / s, v * evaluations / bound, evaluations);
  }
  const double disordered_rhs = rhs_rate<simd_lane>(rows, options.repeats, true);
  const double uniform_steps = step_rate<simd_lane>(0, rows, options.repeats);
  const double disordered_steps = step_rate<simd_lane>(0, rows, options.repeats, true);
  std::printf(
      "  with per-row disorder (SIMD): RHS %.4g evaluations/s (%.2f of uniform), %s %.4g member-steps/s "
      "(%.2f of uniform)\n",
      disordered_rhs, disordered_rhs / simd, kernels::stepper_names[0].data(), disordered_steps,
      disordered_steps / uniform_steps);
  return 0;
}

}  // namespace rotorsweep::apps
