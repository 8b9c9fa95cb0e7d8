// Reading /members back a block of rows at a time: plan indices, statuses and regimes by name,
// every declared summary column, the schedule counters, final angles and states, period series.
#include "io/result_reader.hpp"

#include <optional>
#include <stdexcept>
#include <string>

namespace rotorsweep::io {

namespace {

using ensemble::MemberResult;

kernels::LaneStatus status_from(const std::string& name) {
  for (auto s : {kernels::LaneStatus::ok, kernels::LaneStatus::non_finite,
                 kernels::LaneStatus::step_underflow, kernels::LaneStatus::step_budget})
    if (kernels::status_name(s) == name) return s;
  throw std::runtime_error("unknown status '" + name + "' in /members/status");
}

ensemble::Regime regime_from(const std::string& name) {
  for (auto r : ensemble::all_regimes)
    if (ensemble::regime_name(r) == name) return r;
  throw std::runtime_error("unknown regime '" + name + "' in /members/regime");
}

/// Rows of a (members × width) column.
struct Matrix {
  std::vector<double> values;
  std::size_t width = 0;
  const double* row(std::size_t m) const { return values.data() + m * width; }
};

Matrix read_matrix(const Hdf5Location& group, const std::string& name, std::size_t first, std::size_t count) {
  return {group.read_rows_doubles(name, first, count), std::size_t(group.shape(name).second)};
}

}  // namespace

bool is_rotorsweep_file(const Hdf5Location& file) {
  return file.has_attribute("version") && file.has_attribute("complete") &&
         (file.has_attribute("kind") || (file.has_attribute("scene") && file.has("members")));
}

std::string written_by(const Hdf5Location& file) {
  return file.attribute_string("version") + " (revision " + file.attribute_string("revision") + ")";
}

std::size_t member_rows(const Hdf5Location& file) {
  return std::size_t(file.open_group("members").shape("status").first);
}

std::vector<char> read_done(const Hdf5Location& file) {
  const auto flags = file.open_group("members").read_flags("done");
  return std::vector<char>(flags.begin(), flags.end());
}

std::vector<MemberResult> read_member_rows(const Hdf5Location& file, const ensemble::Scene& scene,
                                           const ensemble::MemberPlan& plan, std::size_t first,
                                           std::size_t count, const char* keep) {
  const auto kept = [keep](std::size_t m) { return keep == nullptr || keep[m] != 0; };
  const auto group = file.open_group("members");
  std::vector<MemberResult> results(count);
  if (group.has("plan_index")) {
    const auto index = group.read_rows_integers("plan_index", first, count);
    for (std::size_t m = 0; m < count; ++m) {
      if (!kept(m)) continue;
      if (index[m] < 0 || std::size_t(index[m]) >= plan.size())
        throw std::runtime_error("/members/plan_index is outside the plan");
      results[m].index = std::size_t(index[m]);
    }
  } else {
    if (first + count > plan.size()) throw std::runtime_error("/members holds more rows than the plan");
    for (std::size_t m = 0; m < count; ++m) results[m].index = first + m;
  }
  const auto integers = [&](const char* name) { return group.read_rows_integers(name, first, count); };
  const auto status = group.read_rows_strings("status", first, count);
  const auto attractor = group.read_rows_strings("attractor", first, count);
  const auto settled = integers("settled");
  const auto periods_run = integers("periods_run");
  const auto accepted = integers("steps_accepted");
  const auto rejected = integers("steps_rejected");
  const auto deviation = group.read_rows_doubles("sublattice_deviation", first, count);
  const auto walls = integers("domain_walls");
  const auto detached = integers("detached_rows");
  const auto orbit = integers("orbit_period");
  const auto groups = integers("angle_groups");
  const auto stray = integers("stray_rows");
  const auto sublattice = read_matrix(group, "sublattice_angles", first, count);
  const auto theta = read_matrix(group, "theta_final", first, count);
  std::vector<std::string> regime;
  if (scene.classifies_regimes()) regime = group.read_rows_strings("regime", first, count);
  std::vector<double> shadow, probe;
  std::vector<std::int64_t> limited, departed, held;
  if (scene.runs_shadows()) {
    shadow = group.read_rows_doubles("dissipation_shadow", first, count);
    limited = integers("symmetry_limited");
    if (group.has("shadow_departed")) departed = integers("shadow_departed");  // files before it have none
    if (group.has("dissipation_probe")) {  // files before the symmetry probe have none
      probe = group.read_rows_doubles("dissipation_probe", first, count);
      held = integers("symmetry_held");
    }
  }
  std::optional<Matrix> row_dissipation, link_alignment;
  if (scene.row_profiles) {
    row_dissipation = read_matrix(group, "row_dissipation", first, count);
    link_alignment = read_matrix(group, "link_alignment", first, count);
  }

  for (std::size_t m = 0; m < count; ++m) {
    if (!kept(m)) continue;
    MemberResult& r = results[m];
    r.status = status_from(status[m]);
    if (!regime.empty()) r.regime = regime_from(regime[m]);
    r.settled = settled[m] != 0;
    r.periods_run = int(periods_run[m]);
    r.steps_accepted = double(accepted[m]);
    r.steps_rejected = double(rejected[m]);
    r.theta_final.assign(theta.row(m), theta.row(m) + plan[r.index].rows);
    auto& f = r.final_state;
    f.sublattice_deviation = deviation[m];
    f.domain_walls = int(walls[m]);
    f.detached_rows = int(detached[m]);
    f.orbit_period = int(orbit[m]);
    f.angle_groups = int(groups[m]);
    f.stray_rows = int(stray[m]);
    f.sublattice_even = sublattice.row(m)[0];
    f.sublattice_odd = sublattice.row(m)[1];
    f.attractor = attractor[m];
    if (!shadow.empty()) {
      r.dissipation_shadow = shadow[m];
      r.symmetry_limited = limited[m] != 0;
      r.shadow_departed = !departed.empty() && departed[m] != 0;
      if (!probe.empty()) {
        r.dissipation_probe = probe[m];
        r.symmetry_held = held[m] != 0;
      }
    }
    if (row_dissipation) {
      const std::size_t rows = plan[r.index].rows, links = scene.couplings.open ? rows - 1 : rows;
      r.row_dissipation.assign(row_dissipation->row(m), row_dissipation->row(m) + rows);
      r.link_alignment.assign(link_alignment->row(m), link_alignment->row(m) + links);
    }
  }

  for (std::size_t i = 0; i < ensemble::observable_count; ++i) {
    if (!scene.has(ensemble::Observable(i))) continue;
    const auto& observable = ensemble::observables[i];
    for (std::size_t c = 0; c < observable.channel_count; ++c) {
      const auto& channel = observable.channels[c];
      for (std::size_t k = 0; k < channel.summary_count; ++k) {
        const auto& summary = channel.summaries[k];
        const auto values = group.read_rows_doubles(std::string(summary.column), first, count);
        for (std::size_t m = 0; m < count; ++m)
          if (kept(m)) results[m].summary(summary.summary, channel.channel) = values[m];
      }
      if (!scene.period_series) continue;
      const auto matrix = read_matrix(group, "periods/" + std::string(channel.column), first, count);
      for (std::size_t m = 0; m < count; ++m) {
        if (!kept(m)) continue;
        auto& records = results[m].periods;
        records.resize(std::size_t(results[m].periods_run));
        for (std::size_t p = 0; p < records.size() && p < matrix.width; ++p)
          records[p][channel.channel] = matrix.row(m)[p];
      }
    }
  }
  if (keep) {
    std::size_t out = 0;
    for (std::size_t m = 0; m < count; ++m)
      if (kept(m)) {
        if (out != m) results[out] = std::move(results[m]);
        ++out;
      }
    results.resize(out);
  }
  return results;
}

}  // namespace rotorsweep::io
