// The nearest-neighbour rows' right-hand side at one point on a team (docs/architecture.md "Teams"):
// f over each rank's rows, and the quadratures' integrands (docs/model.md §3) from team sums.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"

namespace rotorsweep::kernels {

/// f(y, t) into f, each rank its rows (evaluate_range), and the integrands into qdot from the team's
/// sums of the ranks' parts, which each rank leaves at partial + stride · rank (5 values).
template <class Team>
ROTORSWEEP_HD void team_evaluate(Team& team, const NearestNeighbourRows<double>& model,
                                 NearestNeighbourRows<double>::Workspace& work, const double* y, double t,
                                 double* f, double* partial, std::size_t stride, double* qdot) {
  using Model = NearestNeighbourRows<double>;
  const std::size_t n = model.dimension(), ranks = team.size();
  team.each([&](std::size_t r) {
    const TeamRows rows = team_rows(n, ranks, r);
    const Model::RowSums sums = model.evaluate_range(work, y, t, f, rows.begin, rows.end);
    const Model::IntegrandSums more = model.integrand_sums_range(work, f, rows.begin, rows.end);
    double* mine = partial + stride * r;
    mine[0] = sums.lag;
    mine[1] = sums.cos_link;
    mine[2] = more.lag_force;
    mine[3] = more.force_squares;
    mine[4] = more.energy;
  });
  const auto total = [&](std::size_t i) {
    return team.sum([&](std::size_t r) { return partial[stride * r + i]; });
  };
  Model::RowSums sums;
  sums.lag = total(0);
  sums.cos_link = total(1);
  Model::IntegrandSums more;
  more.lag_force = total(2);
  more.force_squares = total(3);
  more.energy = total(4);
  model.team_integrands(sums, more, t, qdot);
}

}  // namespace rotorsweep::kernels
