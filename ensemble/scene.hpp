// A sweep as the user described it (one scene file): model, parameter grids, initial
// conditions, schedule, observables, numerics, output. Plain data; io/ parses and validates it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ensemble/initial_conditions.hpp"
#include "kernels/stepper_choice.hpp"

namespace rotorsweep::ensemble {

enum class LaneKind { simd, scalar };

/// One (N, tolerances) setting of a scene; members of different variants run in separate
/// lane blocks (a block shares its row count and tolerances).
struct Variant {
  std::size_t rows = 20;
  double rtol = 1e-6;
  double atol = 1e-9;
};

struct Scene {
  std::string text;  ///< the scene file as written, stored in the output for provenance

  std::vector<std::size_t> row_counts{20};  ///< model.rows: every N to run
  std::vector<double> rtol_values{1e-6};    ///< numerics.rtol, paired with atol_values
  std::vector<double> atol_values{1e-9};
  std::size_t rows = 20;         ///< N of the variant being run (the first one after parsing)
  std::vector<double> g_values;  ///< drive: g = damping × drive speed
  std::vector<double> A_values;  ///< sweep: substrate strength A
  std::vector<InitialKind> kinds{InitialKind::afm};
  double noise = 0.01;               ///< η of model.md §2
  double offset = 0.0;               ///< θ0 of model.md §2
  std::vector<double> exact_angles;  ///< for kind exact
  int replicas = 1;
  std::uint64_t seed = 1;

  int relax_periods = 2;
  int average_periods = 2;
  double steady_tol = 0.0;  ///< > 0: retire a member once successive periods agree to this
  int max_periods = 50;
  bool refill = true;  ///< refill a retired member's lane at once (false: wait for the whole block)

  bool dissipation = true;  ///< R per period
  bool estimators = false;  ///< W and S per period beside R
  bool alignment = true;    ///< ∫ρ̄ dt and min/max of ρ̄
  bool energy = false;      ///< ∫H dt
  bool slips = true;        ///< count slip events
  bool period_series = false;
  double slip_rate = 10.0;  ///< a step with max_j |Δθ_j|/Δt above this is part of a slip

  kernels::StepperKind stepper = kernels::StepperKind::rodas4;
  double rtol = 1e-6;  ///< tolerances of the variant being run
  double atol = 1e-9;
  double h_max = 0.5;
  double max_steps = 1e8;
  LaneKind lanes = LaneKind::simd;
  bool wrap_angles = false;  ///< restart every period at t = 0 with θ_j in [0, 2π)

  std::string output_path;

  /// Whether the regime rule has what it needs (alignment extrema and slip counts).
  bool classifies_regimes() const { return alignment && slips; }
  /// Every N × every (rtol, atol) pair, N outermost.
  std::vector<Variant> variants() const {
    std::vector<Variant> out;
    for (std::size_t n : row_counts)
      for (std::size_t i = 0; i < rtol_values.size(); ++i) out.push_back({n, rtol_values[i], atol_values[i]});
    return out;
  }
  /// This scene with the variant's N and tolerances as the ones to run.
  Scene for_variant(const Variant& v) const {
    Scene s = *this;
    s.rows = v.rows;
    s.rtol = v.rtol;
    s.atol = v.atol;
    return s;
  }
  std::size_t max_rows() const {
    std::size_t n = 0;
    for (std::size_t r : row_counts) n = r > n ? r : n;
    return n;
  }
  std::size_t member_count() const {
    return row_counts.size() * rtol_values.size() * A_values.size() * g_values.size() * kinds.size() *
           std::size_t(replicas);
  }
};

}  // namespace rotorsweep::ensemble
