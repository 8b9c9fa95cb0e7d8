// The stage matrix M = shift·I − J of the row model's cyclic tridiagonal Jacobian (docs/model.md §1)
// solved by a team of threads for one member (docs/numerics.md "The stage solve on a team").
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/linear/cyclic_tridiagonal.hpp"
#include "kernels/linear/tridiagonal_chain.hpp"

namespace rotorsweep::kernels {

/// J and the factorisation of M = shift·I − J, for one member over n >= 2 rows shared by a team of R
/// ranks (R <= n; team_rows gives each rank a block). J is CyclicTridiagonal's: J(k, k+1) =
/// J(k+1, k) = off[k], link k coupling rows k and (k+1) mod n.
///
/// The last row of each block is a border, b_r; the block's other rows form a plain tridiagonal
/// chain, coupled to the previous block's border b_{r−1} at its first row and to its own border at
/// its last. Each rank eliminates its chain (no pivoting) and its two spikes, M_II⁻¹ times the
/// chain's columns of the two borders, at once with the others; the borders' Schur complement S =
/// M_BB − M_BI M_II⁻¹ M_IB is a cyclic tridiagonal R × R system (border r coupled to r ± 1 through
/// one chain each), which rank 0 solves with CyclicTridiagonal, and every rank then corrects its
/// chain by its spikes. With R = 1 this is CyclicTridiagonal's scheme with one border instead of
/// two. M is positive definite exactly when every chain pivot and every pivot of S is positive
/// (Haynsworth's inertia additivity), which is what positive_definite() reports.
///
/// Strict-FM invariance as CyclicTridiagonal's: with keep_constant_solutions(), a circulant M and a
/// constant right-hand side give the constant r / (shift − diag − 2 off) exactly.
///
/// Every rank holds its own copy of this object over the same arrays (on a device, the team's shared
/// memory): what rank 0 alone computes and the others read — the flags, the inverses, the borders'
/// values — lives in those arrays; only rank 0 touches the reduced factorisation.
template <class Team>
class TeamCyclicTridiagonal {
 public:
  static constexpr std::size_t storage_size(std::size_t n, std::size_t ranks) {
    return 7 * n + 6 * ranks + shared_count + CyclicTridiagonal<double>::storage_size(ranks < 2 ? 2 : ranks);
  }

  /// Over n rows and `ranks` ranks (at most n), its arrays from `arena`.
  ROTORSWEEP_HD TeamCyclicTridiagonal(std::size_t n, std::size_t ranks, LaneArena<double>& arena)
      : n_(n),
        ranks_(ranks),
        diag_(arena.take(n)),
        off_(arena.take(n)),
        inv_pivot_(arena.take(n)),
        upper_(arena.take(n)),
        lower_(arena.take(n)),
        spike_left_(arena.take(n)),
        spike_own_(arena.take(n)),
        left_diag_(arena.take(ranks)),
        own_diag_(arena.take(ranks)),
        across_(arena.take(ranks)),
        left_rhs_(arena.take(ranks)),
        own_rhs_(arena.take(ranks)),
        borders_(arena.take(ranks)),
        shared_(arena.take(shared_count)),
        reduced_(ranks < 2 ? 2 : ranks, arena) {}

  ROTORSWEEP_HD std::size_t size() const { return n_; }
  ROTORSWEEP_HD double& diag(std::size_t i) { return diag_[i]; }
  ROTORSWEEP_HD double& off(std::size_t k) { return off_[k]; }
  /// J's diagonal and links as arrays, for the ranks to fill their rows.
  ROTORSWEEP_HD double* diagonal() { return diag_; }
  ROTORSWEEP_HD double* links() { return off_; }

  ROTORSWEEP_HD bool positive_definite() const { return shared_[positive_definite_slot] != 0.0; }
  ROTORSWEEP_HD void keep_constant_solutions(bool keep) { keep_constant_ = keep; }

  /// Factorises M = shift·I − J for the following solve() calls (every rank, then rank 0).
  ROTORSWEEP_HD void factor(Team& team, double shift) {
    team.each([&](std::size_t r) { factor_block(r, shift); });
    const bool chains_positive = team.all([&](std::size_t r) { return chain_positive(r); });
    const bool circulant = keep_constant_ && team.all([&](std::size_t r) { return block_circulant(r); });
    team.one([&] {
      const bool borders_positive = factor_borders(shift);
      shared_[positive_definite_slot] = chains_positive && borders_positive ? 1.0 : 0.0;
      shared_[circulant_slot] = circulant ? 1.0 : 0.0;
      shared_[constant_inverse_slot] = 1.0 / (shift - diag_[0] - 2.0 * off_[0]);
    });
  }

  /// Solves M x = r in place (r becomes x), with M from the last factor().
  ROTORSWEEP_HD void solve(Team& team, double* r) {
    const double r0 = r[0];
    const bool constant = shared_[circulant_slot] != 0.0 && team.all([&](std::size_t k) {
      const TeamRows rows = team_rows(n_, ranks_, k);
      for (std::size_t i = rows.begin; i < rows.end; ++i)
        if (r[i] != r0) return false;
      return true;
    });
    if (constant) {
      const double x = r0 * shared_[constant_inverse_slot];
      team.each([&](std::size_t k) {
        const TeamRows rows = team_rows(n_, ranks_, k);
        for (std::size_t i = rows.begin; i < rows.end; ++i) r[i] = x;
      });
      return;
    }
    team.each([&](std::size_t k) { solve_chain(k, r); });
    team.one([&] { solve_borders(r); });
    team.each([&](std::size_t k) { correct_chain(k, r); });
  }

 private:
  /// Rank r's block: its chain [begin, border) and border.
  struct Block {
    std::size_t begin, border;
  };
  ROTORSWEEP_HD Block block(std::size_t r) const {
    const TeamRows rows = team_rows(n_, ranks_, r);
    return {rows.begin, rows.end - 1};
  }
  /// M's entry between the chain's first row and the previous border (link begin − 1), and between
  /// its last row and its own border (link border − 1).
  ROTORSWEEP_HD double left_coupling(const Block& b) const { return -off_[(b.begin + n_ - 1) % n_]; }
  ROTORSWEEP_HD double own_coupling(const Block& b) const { return -off_[b.border - 1]; }

  /// Rank r: the chain's LU, its spikes and its parts of S: left_diag (to S at the previous border),
  /// own_diag (at its own border) and across (between the two).
  ROTORSWEEP_HD void factor_block(std::size_t r, double shift) {
    const Block b = block(r);
    if (b.begin == b.border) {  // no chain: the borders are joined by their own link
      left_diag_[r] = own_diag_[r] = 0.0;
      across_[r] = left_coupling(b);
      return;
    }
    const std::size_t first = b.begin, last = b.border - 1;
    factor_tridiagonal_chain(shift, diag_, off_, first, b.border, inv_pivot_, upper_, lower_);
    const double c_left = left_coupling(b), c_own = own_coupling(b);
    tridiagonal_chain_spikes(first, b.border, inv_pivot_, upper_, lower_, c_left, c_own, spike_left_,
                             spike_own_);
    left_diag_[r] = c_left * spike_left_[first];
    own_diag_[r] = c_own * spike_own_[last];
    across_[r] = -c_left * spike_own_[first];
  }

  ROTORSWEEP_HD bool chain_positive(std::size_t r) const {
    const Block b = block(r);
    for (std::size_t i = b.begin; i < b.border; ++i)
      if (!(inv_pivot_[i] > 0.0)) return false;
    return true;
  }
  ROTORSWEEP_HD bool block_circulant(std::size_t r) const {
    const TeamRows rows = team_rows(n_, ranks_, r);
    for (std::size_t i = rows.begin; i < rows.end; ++i)
      if (diag_[i] != diag_[0] || off_[i] != off_[0]) return false;
    return true;
  }

  /// Rank 0: S from the chains' parts, factorised; returns whether it is positive definite. Border r
  /// is reduced row r; reduced link r couples borders r and r + 1 through chain r + 1.
  ROTORSWEEP_HD bool factor_borders(double shift) {
    const std::size_t R = ranks_;
    if (R == 1) {
      const double s = shift - diag_[n_ - 1] - left_diag_[0] - own_diag_[0] + 2.0 * across_[0];
      shared_[single_inverse_slot] = 1.0 / s;
      return s > 0.0;
    }
    for (std::size_t r = 0; r < R; ++r) {
      const std::size_t next = (r + 1) % R;
      const double s_diag = shift - diag_[block(r).border] - own_diag_[r] - left_diag_[next];
      reduced_.diag(r) = -s_diag;  // S = 0·I − J_reduced
      reduced_.off(r) = -across_[next];
    }
    reduced_.factor(0.0);
    return reduced_.positive_definite();
  }

  /// Rank k: z = T⁻¹ r on its chain, and the chain's parts of the borders' right-hand sides.
  ROTORSWEEP_HD void solve_chain(std::size_t k, double* r) {
    const Block b = block(k);
    if (b.begin == b.border) {
      left_rhs_[k] = own_rhs_[k] = 0.0;
      return;
    }
    const std::size_t first = b.begin, last = b.border - 1;
    solve_tridiagonal_chain(first, b.border, inv_pivot_, upper_, lower_, r);
    left_rhs_[k] = left_coupling(b) * r[first];
    own_rhs_[k] = own_coupling(b) * r[last];
  }

  /// Rank 0: the borders' values from S x_B = r_B − M_BI z.
  ROTORSWEEP_HD void solve_borders(double* r) {
    const std::size_t R = ranks_;
    if (R == 1) {
      const std::size_t m = n_ - 1;
      r[m] = (r[m] - left_rhs_[0] - own_rhs_[0]) * shared_[single_inverse_slot];
      return;
    }
    for (std::size_t k = 0; k < R; ++k) {
      const std::size_t border = block(k).border;
      borders_[k] = r[border] - own_rhs_[k] - left_rhs_[(k + 1) % R];
    }
    reduced_.solve(borders_);
    for (std::size_t k = 0; k < R; ++k) r[block(k).border] = borders_[k];
  }

  /// Rank k: its chain's rows x = z − spike_left x_{b−1} − spike_own x_b.
  ROTORSWEEP_HD void correct_chain(std::size_t k, double* r) const {
    const Block b = block(k);
    const double x_left = r[block((k + ranks_ - 1) % ranks_).border], x_own = r[b.border];
    for (std::size_t i = b.begin; i < b.border; ++i) r[i] -= spike_left_[i] * x_left + spike_own_[i] * x_own;
  }

  // the values rank 0 computes for all: slots of shared_
  static constexpr std::size_t positive_definite_slot = 0, circulant_slot = 1, constant_inverse_slot = 2,
                               single_inverse_slot = 3, shared_count = 4;

  std::size_t n_, ranks_;
  double *diag_, *off_;
  double *inv_pivot_, *upper_, *lower_;  ///< the chains' LU
  double *spike_left_,
      *spike_own_;  ///< per chain row: M_II⁻¹ times the previous border's, own border's column
  double *left_diag_, *own_diag_, *across_;  ///< per rank: its chain's parts of S
  double *left_rhs_, *own_rhs_;              ///< per rank: its chain's parts of M_BI z
  double* borders_;                          ///< the reduced right-hand side, then x_B
  double* shared_;                           ///< the slots above
  CyclicTridiagonal<double> reduced_;        ///< S (R >= 2), rank 0's
  bool keep_constant_ = false;
};

}  // namespace rotorsweep::kernels
