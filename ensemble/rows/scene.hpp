// A sweep as the user described it (one scene file): model, parameter grids, initial
// conditions, schedule, observables, numerics, output. Plain data; io/ parses and validates it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "ensemble/engine/device.hpp"
#include "ensemble/engine/member_progress.hpp"
#include "ensemble/rows/coupling_table.hpp"
#include "ensemble/rows/disorder.hpp"
#include "ensemble/rows/initial_conditions.hpp"
#include "ensemble/rows/observables.hpp"
#include "kernels/steppers/step_control.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

/// The model a scene's members run: its kinds and traits in ensemble/rows/row_models.hpp.
enum class RowModelKind : unsigned char;

enum class LaneKind { simd, scalar };

/// One (N, tolerances) setting of a scene; members of different variants run in separate
/// lane blocks (a block shares its row count and tolerances). Member carries its variant's values.
struct Variant {
  std::size_t rows = 20;
  double rtol = 1e-6;
  double atol = 1e-9;
};

/// Thermal noise (docs/model.md §7): temperature T in units of ε, integrated with the Langevin
/// stepper in steps_per_period equal steps; each member's noise comes from (seed, its stream).
struct Thermal {
  double temperature = 0.0;
  int steps_per_period = 2000;  ///< at least this many steps per period
  double step_fraction = 0.5;   ///< and steps no longer than step_fraction · g / κ (κ: curvature bound)
  std::uint64_t seed = 1;
  bool on() const { return temperature > 0; }
};

struct Scene {
  std::string text;  ///< the scene file as written, stored in the output for provenance

  std::vector<std::size_t> row_counts{20};  ///< model.rows: every N to run
  RowModelKind model{};                     ///< model.kind, or for rows the couplings' (row_model_for)
  RowCouplings couplings;                   ///< model.couplings, range, row_length, coupling_table, boundary
  std::vector<double> rtol_values{1e-6};    ///< numerics.rtol, paired with atol_values
  std::vector<double> atol_values{1e-9};
  std::vector<double> g_values;  ///< drive: g = damping × drive speed
  std::vector<double> A_values;  ///< sweep: substrate strength A
  std::vector<InitialKind> kinds{InitialKind::afm};
  std::vector<double> noise_values{0.01};  ///< initial.noise: every η of docs/model.md §2
  std::vector<double> offset_values{0.0};  ///< initial.offset: every θ0 of docs/model.md §2
  std::vector<double> exact_angles;        ///< for kind exact
  int replicas = 1;
  std::uint64_t seed = 1;
  Disorder disorder;  ///< quenched per-row disorder; replica r is realization r
  Thermal thermal;    ///< temperature > 0: overdamped Langevin dynamics

  int relax_periods = 2;
  int average_periods = 2;
  double steady_tol = 0.0;  ///< > 0: retire a member once successive periods agree to this
  int max_periods = 50;
  /// The periods as the engine's stops (relaxed and averaged; with a steady test up to max_periods).
  StopSchedule period_schedule() const {
    return {relax_periods + average_periods, max_periods, steady_tol > 0};
  }
  /// A shadow run's stops: its primary's averaged periods again, without a steady test.
  StopSchedule shadow_schedule() const { return {average_periods, 0, false}; }
  bool refill = true;  ///< refill a retired member's lane at once (false: wait for the whole block)

  ObservableSet observables = ObservableSet::defaults();  ///< observables.<key> of each declaration
  bool period_series = false;
  bool row_profiles = false;  ///< R_j per row and the alignment per link (default: on for open rows)
  double slip_rate = 10.0;    ///< a step with max_j |Δθ_j|/Δt above this is part of a slip
  /// observables.slip_kinds: a member that slips in every averaged period runs again at g/10, and each
  /// slip is a jump or a smooth slip by how its energy scales (ensemble/rows/slip_kinds.hpp)
  bool slip_kinds = false;

  std::size_t stepper = kernels::default_stepper();  ///< position in kernels::steppers
  double h_max = 0.5;
  double max_steps = 1e8;
  kernels::StepController controller = kernels::StepController::integral;  ///< numerics.controller
  LaneKind lanes = LaneKind::simd;
  Device device = Device::cpu;
  bool wrap_angles = false;  ///< restart every period at t = 0 with θ_j in [0, 2π)
  /// numerics.global_error = "shadow": a member whose averaged periods slip runs again at tolerances
  /// × shadow_tolerance_scale, and D's error covers the difference (ensemble/rows/shadow_run.hpp);
  /// "local": D's error is the local estimate alone
  bool shadow_runs = true;

  std::string output_path;

  bool has(Observable o) const { return observables[o]; }
  /// Whether the regime rule has what it needs (alignment extrema and slip counts).
  bool classifies_regimes() const { return observables.classifies_regimes(); }
  /// Whether members that slip get shadow runs: global_error = "shadow", T = 0, D and slips observed.
  bool runs_shadows() const {
    return shadow_runs && !thermal.on() && has(Observable::slips) && has(Observable::dissipation);
  }
  /// Whether no physical perturbation exceeds the tolerance rtol: T = 0 and every disorder below
  /// rtol, so that the integration error breaks the symmetry at each slip (symmetry-limited).
  bool symmetry_limited(double rtol) const {
    if (thermal.on()) return false;
    double largest = std::max({disorder.A, disorder.anisotropy, disorder.coupling});
    for (const auto* rows : {&disorder.A_rows, &disorder.anisotropy_rows, &disorder.coupling_rows})
      for (const double x : *rows) largest = std::max(largest, std::fabs(x));
    return largest < rtol;
  }
  /// Every N × every (rtol, atol) pair, N outermost.
  std::vector<Variant> variants() const {
    std::vector<Variant> out;
    for (std::size_t n : row_counts)
      for (std::size_t i = 0; i < rtol_values.size(); ++i) out.push_back({n, rtol_values[i], atol_values[i]});
    return out;
  }
  std::size_t max_rows() const {
    std::size_t n = 0;
    for (std::size_t r : row_counts) n = r > n ? r : n;
    return n;
  }
  /// The sizes of the plan's axes: rows, rtol, A, g, noise, offset, kinds, replicas.
  std::array<std::size_t, 8> axis_sizes() const {
    return {row_counts.size(),   rtol_values.size(),   A_values.size(), g_values.size(),
            noise_values.size(), offset_values.size(), kinds.size(),    std::size_t(replicas)};
  }
  /// The replicas of a kind: exact starts differ between replicas only through drawn disorder or
  /// temperature (the replica's streams); without either they run once.
  std::size_t replicas_of(InitialKind kind) const {
    return kind != InitialKind::exact || disorder.drawn() || thermal.on() ? std::size_t(replicas) : 1;
  }
  /// The number of members: variants × A × g × (noise × offset × the replicas of each kind that uses
  /// them + the replicas of each kind that does not); SIZE_MAX where that overflows.
  std::size_t member_count() const {
    std::size_t starts = noise_values.size(), block = 0;
    if (__builtin_mul_overflow(starts, offset_values.size(), &starts)) return SIZE_MAX;
    for (InitialKind kind : kinds) {
      std::size_t members = replicas_of(kind);
      if (kind_uses_noise(kind) && __builtin_mul_overflow(members, starts, &members)) return SIZE_MAX;
      if (__builtin_add_overflow(block, members, &block)) return SIZE_MAX;
    }
    std::size_t count = block;
    for (std::size_t n : {row_counts.size(), rtol_values.size(), A_values.size(), g_values.size()})
      if (__builtin_mul_overflow(count, n, &count)) return SIZE_MAX;
    return count;
  }
};

}  // namespace rotorsweep::ensemble
