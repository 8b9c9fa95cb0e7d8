// The dense stage solve of coupled rows (docs/model.md §1 "Extended couplings") on a team of threads
// (docs/architecture.md "Teams"): DenseSymmetric's LDLᵀ and its substitutions with each column's rows spread
// over the ranks.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/linear/dense_symmetric.hpp"

namespace rotorsweep::kernels {

/// DenseSymmetric<double> of one member, shared by a team: the factor goes column by column,
/// right-looking, every rank taking the column's pivot from the updated diagonal, forming L's entries
/// in its rows (row i on rank i mod R) and then taking the column's terms from its rows' trailing
/// entries, two barriers per column; the solve's two substitutions go column by column too, each rank
/// updating its rows, one barrier per column; J x goes row by row over the ranks. Every value is computed as
/// DenseSymmetric computes it, so the factor, the solution and the inertia test have its bits.
template <class Team>
class TeamDenseSymmetric {
 public:
  static constexpr std::size_t storage_size(std::size_t n) { return DenseSymmetric<double>::storage_size(n); }

  ROTORSWEEP_HD TeamDenseSymmetric(std::size_t n, std::size_t ranks, LaneArena<double>& arena)
      : ranks_(ranks), dense_(n, arena) {}

  ROTORSWEEP_HD std::size_t size() const { return dense_.size(); }
  ROTORSWEEP_HD void set_band(std::size_t band, bool wrap) { dense_.set_band(band, wrap); }
  ROTORSWEEP_HD double& entry(std::size_t j, std::size_t k) { return dense_.entry(j, k); }
  ROTORSWEEP_HD const double& entry(std::size_t j, std::size_t k) const { return dense_.entry(j, k); }
  ROTORSWEEP_HD bool positive_definite() const { return dense_.positive_definite(); }
  ROTORSWEEP_HD void keep_constant_solutions(bool keep) { dense_.keep_constant_solutions(keep); }

  /// Factorises M = shift·I − J in place (every rank, together): J holds until then.
  ROTORSWEEP_HD void factor(Team& team, double shift) {
    const std::size_t n = dense_.size();
    team.each([&](std::size_t r) { dense_.start_factor(shift, share(r)); });
    for (std::size_t k = 0; k < n; ++k) {
      team.each([&](std::size_t r) {
        const double d = dense_.updated_pivot(k);  // alike on every rank
        if (k % ranks_ == r) dense_.set_pivot(k, d);
        dense_.column_from_updates(k, 1.0 / d, share(r));
      });
      team.each([&](std::size_t r) { dense_.update_below(k, share(r)); });
    }
    dense_.finish_factor(shift);
  }

  /// Solves M x = r in place, with M from the last factor(); r is the team's.
  ROTORSWEEP_HD void solve(Team& team, double* r) const {
    const std::size_t n = dense_.size();
    typename DenseSymmetric<double>::ConstantRightSide constant{};
    team.each([&](std::size_t) { constant = dense_.constant_right_side(r); });  // alike on every rank
    for (std::size_t m = 0; m + 1 < n; ++m)
      team.each([&](std::size_t rank) { dense_.forward_column(m, r, share(rank)); });
    team.each([&](std::size_t rank) { dense_.scale(r, share(rank)); });
    for (std::size_t i = n; i-- > 1;)
      team.each([&](std::size_t rank) { dense_.backward_column(i, r, share(rank)); });
    team.each([&](std::size_t rank) { dense_.finish_solve(constant, r, share(rank)); });
  }

  /// (J x)_j, as DenseSymmetric's.
  ROTORSWEEP_HD double row_product(std::size_t j, const double* x) const { return dense_.row_product(j, x); }
  /// y += J x, each rank its rows.
  ROTORSWEEP_HD void multiply_add(Team& team, const double* x, double* y) const {
    const std::size_t n = dense_.size();
    team.each([&](std::size_t r) {
      for (std::size_t j = r; j < n; j += ranks_) y[j] += dense_.row_product(j, x);
    });
  }

 private:
  ROTORSWEEP_HD RowShare share(std::size_t rank) const { return {rank, ranks_}; }

  std::size_t ranks_;
  DenseSymmetric<double> dense_;
};

}  // namespace rotorsweep::kernels
