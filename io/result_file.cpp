// Writing a sweep's results: column datasets with a description attribute each, NaN-padded
// period series, and the completion flag last (README "Output file").
#include "io/result_file.hpp"

#include <algorithm>
#include <limits>

namespace rotorsweep::io {

namespace {

using ensemble::MemberResult;
using ensemble::PeriodRecord;

template <class F>
std::vector<double> column(const std::vector<MemberResult>& results, F&& field) {
  std::vector<double> out;
  out.reserve(results.size());
  for (const auto& r : results) out.push_back(field(r));
  return out;
}

template <class F>
std::vector<std::int64_t> integer_column(const std::vector<MemberResult>& results, F&& field) {
  std::vector<std::int64_t> out;
  out.reserve(results.size());
  for (const auto& r : results) out.push_back(std::int64_t(field(r)));
  return out;
}

void write_period_series(const Hdf5Location& members, const ensemble::Scene& scene,
                         const std::vector<MemberResult>& results) {
  const auto periods = members.create_group("periods");
  std::size_t width = 0;
  for (const auto& r : results) width = std::max(width, r.periods.size());
  periods.set_attribute("fill", std::string("NaN beyond a member's periods_run"));
  const auto series = [&](const std::string& name, double PeriodRecord::*field,
                          const std::string& description) {
    std::vector<double> data(results.size() * width, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t m = 0; m < results.size(); ++m)
      for (std::size_t k = 0; k < results[m].periods.size(); ++k)
        data[m * width + k] = results[m].periods[k].*field;
    periods.write(name, data, {results.size(), width}, description + " (members × periods)");
  };
  if (scene.dissipation) series("dissipation", &PeriodRecord::dissipation, "R_k = A Σ∫ sin(θ_j - t) dt");
  if (scene.estimators) {
    series("dissipation_work", &PeriodRecord::work, "W_k = A Σ∫ sin(θ_j - t) θ̇_j dt");
    series("dissipation_stokes", &PeriodRecord::stokes, "S_k = g Σ∫ θ̇_j² dt");
  }
  if (scene.alignment) {
    series("alignment_mean", &PeriodRecord::alignment_mean, "period mean of ρ̄");
    series("alignment_min", &PeriodRecord::alignment_min, "min of ρ̄ at the period's step points");
    series("alignment_max", &PeriodRecord::alignment_max, "max of ρ̄ at the period's step points");
  }
  if (scene.energy) series("energy_mean", &PeriodRecord::energy_mean, "period mean of H");
  if (scene.slips) series("slips", &PeriodRecord::slips, "slip events begun in the period");
}

}  // namespace

ResultFile::ResultFile(const std::string& path, const ensemble::Scene& scene, const Provenance& provenance)
    : file_(Hdf5Location::create_file(path)) {
  file_.set_flag("complete", false);
  file_.set_attribute("scene", scene.text);
  file_.set_attribute("scene_path", provenance.scene_path);
  file_.set_attribute("version", provenance.version);
  file_.set_attribute("revision", provenance.revision);
  file_.flush();
}

void ResultFile::write_members(const ensemble::Scene& scene, const std::vector<ensemble::Member>& members,
                               const std::vector<MemberResult>& results) const {
  const auto group = file_.create_group("members");
  std::vector<double> A, g, rtol, atol;
  std::vector<std::int64_t> replica, rows;
  std::vector<std::string> ic, status, regime;
  for (std::size_t i = 0; i < members.size(); ++i) {
    A.push_back(members[i].A);
    g.push_back(members[i].g);
    replica.push_back(members[i].replica);
    rows.push_back(std::int64_t(members[i].rows));
    rtol.push_back(members[i].rtol);
    atol.push_back(members[i].atol);
    ic.emplace_back(ensemble::kind_name(members[i].kind));
    status.emplace_back(kernels::status_name(results[i].status));
    regime.emplace_back(ensemble::regime_name(results[i].regime));
  }
  group.write("A", A, {}, "substrate strength A");
  group.write("g", g, {}, "g = damping × drive speed");
  group.write("rows", rows, "N");
  group.write("rtol", rtol, {}, "relative tolerance");
  group.write("atol", atol, {}, "absolute tolerance");
  group.write("ic", ic, "initial condition kind: FM, AFM, random, exact");
  group.write("replica", replica, "replica index at this (A, g, ic)");
  const std::string averaged = " over the averaged periods; NaN when status is not ok";
  if (scene.dissipation) {
    group.write("dissipation", column(results, [](auto& r) { return r.dissipation; }), {},
                "D per period, R estimator A Σ∫ sin(θ_j - t) dt, mean" + averaged);
    group.write("dissipation_std", column(results, [](auto& r) { return r.dissipation_std; }), {},
                "population spread of D" + averaged);
  }
  if (scene.estimators) {
    group.write("dissipation_work", column(results, [](auto& r) { return r.dissipation_work; }), {},
                "D per period, work estimator W, mean" + averaged);
    group.write("dissipation_stokes", column(results, [](auto& r) { return r.dissipation_stokes; }), {},
                "D per period, Stokes estimator S, mean" + averaged);
  }
  if (scene.alignment) {
    group.write("alignment_mean", column(results, [](auto& r) { return r.alignment_mean; }), {},
                "time mean of ρ̄" + averaged);
    group.write("alignment_min", column(results, [](auto& r) { return r.alignment_min; }), {},
                "min of ρ̄ at step points" + averaged);
    group.write("alignment_max", column(results, [](auto& r) { return r.alignment_max; }), {},
                "max of ρ̄ at step points" + averaged);
  }
  if (scene.energy)
    group.write("energy_mean", column(results, [](auto& r) { return r.energy_mean; }), {},
                "time mean of H" + averaged);
  if (scene.slips)
    group.write("slips_per_period", column(results, [](auto& r) { return r.slips_per_period; }), {},
                "slip events per period" + averaged);
  if (scene.classifies_regimes())
    group.write("regime", regime, "FM, AFM, CP or unsettled (README: regime rule)");
  group.write("status", status, "ok, non_finite, step_underflow or step_budget");
  group.write("settled", integer_column(results, [](auto& r) { return r.settled; }),
              "1 when the schedule ended as planned (steady_tol reached, or fixed schedule)");
  group.write("periods_run", integer_column(results, [](auto& r) { return r.periods_run; }),
              "drive periods completed");
  group.write("steps_accepted", integer_column(results, [](auto& r) { return r.steps_accepted; }),
              "accepted steps");
  group.write("steps_rejected", integer_column(results, [](auto& r) { return r.steps_rejected; }),
              "rejected steps");
  const std::size_t width = scene.max_rows();
  const auto write_angles = [&](const std::string& name, const std::string& what, const auto& angles_of) {
    std::vector<double> theta(results.size() * width, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t m = 0; m < results.size(); ++m) {
      const std::vector<double>& angles = angles_of(m);
      std::copy(angles.begin(), angles.end(), theta.begin() + std::ptrdiff_t(m * width));
    }
    group.write(name, theta, {results.size(), width},
                what + " (members × largest N; NaN beyond a member's rows)");
  };
  write_angles("theta_initial", "θ_j at t = 0, as drawn from the member's stream",
               [&](std::size_t m) { return ensemble::member_initial_angles(scene, members[m]); });
  write_angles("theta_final", "θ_j at the end, in [0, 2π)",
               [&](std::size_t m) -> const std::vector<double>& { return results[m].theta_final; });
  if (scene.period_series) write_period_series(group, scene, results);
}

void ResultFile::write_curves(const ensemble::Scene& scene,
                              const std::vector<ensemble::CurvePoint>& curves) const {
  const auto group = file_.create_group("curves");
  const auto values = [&](auto&& field) {
    std::vector<double> out;
    for (const auto& p : curves) out.push_back(field(p));
    return out;
  };
  std::vector<std::string> ic;
  std::vector<std::int64_t> members, count, rows;
  for (const auto& p : curves) {
    rows.push_back(std::int64_t(p.rows));
    ic.emplace_back(ensemble::kind_name(p.kind));
    members.push_back(std::int64_t(p.members));
    count.push_back(std::int64_t(p.count));
  }
  group.write("rows", rows, "N");
  group.write("rtol", values([](auto& p) { return p.rtol; }), {}, "relative tolerance");
  group.write("A", values([](auto& p) { return p.A; }), {}, "substrate strength A");
  group.write("g", values([](auto& p) { return p.g; }), {}, "g = damping × drive speed");
  group.write("ic", ic, "initial condition kind");
  group.write("members", members, "replicas at this point");
  group.write("count", count, "members with status ok (the statistics use these)");
  if (scene.dissipation) {
    group.write("dissipation_mean", values([](auto& p) { return p.dissipation_mean; }), {}, "mean of D");
    group.write("dissipation_std", values([](auto& p) { return p.dissipation_std; }), {},
                "population spread of D over replicas");
    group.write("dissipation_min", values([](auto& p) { return p.dissipation_min; }), {}, "smallest D");
    group.write("dissipation_max", values([](auto& p) { return p.dissipation_max; }), {}, "largest D");
  }
  if (scene.classifies_regimes())
    for (auto regime : ensemble::all_regimes) {
      const std::string name(ensemble::regime_name(regime));
      group.write("fraction_" + name, values([&](auto& p) { return p.regime_fraction[std::size_t(regime)]; }),
                  {}, "fraction of the point's members in regime " + name);
    }
}

void ResultFile::finish(const ensemble::SweepStatistics& statistics) const {
  file_.set_attribute("wall_seconds", statistics.wall_seconds);
  file_.set_attribute("threads", std::int64_t(statistics.threads));
  file_.set_attribute("lane_width", std::int64_t(statistics.lane_width));
  file_.set_attribute("lane_occupancy", statistics.occupancy());
  file_.flush();
  file_.set_flag("complete", true);
  file_.flush();
}

}  // namespace rotorsweep::io
