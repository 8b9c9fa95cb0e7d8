// /curves from /members: a first pass collects the attractor labels, a second aggregates blocks of
// whole points (ensemble::aggregate_curves) into pre-sized columns with Wilson 95 % intervals.
#include "io/curve_table.hpp"

#include <algorithm>
#include <functional>
#include <set>

#include "ensemble/rows/curves.hpp"
#include "ensemble/rows/wilson_interval.hpp"
#include "io/result_reader.hpp"

namespace rotorsweep::io {

namespace {

using ensemble::CurvePoint;

/// Members read at a time (whole points, at least one).
constexpr std::size_t block_members = 4096;

struct CurveColumn {
  std::string name;
  ColumnType type;
  std::string description;
  std::function<double(const CurvePoint&)> value;  ///< as a double, also for integers and text codes
  std::function<std::string(const CurvePoint&)> text;
  std::string units = "1";  ///< of a numeric column (UDUNITS spelling)
};

CurveColumn real(std::string name, std::string description, std::function<double(const CurvePoint&)> value) {
  return {std::move(name), ColumnType::float64, std::move(description), std::move(value), {}};
}

CurveColumn integer(std::string name, std::string description,
                    std::function<double(const CurvePoint&)> value) {
  return {std::move(name), ColumnType::int64, std::move(description), std::move(value), {}};
}

void add_fraction(std::vector<CurveColumn>& columns, const std::string& name, const std::string& what,
                  std::function<std::size_t(const CurvePoint&)> count_of) {
  const auto interval = [count_of](const CurvePoint& p) {
    return ensemble::wilson_interval(count_of(p), p.members);
  };
  columns.push_back(
      real("fraction_" + name, "fraction of the point's members " + what,
           [count_of](const CurvePoint& p) { return double(count_of(p)) / double(p.members); }));
  columns.push_back(real("fraction_" + name + "_low",
                         "Wilson 95 % interval of fraction_" + name + ": lower end",
                         [interval](const CurvePoint& p) { return interval(p).low; }));
  columns.push_back(real("fraction_" + name + "_high",
                         "Wilson 95 % interval of fraction_" + name + ": upper end",
                         [interval](const CurvePoint& p) { return interval(p).high; }));
}

std::vector<CurveColumn> curve_columns(const ensemble::Scene& scene) {
  std::vector<CurveColumn> c;
  c.push_back(integer("rows", "N", [](auto& p) { return double(p.rows); }));
  c.push_back(real("rtol", "relative tolerance", [](auto& p) { return p.rtol; }));
  c.push_back(real("A", "substrate strength A", [](auto& p) { return p.A; }));
  c.push_back(real("g", "g = damping × drive speed", [](auto& p) { return p.g; }));
  c.push_back({"ic", ColumnType::text, "initial condition kind", {}, [](const CurvePoint& p) {
                 return std::string(ensemble::kind_name(p.kind));
               }});
  c.push_back(real("noise", "η of the point's FM/AFM starts", [](auto& p) { return p.noise; }));
  c.back().units = "rad";
  c.push_back(real("offset", "θ0 of the point's FM/AFM starts", [](auto& p) { return p.offset; }));
  c.back().units = "rad";
  c.push_back(integer("members", "replicas at this point", [](auto& p) { return double(p.members); }));
  c.push_back(integer("count", "members with status ok (the statistics use these)",
                      [](auto& p) { return double(p.count); }));
  if (scene.has(ensemble::Observable::dissipation)) {
    const std::string over = " over the point's `count` members (status ok), whatever their regime and flags";
    c.push_back(real("dissipation_mean", "mean of D" + over, [](auto& p) { return p.dissipation_mean; }));
    c.push_back(
        real("dissipation_std", "population spread of D" + over, [](auto& p) { return p.dissipation_std; }));
    c.push_back(real("dissipation_min", "smallest D" + over, [](auto& p) { return p.dissipation_min; }));
    c.push_back(real("dissipation_max", "largest D" + over, [](auto& p) { return p.dissipation_max; }));
    c.push_back(real("dissipation_sem",
                     "standard error of dissipation_mean (sample spread / √count; NaN for one)" + over,
                     [](auto& p) { return p.dissipation_sem; }));
    c.push_back(integer("unresolved",
                        "members of count whose D is not resolved (dissipation_resolved = 0: the error is "
                        "above 0.1 |D|, or no bound: symmetry_limited, shadow_departed)",
                        [](auto& p) { return double(p.unresolved); }));
    c.push_back(
        real("dissipation_bias",
             "the mean of dissipation_error" + over +
                 ": a bound on the integration's bias of dissipation_mean unless symmetry_limited > 0 "
                 "(infinite where a member's shadow departed or failed); the mean is limited by the "
                 "tolerance where it exceeds dissipation_sem",
             [](auto& p) { return p.dissipation_bias; }));
  }
  if (scene.runs_shadows()) {
    c.push_back(
        integer("symmetry_limited",
                "members of count whose D an asymmetry of the rows below rtol decides (symmetry_limited in "
                "/members)",
                [](auto& p) { return double(p.symmetry_limited); }));
    c.push_back(integer("symmetry_held",
                        "of those, members held on a symmetric set without slipping (symmetry_held in /members)",
                        [](auto& p) { return double(p.symmetry_held); }));
    c.push_back(integer("shadow_departed",
                        "members of count whose shadow run reached another attractor (shadow_departed in "
                        "/members)",
                        [](auto& p) { return double(p.shadow_departed); }));
  }
  if (scene.classifies_regimes())
    for (auto regime : ensemble::all_regimes) {
      if (regime == ensemble::Regime::sa && !scene.slip_kinds) continue;
      const std::string name(ensemble::regime_name(regime));
      add_fraction(c, name, "that finished in regime " + name,
                   [regime](const CurvePoint& p) { return p.regime_count[std::size_t(regime)]; });
    }
  add_fraction(c, "failed", "that failed (status not ok)", [](const CurvePoint& p) { return p.failed; });
  return c;
}

/// The longest initial-kind name (the text column "ic").
std::size_t kind_length() {
  std::size_t n = 0;
  for (auto kind : {ensemble::InitialKind::fm, ensemble::InitialKind::afm, ensemble::InitialKind::random,
                    ensemble::InitialKind::exact})
    n = std::max(n, ensemble::kind_name(kind).size());
  return n;
}

/// Calls f(members, results) for consecutive blocks of whole points of the plan.
template <class F>
void for_each_block(const Hdf5Location& file, const ensemble::Scene& scene, const ensemble::MemberPlan& plan,
                    F&& f) {
  for (std::size_t point = 0; point < plan.point_count();) {
    const std::size_t first = plan.point_first(point);
    std::size_t end = point + 1;
    while (end < plan.point_count() && plan.point_first(end + 1) - first <= block_members) ++end;
    const std::size_t count = plan.point_first(end) - first;
    std::vector<ensemble::Member> members;
    for (std::size_t i = first; i < first + count; ++i) members.push_back(plan[i]);
    f(members, read_member_rows(file, scene, plan, first, count));
    point = end;
  }
}

}  // namespace

double curves_data_bytes(const ensemble::Scene& scene, std::size_t labels, std::size_t label_length) {
  return double(ensemble::MemberPlan(scene).point_count()) *
             double(8 * curve_columns(scene).size() + 4 * 8 * labels) +
         double(labels * label_length);
}

void write_curves_from_members(const Hdf5Location& file, const ensemble::Scene& scene,
                               const std::function<void(double bytes)>& reserve) {
  const ensemble::MemberPlan plan(scene);
  const hsize_t points = plan.point_count();
  // pass 1: the attractor labels of the whole sweep
  std::set<std::string> label_set;
  const auto members_group = file.open_group("members");
  for (std::size_t first = 0; first < plan.size(); first += block_members)
    for (auto& label :
         members_group.read_rows_strings("attractor", first, std::min(block_members, plan.size() - first)))
      label_set.insert(std::move(label));
  const std::vector<std::string> labels(label_set.begin(), label_set.end());
  std::size_t label_length = 1;
  for (const auto& l : labels) label_length = std::max(label_length, l.size());

  const auto columns = curve_columns(scene);
  reserve(curves_data_bytes(scene, labels.size(), label_length));
  const auto group = file.create_group("curves");
  for (const auto& column : columns)
    group.create_column(column.name, column.type, {points, 0, kind_length()}, column.description,
                        column.units);
  const auto attractors = group.create_group("attractors");
  const hsize_t width = labels.size();
  attractors.create_column("labels", ColumnType::text, {width, 0, label_length},
                           "attractor labels <regime>:<structure>:p<period> (docs/model.md §3)");
  std::vector<hsize_t> label_rows(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) label_rows[i] = i;
  attractors.write_rows("labels", label_rows, labels);
  attractors.create_column("count", ColumnType::int64, {points, width, 0},
                           "members of the point (row) with the label (column)");
  attractors.create_column("fraction", ColumnType::float64, {points, width, 0},
                           "count / members of the point");
  attractors.create_column("low", ColumnType::float64, {points, width, 0},
                           "Wilson 95 % interval of fraction: lower end");
  attractors.create_column("high", ColumnType::float64, {points, width, 0},
                           "Wilson 95 % interval of fraction: upper end");

  // pass 2: points block by block
  for_each_block(file, scene, plan, [&](const auto& members, const auto& results) {
    const auto curves = ensemble::aggregate_curves(members, results);
    std::vector<hsize_t> rows;
    for (const auto& p : curves) rows.push_back(p.index);
    for (const auto& column : columns) {
      if (column.type == ColumnType::text) {
        std::vector<std::string> values;
        for (const auto& p : curves) values.push_back(column.text(p));
        group.write_rows(column.name, rows, values);
      } else if (column.type == ColumnType::int64) {
        std::vector<std::int64_t> values;
        for (const auto& p : curves) values.push_back(std::int64_t(column.value(p)));
        group.write_rows(column.name, rows, values.data());
      } else {
        std::vector<double> values;
        for (const auto& p : curves) values.push_back(column.value(p));
        group.write_rows(column.name, rows, values.data());
      }
    }
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
    attractors.write_rows("count", rows, count.data());
    attractors.write_rows("fraction", rows, fraction.data());
    attractors.write_rows("low", rows, low.data());
    attractors.write_rows("high", rows, high.data());
  });
}

}  // namespace rotorsweep::io
