// The slider on a team (docs/architecture.md "Teams"): SliderModel on the double lane as a TeamModel —
// its rotors split among the ranks, f, the integrands and the reduced J (docs/model.md §9) over each
// rank's rotors.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/linear/team_second_order_jacobian.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/steppers/team_model_concept.hpp"

namespace rotorsweep::kernels {

template <bool Inertial, class Team>
struct TeamStageMatrixOf<SliderModel<double, Inertial>, Team> {
  using type = TeamSecondOrderJacobian<Team, Inertial>;
};

/// A team splits the slider's rotors (each with θ and, with inertia, ω).
template <bool Inertial>
ROTORSWEEP_HD std::size_t team_units(const SliderModel<double, Inertial>& model) {
  return model.rotors();
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

/// K's rows, ∂f/∂t and the integrands' gradients at time t, after team_evaluate there: each rank its
/// rotors, its gradients from its own rows of K, its parts of the time sums at partial + stride · rank.
template <class Team, bool Inertial>
ROTORSWEEP_HD void team_linearize(Team& team, const SliderModel<double, Inertial>& model,
                                  const typename SliderModel<double, Inertial>::Workspace& work,
                                  const double* y, const double*, TeamSecondOrderJacobian<Team, Inertial>& J,
                                  double* df_dt, double*, double* dq_dy, double* partial, std::size_t stride,
                                  double t) {
  team.each([&](std::size_t r) {
    const TeamRows rows = team_rows(model.rotors(), team.size(), r);
    model.jacobian_range(work, y, t, J, df_dt, dq_dy, partial + stride * r, rows.begin, rows.end);
  });
}

}  // namespace rotorsweep::kernels
