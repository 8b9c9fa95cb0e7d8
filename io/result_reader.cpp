// Reading /members back: plan indices, statuses and regimes by name, every declared summary
// column, the schedule counters, final angles, final-state classification and period series.
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

}  // namespace

std::string written_by(const Hdf5Location& file) {
  return file.attribute_string("version") + " (revision " + file.attribute_string("revision") + ")";
}

namespace {

/// A (members × width) dataset's rows, checked against the member count.
struct Matrix {
  std::vector<double> values;
  std::size_t width = 0;
  const double* row(std::size_t m) const { return values.data() + m * width; }
};

Matrix read_matrix(const Hdf5Location& group, const std::string& name, std::size_t members) {
  std::vector<hsize_t> dims;
  Matrix matrix{group.read_doubles(name, &dims), 0};
  if (dims.size() != 2 || dims[0] != members)
    throw std::runtime_error("/members/" + name + " has the wrong shape");
  matrix.width = std::size_t(dims[1]);
  return matrix;
}

}  // namespace

StoredMembers read_member_results(const Hdf5Location& file, const ensemble::Scene& scene,
                                  const std::vector<ensemble::Member>& plan) {
  const auto group = file.open_group("members");
  StoredMembers stored;
  const auto status = group.read_strings("status");
  const std::size_t count = status.size();
  if (group.has("plan_index")) {
    for (auto i : group.read_integers("plan_index")) {
      if (i < 0 || std::size_t(i) >= plan.size())
        throw std::runtime_error("/members/plan_index is outside the plan");
      stored.plan_index.push_back(std::size_t(i));
    }
  } else {
    for (std::size_t i = 0; i < count; ++i) stored.plan_index.push_back(i);
  }
  if (stored.plan_index.size() != count)
    throw std::runtime_error("/members/plan_index and /members/status differ in length");
  auto& results = stored.results;
  results.resize(count);

  const auto attractor = group.read_strings("attractor");
  const auto settled = group.read_integers("settled");
  const auto periods_run = group.read_integers("periods_run");
  const auto accepted = group.read_integers("steps_accepted");
  const auto rejected = group.read_integers("steps_rejected");
  const auto deviation = group.read_doubles("sublattice_deviation");
  const auto walls = group.read_integers("domain_walls");
  const auto detached = group.read_integers("detached_rows");
  const auto orbit = group.read_integers("orbit_period");
  const auto groups = group.read_integers("angle_groups");
  const auto stray = group.read_integers("stray_rows");
  const auto sublattice = read_matrix(group, "sublattice_angles", count);
  const auto theta = read_matrix(group, "theta_final", count);
  std::vector<std::string> regime;
  if (scene.classifies_regimes()) regime = group.read_strings("regime");

  for (std::size_t m = 0; m < count; ++m) {
    MemberResult& r = results[m];
    r.index = stored.plan_index[m];
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
  }

  const bool series = scene.period_series;
  const auto periods = series ? std::optional(group.open_group("periods")) : std::nullopt;
  for (std::size_t i = 0; i < ensemble::observable_count; ++i) {
    if (!scene.has(ensemble::Observable(i))) continue;
    const auto& observable = ensemble::observables[i];
    for (std::size_t c = 0; c < observable.channel_count; ++c) {
      const auto& channel = observable.channels[c];
      for (std::size_t k = 0; k < channel.summary_count; ++k) {
        const auto& summary = channel.summaries[k];
        const auto values = group.read_doubles(std::string(summary.column));
        for (std::size_t m = 0; m < count; ++m)
          results[m].summary(summary.summary, channel.channel) = values[m];
      }
      if (!series) continue;
      const auto matrix = read_matrix(*periods, std::string(channel.column), count);
      for (std::size_t m = 0; m < count; ++m) {
        auto& records = results[m].periods;
        records.resize(std::size_t(results[m].periods_run));
        for (std::size_t p = 0; p < records.size() && p < matrix.width; ++p)
          records[p][channel.channel] = matrix.row(m)[p];
      }
    }
  }
  return stored;
}

}  // namespace rotorsweep::io
