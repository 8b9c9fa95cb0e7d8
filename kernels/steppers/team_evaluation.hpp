// A model's right-hand side at one point on a team (docs/architecture.md "Teams"): f over each rank's
// rows or rotors, and the quadratures' integrands (docs/model.md §3, §9) from team sums.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/models/slider/slider_model.hpp"

namespace rotorsweep::kernels {

/// Whether Model is the slider (its ranks split rotors, each with θ and, with inertia, ω).
template <class Model>
inline constexpr bool team_slider_model = false;
template <bool Inertial>
inline constexpr bool team_slider_model<SliderModel<double, Inertial>> = true;

/// The units a team splits among its ranks (team_rows): rows, or the slider's rotors.
template <class Model>
ROTORSWEEP_HD std::size_t team_units(const Model& model) {
  if constexpr (team_slider_model<Model>)
    return model.rotors();
  else
    return model.dimension();
}

/// Whether Model's range forms read the trigonometry of other ranks' rows, which a phase of its own
/// puts in place first (CoupledRows: a row's pairs reach across the row), rather than taking their
/// neighbours' themselves (NearestNeighbourRows).
template <class Model>
concept TrigonometryFirst = requires(const Model& model, typename Model::Workspace& work, const double* y) {
  model.trigonometry_range(work, y, 0.0, std::size_t(0), std::size_t(0));
};

/// Each rank's rows' trigonometry at (y, t) where Model's range forms read it across ranks; nothing
/// (and no barrier) otherwise.
template <class Team, class Model>
ROTORSWEEP_HD void team_trigonometry(Team& team, const Model& model, typename Model::Workspace& work,
                                     const double* y, double t) {
  if constexpr (TrigonometryFirst<Model>)
    team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(team_units(model), team.size(), r);
      model.trigonometry_range(work, y, t, rows.begin, rows.end);
    });
}

/// The slider's f(y, t) into f and its integrands into qdot: each rank its rotors' trigonometry and
/// field (with the curvatures linearize reads), then their torques, then their rates and sums (2 values
/// at partial + stride · rank).
template <class Team, bool Inertial>
ROTORSWEEP_HD void team_evaluate(Team& team, const SliderModel<double, Inertial>& model,
                                 typename SliderModel<double, Inertial>::Workspace& work, const double* y,
                                 double t, double* f, double* partial, std::size_t stride, double* qdot) {
  const auto each_rank = [&](auto&& part) {
    team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(model.rotors(), team.size(), r);
      part(rows.begin, rows.end, partial + stride * r);
    });
  };
  each_rank([&](std::size_t begin, std::size_t end, double*) {
    model.prepare_range(work, y, t, true, begin, end);
  });
  each_rank([&](std::size_t begin, std::size_t end, double*) { model.torque_range(work, begin, end); });
  each_rank([&](std::size_t begin, std::size_t end, double* mine) {
    const auto sums = model.rates_range(work, y, f, begin, end);
    mine[0] = sums.force;
    mine[1] = sums.dissipation;
  });
  typename SliderModel<double, Inertial>::RotorSums sums;
  sums.force = team.sum([&](std::size_t r) { return partial[stride * r]; });
  sums.dissipation = team.sum([&](std::size_t r) { return partial[stride * r + 1]; });
  model.team_integrands(sums, qdot);
}

/// f(y, t) into f, each rank its rows (evaluate_range), and the integrands into qdot from the team's
/// sums of the ranks' parts, which each rank leaves at partial + stride · rank (5 values).
template <class Team, class Model>
ROTORSWEEP_HD void team_evaluate(Team& team, const Model& model, typename Model::Workspace& work,
                                 const double* y, double t, double* f, double* partial, std::size_t stride,
                                 double* qdot) {
  const std::size_t n = model.dimension(), ranks = team.size();
  team_trigonometry(team, model, work, y, t);
  team.each([&](std::size_t r) {
    const TeamRows rows = team_rows(n, ranks, r);
    const typename Model::RowSums sums = model.evaluate_range(work, y, t, f, rows.begin, rows.end);
    const typename Model::IntegrandSums more = model.integrand_sums_range(work, f, rows.begin, rows.end);
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
  typename Model::RowSums sums;
  sums.lag = total(0);
  sums.cos_link = total(1);
  typename Model::IntegrandSums more;
  more.lag_force = total(2);
  more.force_squares = total(3);
  more.energy = total(4);
  model.team_integrands(sums, more, t, qdot);
}

}  // namespace rotorsweep::kernels
