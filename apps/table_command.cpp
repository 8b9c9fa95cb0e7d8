// `rotorsweep table`: integrates the paper's reference members (N = 20, g = 0.0011, FM and AFM
// starts, periods 3 and 4 in the paper's triangular window, docs/model.md §3) and prints W, S, R
// beside the paper's W, S, R, with R's error and what it is (docs/numerics.md "The global error of D").
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "build_info.hpp"
#include "commands.hpp"
#include "csv_output.hpp"
#include "ensemble/engine/replica_statistics.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/paper_table.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/shadow_run.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/output_target.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "remove_on_signal.hpp"

namespace rotorsweep::apps {

namespace {

namespace paper = ensemble::paper_table;

/// The CSV file's first line; an existing file that starts as it does is replaced without --force.
constexpr std::string_view csv_title =
    "# rotorsweep table: the paper's dissipation integrals (N = 20, g = 0.0011; docs/model.md §3)";
/// The columns' names, after the provenance lines (each starting with "# ").
constexpr std::string_view csv_header =
    "A,ic,W,S,R,paper_R,relative_deviation,steps_per_period,paper_W,paper_S,R_error,R_error_kind,W_error,S_error";

/// Whether an entry's R error bounds its R (resolved, or too large to call it resolved), so that
/// |R − paper R| over it means something; a symmetry-limited or shadow-departed error does not.
bool error_is_bound(const std::string& flag) { return flag == "resolved" || flag == "unresolved"; }

/// The lines that say how the table was made, each starting with "# ": program, stepper, tolerances,
/// window, disorder, and what R_error means.
std::string provenance_lines(const TableOptions& options) {
  char text[512];
  std::string lines = std::string(csv_title) + "\n# written by rotorsweep " + program_identity() + "\n";
  std::snprintf(text, sizeof text,
                "# stepper %s, rtol %g (W and S outside CP at rtol %g), %s window over periods 3 and 4\n",
                options.stepper.c_str(), options.rtol, options.estimator_rtol, options.window.c_str());
  lines += text;
  if (options.disorder > 0)
    std::snprintf(text, sizeof text, "# disorder: sigma_A = %g, seed %llu (realization 0)\n", options.disorder,
                  static_cast<unsigned long long>(options.disorder_seed));
  else
    std::snprintf(text, sizeof text, "# disorder: none\n");
  lines += text;
  return lines +
         "# R_error: the estimate for the mean of periods 3 and 4; it bounds R where R_error_kind is resolved "
         "or unresolved, not where it is symmetry-limited or shadow-departed\n"
         "# W_error, S_error: in CP the shadow run's difference as R's (2 |X - X_shadow| / 0.9), outside CP the "
         "tolerance pair's (2 |X(rtol) - X(tight)| s / (1 - s), s = tight / rtol); of the kind R_error_kind "
         "says\n";
}

/// The paper's scene as a sweep of the scalar lane with the W, S, R estimators, their moments and
/// every period's record (for the triangular window); with a quenched disorder σ_A where given.
ensemble::Scene paper_scene(kernels::StepperId stepper, double rtol, const ensemble::Disorder& disorder) {
  ensemble::Scene scene;
  scene.row_counts = {paper::rows};
  scene.rtol_values = {rtol};
  scene.atol_values = {rtol * 1e-3};
  scene.g_values = {paper::g};
  scene.relax_periods = paper::relax_periods;
  scene.average_periods = paper::average_periods;
  scene.observables = {};
  scene.observables.set(ensemble::Observable::dissipation, true);
  scene.observables.set(ensemble::Observable::estimators, true);
  scene.observables.set(ensemble::Observable::moments, true);
  scene.period_series = true;
  scene.stepper = stepper;
  scene.lanes = ensemble::LaneKind::scalar;
  scene.disorder = disorder;
  return scene;
}

/// The paper's scene with slips counted, so that members whose averaged periods slip get their shadow
/// runs: R's global error and its flags (ensemble/rows/shadow_run.hpp). Counting slips changes no bit.
ensemble::Scene paper_scene_with_errors(kernels::StepperId stepper, double rtol,
                                        const ensemble::Disorder& disorder) {
  auto scene = paper_scene(stepper, rtol, disorder);
  scene.observables.set(ensemble::Observable::slips, true);
  return scene;
}

/// Half a unit of the last of the 7 significant digits the paper prints of `value`: its rounding.
double paper_rounding(double value) {
  return 0.5 * std::pow(10.0, std::floor(std::log10(std::fabs(value))) - 6);
}

/// What R's error is: a bound (resolved, or too large: unresolved), or none (symmetry-limited: the
/// integration error decides R; shadow departed: no estimate), or the member failed.
std::string error_flag(const ensemble::MemberResult& result) {
  if (result.status != kernels::LaneStatus::ok) return std::string(kernels::status_name(result.status));
  if (result.symmetry_limited) return "symmetry-limited";
  if (result.shadow_departed) return "shadow-departed";
  return result.dissipation_resolved() ? "resolved" : "unresolved";
}

/// Estimator `channel` (whose moment channel is `moment`) over the periods `first` and `first + 1` of
/// `periods`, the averaged periods 3 and 4, t in [4π, 8π]: with the triangular window the mean of its
/// integral over the periods [τ, τ + 2π], τ in [4π, 6π], which weighs t by (t − 4π)/2π on period 3 and
/// (8π − t)/2π on period 4: M_3/2π + Q_4 − M_4/2π with M_k = ∫ (t − t_k) q̇ dt; uniform: (Q_3 + Q_4)/2.
double windowed_periods(const std::vector<ensemble::PeriodRecord>& periods, std::size_t first,
                        ensemble::Channel channel, ensemble::Channel moment, bool triangular) {
  if (periods.size() < first + 2) return NAN;
  const auto& third = periods[first];
  const auto& fourth = periods[first + 1];
  if (!triangular) return (third[channel] + fourth[channel]) / 2;
  const double two_pi = 2 * M_PI;
  return third[moment] / two_pi + fourth[channel] - fourth[moment] / two_pi;
}
/// A member's value of the estimator over its periods 3 and 4 (NaN where it failed).
double windowed(const ensemble::MemberResult& result, ensemble::Channel channel, ensemble::Channel moment,
                bool triangular) {
  if (result.status != kernels::LaneStatus::ok) return NAN;
  return windowed_periods(result.periods, 2, channel, moment, triangular);
}

/// The error of an entry's W or S (`channel`, `moment`): in CP, where they come from R's own run, its
/// shadow's difference as R's global term, shadow_safety |X − X'| / (1 − s) over the shadow's periods (the
/// same two; infinite without a shadow that reached the member's attractor); outside CP, where they come
/// from the run `tight` at estimator_rtol, the tolerance pair's Richardson estimate of that run's error,
/// shadow_safety |X(rtol) − X(tight)| s / (1 − s), s = estimator_rtol / rtol (infinite for s ≥ 1).
double estimator_error(const paper::Entry& ref, const ensemble::MemberResult& result,
                       const ensemble::MemberResult& tight, double s, ensemble::Channel channel,
                       ensemble::Channel moment, bool triangular) {
  const double own = windowed(result, channel, moment, triangular);
  if (ref.cp) {
    if (result.shadow_departed || result.shadow_periods.empty()) return INFINITY;
    const double shadow = windowed_periods(result.shadow_periods, 0, channel, moment, triangular);
    return ensemble::shadow_error(own, shadow);
  }
  if (s >= 1) return INFINITY;  // one tolerance: no pair
  return ensemble::shadow_safety * std::fabs(own - windowed(tight, channel, moment, triangular)) * s / (1 - s);
}
double windowed_R(const ensemble::MemberResult& r, bool triangular) {
  return windowed(r, ensemble::Channel::dissipation, ensemble::Channel::dissipation_moment, triangular);
}

/// Member `index` of the sweep: `entry` with noise draw `stream`.
ensemble::Member paper_member(std::size_t index, const paper::Entry& entry, double rtol, std::size_t stream) {
  ensemble::Member m;
  m.index = index;
  m.stream = stream;
  m.replica = int(stream);
  m.A = entry.A;
  m.g = paper::g;
  m.kind = entry.kind;
  m.rows = paper::rows;
  m.rtol = rtol;
  m.atol = rtol * 1e-3;
  return m;
}

/// The paper's members in `scene`; every member draws stream 0 of seed 1 (and realization 0 of the
/// disorder), whatever its place in the table.
ensemble::SweepOutcome integrate(const ensemble::Scene& scene) {
  const double rtol = scene.rtol_values.front();
  std::vector<ensemble::Member> members;
  for (const auto& entry : paper::entries) members.push_back(paper_member(members.size(), entry, rtol, 0));
  return ensemble::run_sweep(scene, members, {.threads = 1});
}

/// The CP entries over `replicas` noise draws of `seed` (draw r with the disorder's realization r), with
/// slips counted, so that each gets its global error and its flags (ensemble/rows/shadow_run.hpp);
/// then a line per entry.
void print_cp_draws(kernels::StepperId stepper, double rtol, const ensemble::Disorder& disorder, int replicas,
                    std::uint64_t seed, bool triangular) {
  auto scene = paper_scene_with_errors(stepper, rtol, disorder);
  scene.seed = seed;
  std::vector<ensemble::Member> members;
  std::vector<const paper::Entry*> entries;
  for (const auto& entry : paper::entries) {
    if (!entry.cp) continue;
    entries.push_back(&entry);
    for (int r = 0; r < replicas; ++r)
      members.push_back(paper_member(members.size(), entry, rtol, std::size_t(r)));
  }
  const auto outcome = ensemble::run_sweep(scene, members, {.threads = ensemble::thread_count(0)});
  std::printf(
      "\nCP entries over %d noise draws (seed %llu; the table's draw is draw 0):\n%5s %4s %14s %11s %11s "
      "%12s %11s %s\n",
      replicas, static_cast<unsigned long long>(seed), "A", "IC", "mean R", "sd", "sem", "(paper-mean)/sd",
      "error/R", "resolved / symmetry-limited / shadow departed");
  for (std::size_t e = 0; e < entries.size(); ++e) {
    const std::size_t first = e * std::size_t(replicas);
    const auto ok = [&](std::size_t k) {
      return outcome.results[first + k].status == kernels::LaneStatus::ok;
    };
    const auto D = ensemble::replica_statistics(
        std::size_t(replicas),
        [&](std::size_t k) { return windowed_R(outcome.results[first + k], triangular); }, ok);
    const auto error = ensemble::replica_statistics(
        std::size_t(replicas), [&](std::size_t k) { return outcome.results[first + k].dissipation_error(); },
        ok);
    std::size_t resolved = 0, limited = 0, departed = 0;
    for (std::size_t k = 0; k < std::size_t(replicas); ++k) {
      const auto& result = outcome.results[first + k];
      resolved += result.dissipation_resolved();
      limited += result.symmetry_limited;
      departed += result.shadow_departed;
    }
    const double sample_sd = D.count > 1 ? D.std * std::sqrt(double(D.count) / double(D.count - 1)) : NAN;
    std::printf("%5.0f %4s %14.7e %11.3e %11.3e %12.2f %11.2e %zu / %zu / %zu of %zu\n", entries[e]->A,
                ensemble::kind_name(entries[e]->kind).data(), D.mean, sample_sd, D.sem,
                (entries[e]->paper_R - D.mean) / sample_sd, error.mean / D.mean, resolved, limited, departed,
                D.count);
  }
  std::printf(
      "error/R: the draws' mean error estimate of R; symmetry-limited members' R depends on the tolerance "
      "itself and no error bounds it (docs/regimes.md, \"Errors in CP, and symmetry-limited members\")\n");
}

}  // namespace

int run_table(const TableOptions& options) {
  const auto stepper = kernels::parse_stepper(options.stepper).value();
  const bool triangular = options.window == "triangular";
  RemoveOnSignal on_start;  // a signal before the file exists ends the command at once
  std::optional<io::OutputTarget> target;
  std::optional<RemoveOnSignal> on_signal;
  std::ofstream csv;
  if (!take_csv_output(options.output, csv_title, options.force, target, on_signal)) return 2;
  if (target) {
    csv.open(target->temporary());
    if (!csv) {
      std::cerr << "error: cannot write " << options.output << ": " << std::strerror(errno) << "\n";
      return 2;
    }
    csv << provenance_lines(options) << csv_header << "\n";
  }
  std::printf("%5s %4s %14s %14s %14s %14s %10s %8s %14s %14s %10s %8s %-16s %10s %10s\n", "A", "IC",
              "W (work)", "S (Stokes)", "R (drive)", "paper R", "R/paper-1", "steps/T", "paper W", "paper S",
              "R error", "dev/unc", "R error is", "W error", "S error");
  const auto start = std::chrono::steady_clock::now();
  ensemble::Disorder disorder;
  disorder.A = options.disorder;
  disorder.seed = options.disorder_seed;
  const auto outcome = integrate(paper_scene_with_errors(stepper, options.rtol, disorder));
  const auto estimators = integrate(paper_scene(stepper, options.estimator_rtol, disorder));
  for (std::size_t i = 0; i < paper::entries.size(); ++i) {
    const auto& ref = paper::entries[i];
    const auto& result = outcome.results[i];
    // outside CP from the tighter run; in CP from R's own run, since a tighter one seeds other escapes
    const auto& tight = ref.cp ? result : estimators.results[i];
    const double W = windowed(tight, ensemble::Channel::work, ensemble::Channel::work_moment, triangular);
    const double S = windowed(tight, ensemble::Channel::stokes, ensemble::Channel::stokes_moment, triangular);
    const double R = windowed_R(result, triangular);
    const double steps_per_period = result.steps_accepted / (paper::relax_periods + paper::average_periods);
    const double deviation = R / ref.paper_R - 1;
    const double error = result.dissipation_error();
    const std::string flag = error_flag(result);
    const double s = options.estimator_rtol / options.rtol;
    const double W_error = estimator_error(ref, result, tight, s, ensemble::Channel::work,
                                           ensemble::Channel::work_moment, triangular);
    const double S_error = estimator_error(ref, result, tight, s, ensemble::Channel::stokes,
                                           ensemble::Channel::stokes_moment, triangular);
    const auto ic = ensemble::kind_name(ref.kind);
    char ratio[16] = "       -";  // dev/unc only where the error bounds R
    if (error_is_bound(flag))
      std::snprintf(ratio, sizeof ratio, "%8.2f",
                    std::fabs(R - ref.paper_R) / (error + paper_rounding(ref.paper_R)));
    std::printf("%5.0f %4s %14.7e %14.7e %14.7e %14.7e %10.2e %8.0f %14.7e %14.7e %10.2e %s %-16s %10.2e %10.2e\n",
                ref.A, ic.data(), W, S, R, ref.paper_R, deviation, steps_per_period, ref.paper_W, ref.paper_S,
                error, ratio, flag.c_str(), W_error, S_error);
    if (csv) {
      char line[360];
      std::snprintf(line, sizeof line, "%g,%s,%.10e,%.10e,%.10e,%.7e,%.3e,%.1f,%.7e,%.7e,%.3e,%s,%.3e,%.3e\n",
                    ref.A, ic.data(), W, S, R, ref.paper_R, deviation, steps_per_period, ref.paper_W,
                    ref.paper_S, error, flag.c_str(), W_error, S_error);
      csv << line;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "stepper %s, rtol %g, %s window over periods 3 and 4 (W and S outside CP at rtol %g, where they "
      "converge, in CP from R's run; the paper's W at A = 11 lies 9e-5 below its R, ours equals R); R error: "
      "the estimate for the mean of periods 3 and 4 (a shadow run's where they slip); dev/unc: |R - paper R| "
      "over R error plus half a unit of the paper's 7th digit, where R error bounds R (- where it does not); "
      "W and S error: in CP the shadow's difference as R's, outside CP the tolerance pair's estimate for the "
      "tight run, of the kind R error is",
      options.stepper.c_str(), options.rtol, options.window.c_str(), options.estimator_rtol);
  if (options.disorder > 0)
    std::printf("; disorder sigma_A = %g (realization 0 of seed %llu)", options.disorder,
                static_cast<unsigned long long>(options.disorder_seed));
  std::printf(": %.2f s", seconds);
  if (target) {
    csv.close();
    if (!csv) {
      std::printf("\n");
      std::cerr << "error: writing " << options.output << " failed: " << std::strerror(errno) << "\n";
      return 1;
    }
    on_signal.reset();
    target->claim_temporary();
    target->commit();
    std::printf(", table written to %s%s", options.output.c_str(), target->replaced() ? " (replaced)" : "");
  }
  std::printf("\n");
  if (options.replicas > 1)
    print_cp_draws(stepper, options.rtol, disorder, options.replicas, options.seed, triangular);
  return 0;
}

}  // namespace rotorsweep::apps
