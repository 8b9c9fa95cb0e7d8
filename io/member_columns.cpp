// The /members column list: plan axes, observable summaries, schedule counters, angles, disorder,
// final-state classification (docs/model.md §3) and period series, and their row-wise writing.
#include "io/member_columns.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "ensemble/rows/disorder.hpp"
#include "ensemble/rows/initial_conditions.hpp"
#include "ensemble/rows/shadow_run.hpp"
#include "ensemble/rows/symmetry_probe.hpp"

namespace rotorsweep::io {

namespace {

using ensemble::Member;
using ensemble::MemberResult;

/// A constant in a description, as printf's %g writes it.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::size_t longest(std::initializer_list<std::string_view> names) {
  std::size_t n = 0;
  for (auto name : names) n = std::max(n, name.size());
  return n;
}

/// "<regime>:<structure>:p<period>": the longest regime, "detached" + the row count, one digit.
std::size_t attractor_length(const ensemble::Scene& scene) {
  std::size_t regime = 0;
  for (auto r : ensemble::all_regimes) regime = std::max(regime, ensemble::regime_name(r).size());
  return regime + std::string(":detached").size() + std::to_string(scene.max_rows()).size() +
         std::string(":p0").size();
}

template <class F>
void for_each_channel(const ensemble::Scene& scene, F&& f) {
  for (std::size_t i = 0; i < ensemble::observable_count; ++i) {
    if (!scene.has(ensemble::Observable(i))) continue;
    const auto& observable = ensemble::observables[i];
    for (std::size_t c = 0; c < observable.channel_count; ++c) f(observable.channels[c]);
  }
}

void add_plan_axes(std::vector<MemberColumn>& columns) {
  columns.push_back(
      MemberColumn::real_valued("A", "substrate strength A", [](auto& m, auto&) { return m.A; }));
  columns.push_back(
      MemberColumn::real_valued("g", "g = damping × drive speed", [](auto& m, auto&) { return m.g; }));
  columns.push_back(
      MemberColumn::integer_valued("rows", "N", [](auto& m, auto&) { return std::int64_t(m.rows); }));
  columns.push_back(
      MemberColumn::real_valued("rtol", "relative tolerance", [](auto& m, auto&) { return m.rtol; }));
  columns.push_back(
      MemberColumn::real_valued("atol", "absolute tolerance", [](auto& m, auto&) { return m.atol; }));
  columns.push_back(MemberColumn::text_valued(
      "ic", longest({"FM", "AFM", "random", "exact"}), "initial condition kind: FM, AFM, random, exact",
      [](auto& m, auto&) { return std::string(ensemble::kind_name(m.kind)); }));
  columns.push_back(MemberColumn::real_valued(
                        "noise", "η: FM/AFM starts draw θ_j - θ0 - (π for odd rows in AFM) from U[-η, η]",
                        [](auto& m, auto&) { return m.noise; })
                        .in_units("rad"));
  columns.push_back(MemberColumn::real_valued("offset", "θ0 added to FM/AFM starts", [](auto& m, auto&) {
                      return m.offset;
                    }).in_units("rad"));
  columns.push_back(MemberColumn::integer_valued("replica", "replica index at this (A, g, ic)",
                                                 [](auto& m, auto&) { return std::int64_t(m.replica); }));
}

void add_outcome(std::vector<MemberColumn>& columns, const ensemble::Scene& scene) {
  const std::string averaged = " over the averaged periods; NaN when status is not ok";
  for_each_channel(scene, [&](const ensemble::ChannelDeclaration& channel) {
    for (std::size_t k = 0; k < channel.summary_count; ++k) {
      const auto& summary = channel.summaries[k];
      columns.push_back(MemberColumn::real_valued(std::string(summary.column),
                                                  std::string(summary.description) + averaged,
                                                  [summary, channel](auto&, const MemberResult& r) {
                                                    return r.summary(summary.summary, channel.channel);
                                                  }));
    }
  });
  if (scene.classifies_regimes())
    columns.push_back(MemberColumn::text_valued(
        "regime", longest({"FM", "AFM", "CP", "SA", "DW", "unsettled"}),
        scene.slip_kinds
            ? "FM, AFM, CP, DW (slipping across domain walls), SA (smooth alternation) or unsettled (docs/regimes.md: "
              "regime rule)"
            : "FM, AFM, CP, DW (slipping across domain walls) or unsettled (docs/regimes.md: regime rule)",
        [](auto&, auto& r) { return std::string(ensemble::regime_name(r.regime)); }));
  if (scene.slip_kinds) {
    columns.push_back(MemberColumn::real_valued("slip_jumps",
                                                "slips per averaged period whose energy at g/10 keeps more "
                                                "than a quarter of it (jumps; NaN: no rerun, "
                                                "the member did not slip every period)",
                                                [](auto&, auto& r) { return r.slip_jumps; }));
    columns.push_back(MemberColumn::real_valued("slip_smooth",
                                                "slips per averaged period whose energy at g/10 falls below "
                                                "a quarter of it (smooth slips; slips whose "
                                                "period's count differs at g/10 are neither)",
                                                [](auto&, auto& r) { return r.slip_smooth; }));
  }
  columns.push_back(
      MemberColumn::text_valued("status", longest({"ok", "non_finite", "step_underflow", "step_budget"}),
                                "ok, non_finite, step_underflow or step_budget",
                                [](auto&, auto& r) { return std::string(kernels::status_name(r.status)); }));
  if (scene.has(ensemble::Observable::dissipation))
    columns.push_back(MemberColumn::integer_valued(
        "dissipation_resolved",
        "1 when dissipation_error is a bound one can quote and below 0.1 |D|: status ok, not "
        "symmetry_limited, no shadow_departed",
        [](auto&, auto& r) { return std::int64_t(r.dissipation_resolved()); }));
  if (scene.runs_shadows()) {
    columns.push_back(MemberColumn::real_valued(
        "dissipation_shadow",
        "D of the member's averaged periods run again at tolerances × " +
            number(ensemble::shadow_tolerance_scale) +
            " where they slip (NaN: not run); dissipation_error ≥ " + number(ensemble::shadow_safety) +
            " |D − dissipation_shadow| / " + number(1 - ensemble::shadow_tolerance_scale) +
            " (docs/numerics.md \"The global error of D\")",
        [](auto&, auto& r) { return r.dissipation_shadow; }));
    columns.push_back(MemberColumn::real_valued(
        "dissipation_probe",
        "D of the member's symmetry probe: its averaged periods again with A_j = A (1 + " +
            number(ensemble::probe_asymmetry_scale) + " rtol ξ_j), run where "
        "no disorder or temperature of the scene exceeds rtol and the member slips or ends on a symmetric "
        "set (NaN: not run; docs/numerics.md \"Symmetry-limited members\")",
        [](auto&, auto& r) { return r.dissipation_probe; }));
    columns.push_back(MemberColumn::integer_valued(
        "symmetry_limited",
        "1 when an asymmetry of the rows below rtol decides D: the symmetry probe reached another attractor, "
        "or the member slips and the probe moved D by more than dissipation_error (docs/numerics.md "
        "\"Symmetry-limited members\")",
        [](auto&, auto& r) { return std::int64_t(r.symmetry_limited); }));
    columns.push_back(MemberColumn::integer_valued(
        "symmetry_held",
        "1 when the member is symmetry_limited without slipping: held on a symmetric set (strict FM, a "
        "commensurate pattern, a mirror-symmetric state) that an asymmetry at rtol leaves",
        [](auto&, auto& r) { return std::int64_t(r.symmetry_held); }));
    columns.push_back(MemberColumn::integer_valued(
        "shadow_departed",
        "1 when the shadow run reached another attractor than the member (another regime, slips per "
        "period, domain walls or detached rows): it estimates no error, dissipation_error is infinite "
        "(docs/numerics.md \"The global error of D\")",
        [](auto&, auto& r) { return std::int64_t(r.shadow_departed); }));
  }
  columns.push_back(MemberColumn::integer_valued(
      "settled", "1 when the schedule ended as planned (steady_tol reached, or fixed schedule)",
      [](auto&, auto& r) { return std::int64_t(r.settled); }));
  columns.push_back(MemberColumn::integer_valued("periods_run", "drive periods completed",
                                                 [](auto&, auto& r) { return std::int64_t(r.periods_run); }));
  columns.push_back(MemberColumn::integer_valued(
      "steps_accepted", "accepted steps", [](auto&, auto& r) { return std::int64_t(r.steps_accepted); }));
  columns.push_back(MemberColumn::integer_valued(
      "steps_rejected", "rejected steps", [](auto&, auto& r) { return std::int64_t(r.steps_rejected); }));
}

void add_angles_and_disorder(std::vector<MemberColumn>& columns, const ensemble::Scene& scene) {
  const hsize_t width = scene.max_rows();
  const std::string rows = " (members × largest N; NaN beyond a member's rows)";
  columns.push_back(MemberColumn::vector_valued(
                        "theta_initial", width, "θ_j at t = 0, as drawn from the member's stream" + rows,
                        [scene](const Member& m, auto&) { return ensemble::member_initial_angles(scene, m); })
                        .in_units("rad"));
  columns.push_back(MemberColumn::vector_valued("theta_final", width, "θ_j at the end, in [0, 2π)" + rows,
                                                [](auto&, const MemberResult& r) { return r.theta_final; })
                        .in_units("rad"));
  const auto& disorder = scene.disorder;
  const auto deviations = [disorder](const Member& m) {
    return ensemble::row_deviations(disorder, m.rows, m.replica);
  };
  if (disorder.A > 0 || !disorder.A_rows.empty())
    columns.push_back(MemberColumn::vector_valued(
        "disorder_A", width, "δ_j: row j's substrate strength is A (1 + δ_j)" + rows,
        [deviations](const Member& m, auto&) { return deviations(m).A; }));
  if (disorder.anisotropy > 0 || !disorder.anisotropy_rows.empty())
    columns.push_back(MemberColumn::vector_valued(
        "disorder_anisotropy", width, "α_j: row j's anisotropy is (3/2)(1 + α_j)" + rows,
        [deviations](const Member& m, auto&) { return deviations(m).anisotropy; }));
  if (disorder.coupling > 0 || !disorder.coupling_rows.empty())
    columns.push_back(MemberColumn::vector_valued(
        "disorder_coupling", width, "β_j: the coupling of rows j and j+1 is 1 + β_j" + rows,
        [deviations](const Member& m, auto&) { return deviations(m).coupling; }));
}

/// R_j per row and the alignment per link (docs/model.md §3, "Row profiles").
void add_row_profiles(std::vector<MemberColumn>& columns, const ensemble::Scene& scene) {
  const hsize_t width = scene.max_rows();
  const std::string averaged =
      ", mean over the averaged periods (members × largest N; NaN beyond a member's ";
  columns.push_back(
      MemberColumn::vector_valued("row_dissipation", width,
                                  "D_j = A_j ∫ sin(θ_j - t) dt per period, row j's share of D" + averaged +
                                      "rows, or when status is not ok)",
                                  [](auto&, const MemberResult& r) { return r.row_dissipation; }));
  columns.push_back(MemberColumn::vector_valued(
      "link_alignment", width,
      "time mean of cos²((θ_j - θ_{j+1})/2) on link j (N links periodic, N - 1 open)" + averaged +
          "links, or when status is not ok)",
      [](auto&, const MemberResult& r) { return r.link_alignment; }));
}

/// The final-state classification of every member (docs/model.md §3, "Final states").
void add_final_state(std::vector<MemberColumn>& columns, const ensemble::Scene& scene) {
  columns.push_back(MemberColumn::real_valued(
                        "sublattice_deviation",
                        "largest distance (rad) of a row from its sublattice's circular mean at the last "
                        "period ends",
                        [](auto&, auto& r) { return r.final_state.sublattice_deviation; })
                        .in_units("rad"));
  columns.push_back(MemberColumn::integer_valued(
      "domain_walls", "domain walls: sign changes of cos(θ_j - θ_{j+1}) around the ring, halved",
      [](auto&, auto& r) { return std::int64_t(r.final_state.domain_walls); }));
  columns.push_back(MemberColumn::integer_valued(
      "detached_rows",
      "rows farther than π/4 from the mean of the rest of their sublattice at the last "
      "period end",
      [](auto&, auto& r) { return std::int64_t(r.final_state.detached_rows); }));
  columns.push_back(MemberColumn::integer_valued(
      "orbit_period", "periods after which the state repeats (1..3; 0: not within 3)",
      [](auto&, auto& r) { return std::int64_t(r.final_state.orbit_period); }));
  columns.push_back(MemberColumn::integer_valued(
      "angle_groups", "clusters of the final angles on the circle (split at gaps > 0.1 rad)",
      [](auto&, auto& r) { return std::int64_t(r.final_state.angle_groups); }));
  columns.push_back(
      MemberColumn::integer_valued("stray_rows", "rows outside the two largest clusters of final angles",
                                   [](auto&, auto& r) { return std::int64_t(r.final_state.stray_rows); }));
  columns.push_back(
      MemberColumn::vector_valued(
          "sublattice_angles", 2,
          "circular means of the even and odd rows at the last period end, in [0, 2π)",
          [](auto&, auto& r) {
            return std::vector<double>{r.final_state.sublattice_even, r.final_state.sublattice_odd};
          })
          .in_units("rad"));
  columns.push_back(MemberColumn::text_valued("attractor", attractor_length(scene),
                                              "<regime>:<structure>:p<period>, or failed (docs/model.md §3)",
                                              [](auto&, auto& r) { return r.final_state.attractor; }));
}

void add_period_series(std::vector<MemberColumn>& columns, const ensemble::Scene& scene) {
  const hsize_t width = period_series_width(scene);
  for_each_channel(scene, [&](const ensemble::ChannelDeclaration& channel) {
    columns.push_back(MemberColumn::vector_valued("periods/" + std::string(channel.column), width,
                                                  std::string(channel.description) + " (members × periods)",
                                                  [channel](auto&, const MemberResult& r) {
                                                    std::vector<double> values;
                                                    for (const auto& record : r.periods)
                                                      values.push_back(record[channel.channel]);
                                                    return values;
                                                  }));
  });
}

}  // namespace

std::size_t period_series_width(const ensemble::Scene& scene) {
  const int periods = scene.steady_tol > 0 ? scene.max_periods : scene.relax_periods + scene.average_periods;
  return std::size_t(std::max(periods, 1));
}

std::vector<MemberColumn> member_columns(const ensemble::Scene& scene) {
  std::vector<MemberColumn> columns;
  add_plan_axes(columns);
  add_outcome(columns, scene);
  add_angles_and_disorder(columns, scene);
  if (scene.row_profiles) add_row_profiles(columns, scene);
  add_final_state(columns, scene);
  if (scene.period_series) add_period_series(columns, scene);
  return columns;
}

double member_row_bytes(const std::vector<MemberColumn>& columns) {
  return 1 + table_row_bytes(columns);  // and the done flag
}

void create_member_columns(const Hdf5Location& members, const std::vector<MemberColumn>& columns,
                           hsize_t rows) {
  if (std::any_of(columns.begin(), columns.end(),
                  [](const MemberColumn& c) { return c.name.starts_with("periods/"); }))
    members.create_group("periods").set_attribute("fill", std::string("NaN beyond a member's periods_run"));
  create_table_columns(members, columns, rows);
}

}  // namespace rotorsweep::io
