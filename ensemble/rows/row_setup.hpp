// How a member of a scene becomes a lane of the row model (docs/model.md §1, 2, 7, 8): its initial
// angles from its own stream, and its parameters A, g, the strict-FM mark, its disorder or couplings.
#pragma once

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <vector>

#include "ensemble/rows/disorder.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/symmetry_probe.hpp"
#include "kernels/lanes/counter_random.hpp"
#include "kernels/lanes/lane_arena.hpp"

namespace rotorsweep::ensemble {

template <class Model>
struct RowSetup {
  explicit RowSetup(const Scene* s) : scene(s) {}

  const Scene* scene;

  /// The model's construction arguments after the rows and the arena: the quadratures the scene's
  /// observables need, where the model chooses them (a model of one quadrature takes none).
  auto model_arguments() const {
    if constexpr (std::is_constructible_v<Model, std::size_t, kernels::LaneArena<typename Model::lane_type>&,
                                          kernels::Integrals>)
      return std::tuple<kernels::Integrals>{scene->observables.quadratures()};
    else
      return std::tuple<>{};
  }

  std::vector<double> initial_state(const Member& member) const {
    return member_initial_angles(*scene, member);
  }

  /// A member that starts with all rows equal is marked strict FM (symmetry protection); a symmetry
  /// probe carries its deviations (member_deviations). The parameters point into this setup's buffers
  /// (its disorder, and the coupling table of its N); a model takes those of them its Parameters have.
  typename Model::Parameters parameters(const Member& member, const std::vector<double>& theta) {
    typename Model::Parameters p{};
    p.A = member.A;
    p.g = member.g;
    if constexpr (requires { p.strict_fm; })
      p.strict_fm = std::all_of(theta.begin(), theta.end(), [&](double x) { return x == theta[0]; });
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
    if constexpr (requires { p.A_rows; }) {
      if (!scene->disorder.any() && member.rerun != Rerun::probe) return p;
      deviations = member_deviations(scene->disorder, member);
      const auto rows_or_null = [](const std::vector<double>& v) { return v.empty() ? nullptr : v.data(); };
      p.A_rows = rows_or_null(deviations.A);
      p.anisotropy_rows = rows_or_null(deviations.anisotropy);
      if constexpr (requires { p.coupling_rows; }) p.coupling_rows = rows_or_null(deviations.coupling);
    }
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
