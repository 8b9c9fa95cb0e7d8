// How a member of a scene becomes a lane of the row model (docs/model.md §1, 2, 7, 8): its initial
// angles from its own stream, and its parameters A, g, the strict-FM mark, its disorder or couplings.
#pragma once

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <vector>

#include "ensemble/rows/disorder.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/symmetry_probe.hpp"
#include "kernels/lanes/counter_random.hpp"

namespace rotorsweep::ensemble {

template <class Model>
struct RowSetup {
  explicit RowSetup(const Scene* s) : scene(s) {}

  const Scene* scene;

  /// The model's construction arguments after the rows and the arena: the quadratures the scene's
  /// observables need.
  std::tuple<kernels::Integrals> model_arguments() const { return {scene->observables.quadratures()}; }

  std::vector<double> initial_state(const Member& member) const {
    return member_initial_angles(*scene, member);
  }

  /// A member that starts with all rows equal is marked strict FM (symmetry protection); a symmetry
  /// probe carries its deviations (member_deviations). The
  /// parameters point into this setup's buffers (its disorder, and the coupling table of its N).
  typename Model::Parameters parameters(const Member& member, const std::vector<double>& theta) {
    const bool strict_fm = std::all_of(theta.begin(), theta.end(), [&](double x) { return x == theta[0]; });
    typename Model::Parameters p{member.A, member.g, strict_fm};
    if constexpr (coupled) {
      if (table_rows != member.rows) {
        table = scene->couplings.for_rows(member.rows);
        table_rows = member.rows;
      }
      p.a = table.a;
      p.b = table.b.data();
      p.c = table.c.data();
      p.range = table.range();
      p.open = scene->couplings.open;
    }
    if (!scene->disorder.any() && member.rerun != Rerun::probe) return p;
    deviations = member_deviations(scene->disorder, member);
    const auto rows_or_null = [](const std::vector<double>& v) { return v.empty() ? nullptr : v.data(); };
    p.A_rows = rows_or_null(deviations.A);
    p.anisotropy_rows = rows_or_null(deviations.anisotropy);
    if constexpr (!coupled) p.coupling_rows = rows_or_null(deviations.coupling);
    return p;
  }

  /// The key of the member's noise stream (thermal seed, replica).
  std::uint64_t noise_key(const Member& member) const {
    return kernels::RandomStream(scene->thermal.seed, member.stream).key();
  }

  RowDeviations deviations;  ///< the last member's disorder
  /// Whether the model takes a coupling table (CoupledRows) rather than per-row disorder.
  static constexpr bool coupled = requires(typename Model::Parameters p) { p.range; };
  CouplingTable table;  ///< the coupling table of N = table_rows
  std::size_t table_rows = 0;
};

}  // namespace rotorsweep::ensemble
