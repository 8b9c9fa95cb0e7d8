// The row profile of a member's periods on a team of threads (docs/model.md §3 "Row profiles",
// docs/architecture.md "Teams"): RowProfileIntegral's sums, each rank over its rows.
#pragma once

#include <cstddef>

#include "ensemble/rows/row_profile_integral.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/models/rows/row_models_on_teams.hpp"
#include "kernels/steppers/team_integrator.hpp"

namespace rotorsweep::ensemble {

/// RowProfileIntegral<Model, stochastic> of a row model on the double lane for one member on a team:
/// each step integrated by two-point Gauss–Legendre quadrature of the cubic Hermite interpolant (at
/// T > 0 the profile at each step's start), with the same values per row, so on the same path it
/// gives the same bits. The interpolant's nodes of every rank are in place before any rank evaluates the
/// profile there (its links read the next rank's first row), and so is every rank's trigonometry
/// where the model's range forms read it across ranks (kernels::team_trigonometry).
template <class Team, class Model, bool stochastic>
class TeamRowProfileIntegral {
 public:
  /// Takes its views for N = rows (none for rows = 0: switched off).
  ROTORSWEEP_HD TeamRowProfileIntegral(std::size_t rows, kernels::LaneArena<double>& arena)
      : n_(rows), work_(rows, arena), row_(rows, arena) {}

  /// The member starts at state s: its sums restart (and f there is the interpolant's first slope).
  ROTORSWEEP_HD void start(Team& team, const Model& model, const kernels::TeamMemberState& s) {
    links_ = model.links();
    if constexpr (!stochastic) kernels::team_trigonometry(team, model, work_, s.y, s.t);
    each_range(team, [&](std::size_t begin, std::size_t end) {
      for (std::size_t j = begin; j < end; ++j) row_.drive_sum[j] = row_.link_sum[j] = 0.0;
      if constexpr (!stochastic) model.evaluate_range(work_, s.y, s.t, row_.f_before, begin, end);
    });
  }

  ROTORSWEEP_HD void before_step(Team& team, const Model& model, const kernels::TeamMemberState& s) {
    t_before_ = s.t;
    if constexpr (stochastic) kernels::team_trigonometry(team, model, work_, s.y, s.t);
    each_range(team, [&](std::size_t begin, std::size_t end) {
      if constexpr (stochastic)
        model.row_profile_range(work_, s.y, s.t, row_.scratch, row_.drive_node, row_.link_node, begin, end);
      else
        for (std::size_t j = begin; j < end; ++j) row_.theta_before[j] = s.y[j];
    });
  }

  ROTORSWEEP_HD void after_step(Team& team, const Model& model, const kernels::TeamMemberState& s,
                                bool accepted) {
    const double h = accepted ? s.t - t_before_ : 0.0;
    if constexpr (stochastic) {
      each_range(team, [&](std::size_t begin, std::size_t end) {
        add(h, row_.drive_node, row_.link_node, begin, end);
      });
    } else {
      kernels::team_trigonometry(team, model, work_, s.y, s.t);
      each_range(team, [&](std::size_t begin, std::size_t end) {
        model.evaluate_range(work_, s.y, s.t, row_.f_now, begin, end);
      });
      add_node(team, model, 0.21132486540518711775, h, s.y);  // 1/2 − √3/6
      add_node(team, model, 0.78867513459481288225, h, s.y);  // 1/2 + √3/6
      each_range(team, [&](std::size_t begin, std::size_t end) {
        for (std::size_t j = begin; j < end; ++j)
          row_.f_before[j] = accepted ? row_.f_now[j] : row_.f_before[j];
      });
    }
  }

  /// The period just ended: writes its R_j (rows) then its link integrals (links: N periodic, N − 1
  /// open) to `out` and starts the next period's sums.
  ROTORSWEEP_HD void take_period(Team& team, double* out) {
    each_range(team, [&](std::size_t begin, std::size_t end) {
      for (std::size_t j = begin; j < end; ++j) {
        out[j] = row_.drive_sum[j];
        row_.drive_sum[j] = 0.0;
      }
      for (std::size_t j = begin; j < end && j < links_; ++j) {
        out[n_ + j] = row_.link_sum[j];
        row_.link_sum[j] = 0.0;
      }
    });
  }

 private:
  /// part(begin, end) over every rank's rows, one phase.
  template <class Part>
  ROTORSWEEP_HD void each_range(Team& team, Part&& part) const {
    team.each([&](std::size_t r) {
      const kernels::TeamRows rows = kernels::team_rows(n_, team.size(), r);
      part(rows.begin, rows.end);
    });
  }

  /// Adds half the step times the profile at θ(t0 + s h) of the cubic Hermite interpolant: the
  /// nodes of every row first, then the profile there.
  ROTORSWEEP_HD void add_node(Team& team, const Model& model, double s, double h, const double* theta_now) {
    const double r = 1.0 - s;
    const double start = (1.0 + 2.0 * s) * r * r, start_slope = s * r * r * h;
    const double end = s * s * (3.0 - 2.0 * s), end_slope = -(s * s * r) * h;
    each_range(team, [&](std::size_t begin, std::size_t stop) {
      for (std::size_t j = begin; j < stop; ++j)
        row_.theta_node[j] = start * row_.theta_before[j] + start_slope * row_.f_before[j] +
                             end * theta_now[j] + end_slope * row_.f_now[j];
    });
    kernels::team_trigonometry(team, model, work_, row_.theta_node, t_before_ + s * h);
    each_range(team, [&](std::size_t begin, std::size_t stop) {
      model.row_profile_range(work_, row_.theta_node, t_before_ + s * h, row_.scratch, row_.drive_node,
                              row_.link_node, begin, stop);
      add(0.5 * h, row_.drive_node, row_.link_node, begin, stop);
    });
  }

  ROTORSWEEP_HD void add(double weight, const double* drive, const double* link, std::size_t begin,
                         std::size_t end) {
    for (std::size_t j = begin; j < end; ++j) row_.drive_sum[j] += weight * drive[j];
    for (std::size_t j = begin; j < end && j < links_; ++j) row_.link_sum[j] += weight * link[j];
  }

  std::size_t n_, links_ = 0;
  typename Model::Workspace work_;
  RowProfileArrays<double> row_;  ///< the per-row arrays, each rank its rows
  double t_before_ = 0.0;
};

}  // namespace rotorsweep::ensemble
