// The slider's stage solve (docs/model.md §9 "Integrating it") on a team of threads (docs/architecture.md
// "Teams"): SecondOrderJacobian's reduction to σ − K over each rank's rotors, K's LDLᵀ by TeamDenseSymmetric.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/linear/second_order_jacobian.hpp"
#include "kernels/linear/team_dense_symmetric.hpp"

namespace rotorsweep::kernels {

/// SecondOrderJacobian<double, Inertial> of one member, shared by a team: the reduced right-hand side
/// and the recovery of (θ, ω) go over each rank's rotors (team_rows), the stiffness K factorises and
/// solves as TeamDenseSymmetric, and J x goes row by row; every value as SecondOrderJacobian computes
/// it, so the solution, J x and the inertia test have its bits.
template <class Team, bool Inertial>
class TeamSecondOrderJacobian {
 public:
  static constexpr std::size_t storage_size(std::size_t dimension) {
    return SecondOrderJacobian<double, Inertial>::storage_size(dimension);
  }

  ROTORSWEEP_HD TeamSecondOrderJacobian(std::size_t dimension, std::size_t ranks, LaneArena<double>& arena)
      : n_(SecondOrderJacobian<double, Inertial>::rotors(dimension)),
        stiffness_(n_, ranks, arena),
        reduced_(arena.take(n_)) {}

  /// K = ∂τ/∂θ: each rank sets its rows' entries (entry(j, k) and entry(k, j) alike).
  ROTORSWEEP_HD TeamDenseSymmetric<Team>& stiffness() { return stiffness_; }
  /// The member's I and γ (every rank, alike).
  ROTORSWEEP_HD void set_dynamics(double inertia, double damping) {
    inertia_ = inertia;
    damping_ = damping;
  }

  /// y += J x, each rank its rotors' rows (θ and ω); until the next factor(), which takes K's place.
  ROTORSWEEP_HD void multiply_add(Team& team, const double* x, double* y) const {
    each_rotor(team, [&](std::size_t j) {
      const double sum = stiffness_.row_product(j, x);
      if constexpr (Inertial) {
        y[j] += x[n_ + j];
        y[n_ + j] += (sum - damping_ * x[n_ + j]) * (1.0 / inertia_);
      } else {
        y[j] += sum * (1.0 / damping_);
      }
    });
  }

  /// Factorises the reduced matrix σ − K of the stage matrix shift·1 − J (every rank, together).
  ROTORSWEEP_HD void factor(Team& team, double shift) {
    shift_ = shift;
    if constexpr (Inertial)
      stiffness_.factor(team, shift * (shift * inertia_ + damping_));
    else
      stiffness_.factor(team, shift * damping_);
  }

  /// Solves (shift·1 − J) x = r in place, with the last factor(); r is the team's.
  ROTORSWEEP_HD void solve(Team& team, double* r) const {
    if constexpr (Inertial) {
      const double velocity_weight = shift_ * inertia_ + damping_;
      each_rotor(team, [&](std::size_t j) { reduced_[j] = inertia_ * r[n_ + j] + velocity_weight * r[j]; });
      stiffness_.solve(team, reduced_);
      each_rotor(team, [&](std::size_t j) {
        r[n_ + j] = shift_ * reduced_[j] - r[j];
        r[j] = reduced_[j];
      });
    } else {
      each_rotor(team, [&](std::size_t j) { r[j] *= damping_; });
      stiffness_.solve(team, r);
    }
  }

  ROTORSWEEP_HD bool positive_definite() const { return stiffness_.positive_definite(); }

 private:
  /// row(j) for every rotor, each rank its own, one phase.
  template <class Row>
  ROTORSWEEP_HD void each_rotor(Team& team, Row&& row) const {
    team.each([&](std::size_t r) {
      const TeamRows rows = team_rows(n_, team.size(), r);
      for (std::size_t j = rows.begin; j < rows.end; ++j) row(j);
    });
  }

  std::size_t n_;
  TeamDenseSymmetric<Team> stiffness_;
  double* reduced_;
  double inertia_ = 1.0, damping_ = 1.0, shift_ = 1.0;
};

}  // namespace rotorsweep::kernels
