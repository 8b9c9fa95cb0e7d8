// `rotorsweep table`: integrates the paper's reference members (N = 20, g = 0.0011, FM and
// AFM starts, 2 relaxation periods, 2 averaged) and prints W, S, R beside the paper's R.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "commands.hpp"
#include "ensemble/initial_conditions.hpp"
#include "kernels/adaptive_integrator.hpp"
#include "kernels/period_driver.hpp"
#include "kernels/row_model.hpp"
#include "kernels/stepper_choice.hpp"

namespace rotorsweep::apps {

namespace {

constexpr kernels::Integrals estimators{true, true, true, false, false};
using Model = kernels::NearestNeighbourRows<double, estimators>;

struct Reference {
  double A;
  ensemble::InitialKind kind;
  double paper_R;  ///< the paper's table, column A ∫ Σ sin(θ_j - t) dt
};

constexpr Reference references[] = {
    {1, ensemble::InitialKind::fm, 2.018948e-3},  {1, ensemble::InitialKind::afm, 7.184589e-4},
    {4, ensemble::InitialKind::fm, 2.296052e-2},  {4, ensemble::InitialKind::afm, 2.296052e-2},
    {6, ensemble::InitialKind::fm, 3.407353e1},   {6, ensemble::InitialKind::afm, 3.410911e1},
    {8, ensemble::InitialKind::fm, 5.728856},     {8, ensemble::InitialKind::afm, 5.697104},
    {11, ensemble::InitialKind::fm, 1.654868e-1}, {11, ensemble::InitialKind::afm, 1.654868e-1},
};

struct Row {
  double W = 0, S = 0, R = 0, steps_per_period = 0;
};

Row integrate(const Reference& ref, kernels::StepperKind stepper, double rtol) {
  constexpr std::size_t rows = 20;
  constexpr int relax = 2, average = 2;
  const Model model(rows, ref.A, 0.0011);
  return kernels::with_stepper<Model>(stepper, [&]<class Stepper>() {
    kernels::AdaptiveIntegrator<Model, Stepper> integrator(model, {rtol, rtol * 1e-3});
    kernels::LaneState<double> state(rows, Model::quadrature_count);
    const auto theta = ensemble::initial_angles({ref.kind, 0.01, 0.0, {}}, rows, 1, 0);
    for (std::size_t j = 0; j < rows; ++j) state.theta[j] = theta[j];
    Row row;
    kernels::run_periods(model, integrator, state, relax + average, [&](int k, const auto& s) {
      if (k < relax) return;
      row.R += s.quad[estimators.drive_index()] / average;
      row.W += s.quad[estimators.work_index()] / average;
      row.S += s.quad[estimators.stokes_index()] / average;
    });
    row.steps_per_period = state.steps_accepted / (relax + average);
    return row;
  });
}

}  // namespace

int run_table(const TableOptions& options) {
  const auto stepper = kernels::parse_stepper(options.stepper).value();
  std::ofstream csv;
  if (!options.output.empty()) {
    csv.open(options.output);
    if (!csv) {
      std::cerr << "error: cannot write " << options.output << "\n";
      return 2;
    }
    csv << "A,ic,W,S,R,paper_R,relative_deviation,steps_per_period\n";
  }
  std::printf("%5s %4s %14s %14s %14s %14s %10s %8s\n", "A", "IC", "W (work)", "S (Stokes)", "R (drive)",
              "paper R", "R/paper-1", "steps/T");
  const auto start = std::chrono::steady_clock::now();
  for (const auto& ref : references) {
    const Row row = integrate(ref, stepper, options.rtol);
    const double deviation = row.R / ref.paper_R - 1;
    const auto ic = ensemble::kind_name(ref.kind);
    std::printf("%5.0f %4s %14.7e %14.7e %14.7e %14.7e %10.2e %8.0f\n", ref.A, ic.data(), row.W, row.S, row.R,
                ref.paper_R, deviation, row.steps_per_period);
    if (csv) {
      char line[256];
      std::snprintf(line, sizeof line, "%g,%s,%.10e,%.10e,%.10e,%.7e,%.3e,%.1f\n", ref.A, ic.data(), row.W,
                    row.S, row.R, ref.paper_R, deviation, row.steps_per_period);
      csv << line;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("stepper %s, rtol %g: %.2f s", options.stepper.c_str(), options.rtol, seconds);
  if (csv) std::printf(", table written to %s", options.output.c_str());
  std::printf("\n");
  return 0;
}

}  // namespace rotorsweep::apps
