// Writing a sweep's results: column datasets with a description attribute each, NaN-padded
// period series, and the completion flag last (README "Output file").
#include "io/result_file.hpp"

#include <algorithm>
#include <limits>
#include <set>

#include "ensemble/wilson_interval.hpp"

namespace rotorsweep::io {

namespace {

using ensemble::MemberResult;

void write_final_states(const Hdf5Location& group, const std::vector<MemberResult>& results);

template <class T, class F>
std::vector<double> column(const std::vector<T>& rows, F&& field) {
  std::vector<double> out;
  out.reserve(rows.size());
  for (const auto& r : rows) out.push_back(field(r));
  return out;
}

template <class F>
std::vector<std::int64_t> integer_column(const std::vector<MemberResult>& results, F&& field) {
  std::vector<std::int64_t> out;
  out.reserve(results.size());
  for (const auto& r : results) out.push_back(std::int64_t(field(r)));
  return out;
}

/// Calls f(channel declaration) for every channel of the observables the scene asks for.
template <class F>
void for_each_channel(const ensemble::Scene& scene, F&& f) {
  for (std::size_t i = 0; i < ensemble::observable_count; ++i) {
    if (!scene.has(ensemble::Observable(i))) continue;
    const auto& observable = ensemble::observables[i];
    for (std::size_t c = 0; c < observable.channel_count; ++c) f(observable.channels[c]);
  }
}

void write_period_series(const Hdf5Location& members, const ensemble::Scene& scene,
                         const std::vector<MemberResult>& results) {
  const auto periods = members.create_group("periods");
  std::size_t width = 0;
  for (const auto& r : results) width = std::max(width, r.periods.size());
  periods.set_attribute("fill", std::string("NaN beyond a member's periods_run"));
  for_each_channel(scene, [&](const ensemble::ChannelDeclaration& channel) {
    std::vector<double> data(results.size() * width, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t m = 0; m < results.size(); ++m)
      for (std::size_t k = 0; k < results[m].periods.size(); ++k)
        data[m * width + k] = results[m].periods[k][channel.channel];
    periods.write(std::string(channel.column), data, {results.size(), width},
                  std::string(channel.description) + " (members × periods)");
  });
}

}  // namespace

ResultFile::ResultFile(const std::string& path, const ensemble::Scene& scene, const Provenance& provenance)
    : ResultFile(Hdf5Location::create_file(path), scene, provenance) {}

ResultFile ResultFile::in_memory(const ensemble::Scene& scene, const Provenance& provenance) {
  return ResultFile(Hdf5Location::create_in_memory(provenance.scene_path + ".h5"), scene, provenance);
}

ResultFile::ResultFile(Hdf5Location file, const ensemble::Scene& scene, const Provenance& provenance)
    : file_(std::move(file)) {
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
  group.write("noise", column(members, [](const ensemble::Member& m) { return m.noise; }), {},
              "η: FM/AFM starts draw θ_j - θ0 - (π for odd rows in AFM) from U[-η, η]");
  group.write("offset", column(members, [](const ensemble::Member& m) { return m.offset; }), {},
              "θ0 added to FM/AFM starts");
  group.write("replica", replica, "replica index at this (A, g, ic)");
  const std::string averaged = " over the averaged periods; NaN when status is not ok";
  for_each_channel(scene, [&](const ensemble::ChannelDeclaration& channel) {
    for (std::size_t k = 0; k < channel.summary_count; ++k) {
      const auto& summary = channel.summaries[k];
      group.write(
          std::string(summary.column),
          column(results, [&](const MemberResult& r) { return r.summary(summary.summary, channel.channel); }),
          {}, std::string(summary.description) + averaged);
    }
  });
  if (scene.classifies_regimes())
    group.write("regime", regime, "FM, AFM, CP or unsettled (README: regime rule)");
  group.write("status", status, "ok, non_finite, step_underflow or step_budget");
  if (scene.has(ensemble::Observable::dissipation))
    group.write("dissipation_resolved",
                integer_column(results, [](auto& r) { return r.dissipation_resolved(); }),
                "1 when D is resolved: status ok and dissipation_error < 0.1 |D|");
  group.write("settled", integer_column(results, [](auto& r) { return r.settled; }),
              "1 when the schedule ended as planned (steady_tol reached, or fixed schedule)");
  group.write("periods_run", integer_column(results, [](auto& r) { return r.periods_run; }),
              "drive periods completed");
  group.write("steps_accepted", integer_column(results, [](auto& r) { return r.steps_accepted; }),
              "accepted steps");
  group.write("steps_rejected", integer_column(results, [](auto& r) { return r.steps_rejected; }),
              "rejected steps");
  const std::size_t width = scene.max_rows();
  const auto write_rows = [&](const std::string& name, const std::string& what, const auto& angles_of) {
    std::vector<double> theta(results.size() * width, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t m = 0; m < results.size(); ++m) {
      const std::vector<double>& angles = angles_of(m);
      std::copy(angles.begin(), angles.end(), theta.begin() + std::ptrdiff_t(m * width));
    }
    group.write(name, theta, {results.size(), width},
                what + " (members × largest N; NaN beyond a member's rows)");
  };
  write_rows("theta_initial", "θ_j at t = 0, as drawn from the member's stream",
             [&](std::size_t m) { return ensemble::member_initial_angles(scene, members[m]); });
  write_rows("theta_final", "θ_j at the end, in [0, 2π)",
             [&](std::size_t m) -> const std::vector<double>& { return results[m].theta_final; });
  const auto& disorder = scene.disorder;
  const auto deviations = [&](std::size_t m) {
    return ensemble::row_deviations(disorder, members[m].rows, members[m].replica);
  };
  if (disorder.A > 0 || !disorder.A_rows.empty())
    write_rows("disorder_A", "δ_j: row j's substrate strength is A (1 + δ_j)",
               [&](std::size_t m) { return deviations(m).A; });
  if (disorder.anisotropy > 0 || !disorder.anisotropy_rows.empty())
    write_rows("disorder_anisotropy", "α_j: row j's anisotropy is (3/2)(1 + α_j)",
               [&](std::size_t m) { return deviations(m).anisotropy; });
  if (disorder.coupling > 0 || !disorder.coupling_rows.empty())
    write_rows("disorder_coupling", "β_j: the coupling of rows j and j+1 is 1 + β_j",
               [&](std::size_t m) { return deviations(m).coupling; });
  write_final_states(group, results);
  if (scene.period_series) write_period_series(group, scene, results);
}

namespace {

/// The final-state classification of every member (docs/model.md §3, "Final states").
void write_final_states(const Hdf5Location& group, const std::vector<MemberResult>& results) {
  const auto state = [&](auto&& field) {
    return column(results, [&](const MemberResult& r) { return double(field(r.final_state)); });
  };
  group.write("sublattice_deviation", state([](auto& f) { return f.sublattice_deviation; }), {},
              "largest distance (rad) of a row from its sublattice's circular mean at the last period ends");
  group.write("domain_walls", integer_column(results, [](auto& r) { return r.final_state.domain_walls; }),
              "domain walls: sign changes of cos(θ_j - θ_{j+1}) around the ring, halved");
  group.write("detached_rows", integer_column(results, [](auto& r) { return r.final_state.detached_rows; }),
              "rows farther than π/4 from the mean of the rest of their sublattice at the last period end");
  group.write("orbit_period", integer_column(results, [](auto& r) { return r.final_state.orbit_period; }),
              "periods after which the state repeats (1..3; 0: not within 3)");
  group.write("angle_groups", integer_column(results, [](auto& r) { return r.final_state.angle_groups; }),
              "clusters of the final angles on the circle (split at gaps > 0.1 rad)");
  group.write("stray_rows", integer_column(results, [](auto& r) { return r.final_state.stray_rows; }),
              "rows outside the two largest clusters of final angles");
  std::vector<double> angles;
  for (const auto& r : results) {
    angles.push_back(r.final_state.sublattice_even);
    angles.push_back(r.final_state.sublattice_odd);
  }
  group.write("sublattice_angles", angles, {results.size(), 2},
              "circular means of the even and odd rows at the last period end, in [0, 2π)");
  std::vector<std::string> labels;
  for (const auto& r : results) labels.push_back(r.final_state.attractor);
  group.write("attractor", labels, "<regime>:<structure>:p<period>, or failed (docs/model.md §3)");
}

/// /curves/attractors: every attractor label of the sweep, and per point and label the count, the
/// fraction and its Wilson 95 % interval (points × labels).
void write_attractors(const Hdf5Location& curves_group, const std::vector<ensemble::CurvePoint>& curves) {
  std::set<std::string> label_set;
  for (const auto& p : curves)
    for (const auto& [label, count] : p.attractor_count) label_set.insert(label);
  const std::vector<std::string> labels(label_set.begin(), label_set.end());
  std::vector<std::int64_t> count;
  std::vector<double> fraction, low, high;
  for (const auto& p : curves)
    for (const auto& label : labels) {
      const auto it = p.attractor_count.find(label);
      const std::size_t k = it == p.attractor_count.end() ? 0 : it->second;
      const auto interval = ensemble::wilson_interval(k, p.members);
      count.push_back(std::int64_t(k));
      fraction.push_back(double(k) / double(p.members));
      low.push_back(interval.low);
      high.push_back(interval.high);
    }
  const auto group = curves_group.create_group("attractors");
  const std::vector<hsize_t> dims{curves.size(), labels.size()};
  group.write("labels", labels, "attractor labels <regime>:<structure>:p<period> (docs/model.md §3)");
  group.write("count", count, dims, "members of the point (row) with the label (column)");
  group.write("fraction", fraction, dims, "count / members of the point");
  group.write("low", low, dims, "Wilson 95 % interval of fraction: lower end");
  group.write("high", high, dims, "Wilson 95 % interval of fraction: upper end");
}

}  // namespace

void ResultFile::write_curves(const ensemble::Scene& scene,
                              const std::vector<ensemble::CurvePoint>& curves) const {
  const auto group = file_.create_group("curves");
  const auto values = [&](auto&& field) {
    std::vector<double> out;
    for (const auto& p : curves) out.push_back(field(p));
    return out;
  };
  std::vector<std::string> ic;
  std::vector<std::int64_t> members, count, unresolved, rows;
  for (const auto& p : curves) {
    rows.push_back(std::int64_t(p.rows));
    ic.emplace_back(ensemble::kind_name(p.kind));
    members.push_back(std::int64_t(p.members));
    count.push_back(std::int64_t(p.count));
    unresolved.push_back(std::int64_t(p.unresolved));
  }
  group.write("rows", rows, "N");
  group.write("rtol", values([](auto& p) { return p.rtol; }), {}, "relative tolerance");
  group.write("A", values([](auto& p) { return p.A; }), {}, "substrate strength A");
  group.write("g", values([](auto& p) { return p.g; }), {}, "g = damping × drive speed");
  group.write("ic", ic, "initial condition kind");
  group.write("noise", values([](auto& p) { return p.noise; }), {}, "η of the point's FM/AFM starts");
  group.write("offset", values([](auto& p) { return p.offset; }), {}, "θ0 of the point's FM/AFM starts");
  group.write("members", members, "replicas at this point");
  group.write("count", count, "members with status ok (the statistics use these)");
  if (scene.has(ensemble::Observable::dissipation)) {
    group.write("dissipation_mean", values([](auto& p) { return p.dissipation_mean; }), {}, "mean of D");
    group.write("dissipation_std", values([](auto& p) { return p.dissipation_std; }), {},
                "population spread of D over replicas");
    group.write("dissipation_min", values([](auto& p) { return p.dissipation_min; }), {}, "smallest D");
    group.write("dissipation_max", values([](auto& p) { return p.dissipation_max; }), {}, "largest D");
    group.write("dissipation_sem", values([](auto& p) { return p.dissipation_sem; }), {},
                "standard error of dissipation_mean over the replicas (sample spread / √count; NaN for one)");
    group.write("unresolved", unresolved, "members of count whose D is not resolved (dissipation_resolved)");
  }
  // basin fractions over all members of a point, with Wilson 95 % intervals
  const auto write_fraction = [&](const std::string& name, const std::string& what, const auto& count_of) {
    const auto fraction = [&](auto&& pick) {
      return values([&](const ensemble::CurvePoint& p) {
        const auto interval = ensemble::wilson_interval(count_of(p), p.members);
        return pick(double(count_of(p)) / double(p.members), interval);
      });
    };
    group.write("fraction_" + name, fraction([](double f, auto) { return f; }), {},
                "fraction of the point's members " + what);
    group.write("fraction_" + name + "_low", fraction([](double, auto i) { return i.low; }), {},
                "Wilson 95 % interval of fraction_" + name + ": lower end");
    group.write("fraction_" + name + "_high", fraction([](double, auto i) { return i.high; }), {},
                "Wilson 95 % interval of fraction_" + name + ": upper end");
  };
  if (scene.classifies_regimes())
    for (auto regime : ensemble::all_regimes) {
      const std::string name(ensemble::regime_name(regime));
      write_fraction(name, "that finished in regime " + name,
                     [&](const ensemble::CurvePoint& p) { return p.regime_count[std::size_t(regime)]; });
    }
  write_fraction("failed", "that failed (status not ok)",
                 [](const ensemble::CurvePoint& p) { return p.failed; });
  write_attractors(group, curves);
}

void ResultFile::write_sweep(const ensemble::Scene& scene, const std::vector<ensemble::Member>& members,
                             const ensemble::SweepOutcome& outcome) const {
  write_members(scene, members, outcome.results);
  write_curves(scene, ensemble::aggregate_curves(members, outcome.results, scene.replicas));
  finish(outcome.statistics);
}

void ResultFile::write_part(const ensemble::Scene& scene, const std::vector<ensemble::Member>& members,
                            const std::vector<MemberResult>& results) const {
  write_members(scene, members, results);
  std::vector<std::int64_t> index;
  for (const auto& m : members) index.push_back(std::int64_t(m.index));
  file_.open_group("members").write("plan_index", index,
                                    "the member's index in the whole plan (shard and partial files only)");
}

void ResultFile::write_shard(const ensemble::Scene& scene, const std::vector<ensemble::Member>& members,
                             const ensemble::SweepOutcome& outcome, const ShardLabel& shard) const {
  file_.set_attribute("shard_index", std::int64_t(shard.index));
  file_.set_attribute("shard_count", std::int64_t(shard.count));
  file_.set_attribute("plan_members", std::int64_t(shard.plan_members));
  write_part(scene, members, outcome.results);
  finish(outcome.statistics);
}

void ResultFile::write_partial(const ensemble::Scene& scene, const std::vector<ensemble::Member>& members,
                               const std::vector<MemberResult>& results, std::size_t plan_members,
                               const ensemble::SweepStatistics& statistics) const {
  file_.set_attribute("members_done", std::int64_t(members.size()));
  file_.set_attribute("plan_members", std::int64_t(plan_members));
  write_part(scene, members, results);
  write_statistics(statistics);
  file_.flush();
}

void ResultFile::write_statistics(const ensemble::SweepStatistics& statistics) const {
  file_.set_attribute("wall_seconds", statistics.wall_seconds);
  file_.set_attribute("threads", std::int64_t(statistics.threads));
  file_.set_attribute("lane_width", std::int64_t(statistics.lane_width));
  file_.set_attribute("lane_occupancy", statistics.occupancy());
}

void ResultFile::finish(const ensemble::SweepStatistics& statistics) const {
  write_statistics(statistics);
  file_.flush();
  file_.set_flag("complete", true);
  file_.flush();
}

}  // namespace rotorsweep::io
