// Test support: one member of the nearest-neighbour rows (docs/model.md §1) integrated over two periods
// from an AFM start by the adaptive steps on a host team and in an emulated warp's registers, to hold
// against the lanes' (lanes_reference.hpp): the three forms of AdaptiveSteps.
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <vector>

#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/lanes/warp.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/models/rows/row_models_on_teams.hpp"
#include "kernels/models/rows/warp_rows.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "kernels/steppers/team_integrator.hpp"
#include "kernels/steppers/team_rosenbrock.hpp"
#include "kernels/steppers/warp_member_form.hpp"
#include "kernels/steppers/warp_rosenbrock.hpp"
#include "support/lanes_reference.hpp"

namespace rotorsweep::testing {

using RowsOnLanes = kernels::NearestNeighbourRows<double>;

/// afm_start's two periods of `model` (N = n) on a host team of `ranks` with `table` at tight_tolerances.
inline TwoPeriods on_team(const RowsOnLanes& model, std::size_t n, std::size_t ranks,
                          const kernels::RosenbrockTableau& table) {
  using namespace kernels;
  using Team = TeamIntegrator<HostTeam, TeamRosenbrock<HostTeam, RowsOnLanes>>;
  const double scale = AdaptiveIntegrator<RowsOnLanes, RosenbrockStepper<RowsOnLanes>>::first_step_scale(
      tight_tolerances, table);
  std::vector<double> storage(counted_storage<double>([&](LaneArena<double>& arena) {
    const Team counted(model, ranks, table, tight_tolerances, StepLimits{}, scale, arena);
  }));
  LaneArena<double> arena(storage.data(), storage.size());
  Team integrator(model, ranks, table, tight_tolerances, StepLimits{}, scale, arena);
  std::vector<double> theta = afm_start(n);
  TeamMemberState state;
  state.y = theta.data();
  state.t_stop = 2 * two_pi;
  HostTeam team(ranks);
  integrator.advance(team, model, state);
  REQUIRE(state.status == LaneStatus::ok);
  return {theta, std::vector<double>(state.quad, state.quad + 8),
          state.steps_accepted + state.steps_rejected};
}

/// afm_start's two periods of the rows with parameters p (N = n) in the registers of L emulated lanes of
/// R slots each (WarpRows, every quadrature) with S stage vectors, `table` at tight_tolerances.
template <std::size_t L, std::size_t R, bool PerRow, std::size_t S = 8>
TwoPeriods in_registers(std::size_t n, const RowsOnLanes::Parameters& p,
                        const kernels::RosenbrockTableau& table) {
  using namespace kernels;
  using W = HostWarp<L>;
  using Model = WarpRows<W, R, PerRow, all_integrals>;
  using Integrator = WarpIntegrator<Model, WarpRosenbrock<Model, S>>;
  const WarpRowSlots<W, R> slots(n);
  Model model(slots, all_integrals, {p.A, p.g, p.strict_fm, p.A_rows, p.anisotropy_rows, p.coupling_rows});
  const double scale = AdaptiveIntegrator<RowsOnLanes, RosenbrockStepper<RowsOnLanes>>::first_step_scale(
      tight_tolerances, table);
  Integrator integrator(table, tight_tolerances, StepLimits{}, scale);
  typename Integrator::State state;
  const auto theta = afm_start(n);
  for (std::size_t r = 0; r < R; ++r)
    for (std::size_t l = 0; l < L; ++l)
      lane_set(state.y[r], l,
               mask_get(slots.real(r), l) ? theta[std::size_t(lane_get(slots.row(r), l))] : 0.0);
  state.t_stop = 2 * two_pi;
  integrator.advance(model, state);
  REQUIRE(state.status == LaneStatus::ok);
  TwoPeriods run{std::vector<double>(n), std::vector<double>(state.quad, state.quad + 8),
                 state.steps_accepted + state.steps_rejected};
  for (std::size_t r = 0; r < R; ++r)
    for (std::size_t l = 0; l < L; ++l)
      if (mask_get(slots.real(r), l))
        run.theta[std::size_t(lane_get(slots.row(r), l))] = lane_get(state.y[r], l);
  return run;
}

/// Whether `run` follows `lanes`: every quadrature and angle within `tolerance` (relative, absolute for
/// angles), step attempts within 1 %.
inline void check_follows_lanes(const TwoPeriods& run, const TwoPeriods& lanes, double tolerance) {
  for (std::size_t q = 0; q < 8; ++q) {
    INFO("quadrature " << q);
    CHECK(run.quad[q] == Approx(lanes.quad[q]).epsilon(tolerance).margin(1e-12));
  }
  double largest = 0;
  for (std::size_t j = 0; j < lanes.theta.size(); ++j)
    largest = std::max(largest, std::fabs(run.theta[j] - lanes.theta[j]));
  CHECK(largest < tolerance);
  CHECK(run.steps == Approx(lanes.steps).epsilon(0.01));
}

}  // namespace rotorsweep::testing
