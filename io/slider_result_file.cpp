// Writes a slider scan as its members finish: /members (one row per member), /series (members × samples),
// /curve (per size, speed, damping and separation: replica mean and spread of the friction and order
// parameters) at the end.
#include "io/slider_result_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "ensemble/engine/replica_statistics.hpp"
#include "ensemble/engine/shadow_estimate.hpp"
#include "io/output_target.hpp"
#include "io/toml_section.hpp"
#include "kernels/steppers/lane_status.hpp"

namespace rotorsweep::io {

namespace {

using ensemble::SliderMember;
using Column = SliderColumn;

/// A per-member vector as a column of `width` (× `depth`) values.
Column vector_column(std::string name, hsize_t width, std::string description,
                     std::vector<double> SliderMember::*field, hsize_t depth = 0) {
  return Column::vector_valued(
      std::move(name), width, std::move(description), [field](const SliderMember& m) { return m.*field; },
      depth);
}

std::size_t status_length() {
  std::size_t length = 0;
  for (const auto status : {kernels::LaneStatus::ok, kernels::LaneStatus::non_finite,
                            kernels::LaneStatus::step_underflow, kernels::LaneStatus::step_budget})
    length = std::max(length, kernels::status_name(status).size());
  return length;
}

/// Per (size, speed, damping, separation): the replicas' mean and spread of the friction, the order
/// parameters, the scaled damping g and the row model's A at that separation, from the members' rows of
/// a complete file.
void write_curve(const Hdf5Location& file, const ensemble::SliderScene& scene) {
  const auto members = file.open_group("members");
  const auto friction_of = members.read_doubles("friction"), order_x_of = members.read_doubles("order_x"),
             order_y_of = members.read_doubles("order_y");
  const auto error_of = scene.shadow_runs ? members.read_doubles("friction_error") : std::vector<double>{};
  const auto status = members.read_strings("status");
  std::vector<double> speed, damping, scaled_damping, separation, friction, spread, sem, bias, order_x, order_y,
      paper_A, field_A;
  std::vector<std::int64_t> columns, rows, valid;
  for (std::size_t point = 0; point < scene.member_count() / scene.replicas; ++point) {
    const std::size_t first = point * scene.replicas;
    const ensemble::SliderMember m = ensemble::slider_plan_member(scene, first);
    const ensemble::SliderSize size = m.size;
    const double h = m.separation;
    const ensemble::SliderUnits units(ensemble::slider_variant(scene, m.index.speed, m.index.damping));
    speed.push_back(m.speed);
    damping.push_back(m.damping);
    scaled_damping.push_back(m.damping / (units.energy * units.time));
    const auto ok = [&](std::size_t r) { return status[first + r] == "ok"; };
    const auto f = ensemble::replica_statistics(
        scene.replicas, [&](std::size_t r) { return friction_of[first + r]; }, ok);
    const auto x = ensemble::replica_statistics(
        scene.replicas, [&](std::size_t r) { return order_x_of[first + r]; }, ok);
    const auto y = ensemble::replica_statistics(
        scene.replicas, [&](std::size_t r) { return order_y_of[first + r]; }, ok);
    if (scene.shadow_runs)
      bias.push_back(
          ensemble::replica_statistics(scene.replicas, [&](std::size_t r) { return error_of[first + r]; }, ok)
              .mean);
    const double n = double(f.count);
    separation.push_back(h);
    columns.push_back(std::int64_t(size.columns));
    rows.push_back(std::int64_t(size.rows));
    friction.push_back(f.mean);
    spread.push_back(f.count > 1 ? f.std * std::sqrt(n / (n - 1)) : std::nan(""));
    sem.push_back(f.sem);
    order_x.push_back(x.mean);
    order_y.push_back(y.mean);
    valid.push_back(std::int64_t(f.count));
    paper_A.push_back(ensemble::paper_drive_amplitude(scene, h));
    field_A.push_back(ensemble::field_drive_amplitude(scene, size, h));
  }
  const auto curve = file.create_group("curve");
  curve.write("separation", separation, {}, "layer separation h, m");
  curve.write("columns", columns, "the slider's rotors along x");
  curve.write("rows", rows, "the slider's rotors along y");
  curve.write("speed", speed, {}, "sliding speed v, m/s");
  curve.write("damping", damping, {}, "the rotors' Stokes damping γ, kg m²/s");
  curve.write("g", scaled_damping, {},
              "γ in the scene's units, γ / (E0 T0) with T0 = a/(2π v): the row model's damping g");
  curve.write("friction", friction, {}, "mean drive force over the replicas, N (NaN: no replica finished)");
  curve.write("friction_std", spread, {},
              "sample standard deviation over the replicas (÷ (n − 1)), N (NaN below 2 replicas)");
  curve.write("friction_sem", sem, {},
              "standard error of friction: population spread / √(n − 1) over the replicas that finished, the "
              "statistic of every result file's curves (docs/output.md \"Output file\"), N (NaN below 2 replicas)");
  if (scene.shadow_runs)
    curve.write("friction_bias", bias, {},
                "mean of the replicas' friction_error: a bound on the integration's bias of friction, N");
  curve.write("order_x", order_x, {}, "mean alignment of x-neighbours, cos(θ_i − θ_j), over the averaged periods");
  curve.write("order_y", order_y, {}, "mean alignment of y-neighbours over the averaged periods");
  curve.write("replicas", valid, "replicas that finished (status ok)");
  curve.write("A_paper", paper_A, {}, "row model's A = (a/h)³ m_sub/m (docs/model.md §9)");
  curve.write("A_field", field_A, {},
              "row model's A from the substrate field's first harmonic (docs/model.md §9)");
  curve.set_units("separation", "m");
  curve.set_units("speed", "m/s");
  curve.set_units("damping", "kg m²/s");
  for (const char* force : {"friction", "friction_std", "friction_sem"}) curve.set_units(force, "N");
  if (scene.shadow_runs) curve.set_units("friction_bias", "N");
}

}  // namespace

std::vector<SliderColumn> slider_columns(const ensemble::SliderScene& scene,
                                         const ensemble::SliderTimeline& timeline) {
  const hsize_t periods = timeline.periods, samples = timeline.samples;
  std::vector<Column> c;
  c.push_back(Column::real_valued("members/separation", "layer separation h, m",
                                  [](const SliderMember& m) { return m.separation; }));
  c.push_back(Column::integer_valued("members/columns", "the slider's rotors along x",
                                     [](const SliderMember& m) { return std::int64_t(m.size.columns); }));
  c.push_back(Column::integer_valued("members/rows", "the slider's rotors along y",
                                     [](const SliderMember& m) { return std::int64_t(m.size.rows); }));
  c.push_back(Column::real_valued("members/speed", "sliding speed v, m/s",
                                  [](const SliderMember& m) { return m.speed; }));
  c.push_back(Column::real_valued("members/damping", "the rotors' Stokes damping γ, kg m²/s",
                                  [](const SliderMember& m) { return m.damping; }));
  c.push_back(Column::integer_valued("members/replica",
                                     "replica index at this size, speed, damping and separation",
                                     [](const SliderMember& m) { return std::int64_t(m.index.replica); }));
  c.push_back(Column::real_valued(
      "members/friction",
      "mean drive force over the averaged periods of sliding: those after drive.relax_periods (by default "
      "the first, the transient after the rest; none where the run slides one period), N (NaN where status "
      "is not ok)",
      [](const SliderMember& m) { return m.friction; }));
  if (scene.shadow_runs) {
    c.push_back(Column::real_valued(
        "members/friction_shadow",
        "friction of the member's shadow run, the same member at tolerances × " +
            number_text(ensemble::shadow_tolerance_scale) + ", N (NaN where it or its shadow failed)",
        [](const SliderMember& m) { return m.friction_shadow; }));
    c.push_back(Column::real_valued(
        "members/friction_error",
        "estimated integration error of friction, " + number_text(ensemble::shadow_safety) +
            " |friction − friction_shadow| / " + number_text(1 - ensemble::shadow_tolerance_scale) +
            " (Richardson's estimate for an error proportional to the tolerance, with a margin), N "
            "(infinite where the shadow failed, NaN where the member did)",
        [](const SliderMember& m) { return m.friction_error; }));
  }
  c.push_back(Column::real_valued("members/order_x",
                                  "mean over the averaged periods' samples of cos(θ_i − θ_j) for x-neighbours",
                                  [](const SliderMember& m) { return m.order_x; }));
  c.push_back(Column::real_valued("members/order_y",
                                  "mean over the averaged periods' samples of cos(θ_i − θ_j) for y-neighbours",
                                  [](const SliderMember& m) { return m.order_y; }));
  c.push_back(Column::real_valued("members/steps_accepted", "accepted steps",
                                  [](const SliderMember& m) { return m.steps_accepted; }));
  c.push_back(Column::real_valued("members/steps_rejected", "rejected steps",
                                  [](const SliderMember& m) { return m.steps_rejected; }));
  c.push_back(Column::text_valued("members/status", status_length(),
                                  "ok, or why the member stopped (its values are then NaN or partial)",
                                  [](const SliderMember& m) { return m.status; }));
  c.push_back(vector_column("members/period_friction", periods,
                            "mean drive force per substrate period a/v, N", &SliderMember::period_friction));
  c.push_back(vector_column("members/period_work", periods, "work of the drive per period, J",
                            &SliderMember::period_work));
  c.push_back(vector_column("members/period_dissipation", periods, "γ ∫ Σ θ̇² dt per period, J",
                            &SliderMember::period_dissipation));
  c.push_back(vector_column("members/period_stored", periods,
                            "change of magnetic plus kinetic energy over the period, J",
                            &SliderMember::period_stored));
  c.push_back(
      vector_column("members/period_balance", periods,
                    "(work − dissipation − stored) / max(|work|, dissipation): the energy balance's residual",
                    &SliderMember::period_balance));
  if (scene.forces) {
    c.push_back(vector_column("members/period_force_y", periods,
                              "mean force on the slider along y per period (trapezoidal over the samples), N",
                              &SliderMember::period_force_y));
    c.push_back(vector_column("members/period_force_z", periods,
                              "mean force on the slider along z per period (trapezoidal over the samples), N",
                              &SliderMember::period_force_z));
  }
  if (scene.series) {
    c.push_back(vector_column("series/friction", samples, "drive force F = ∂E/∂x_s, N",
                              &SliderMember::friction_series));
    c.push_back(vector_column("series/order_x", samples, "mean cos(θ_i − θ_j) over x-neighbours",
                              &SliderMember::order_x_series));
    c.push_back(vector_column("series/order_y", samples, "mean cos(θ_i − θ_j) over y-neighbours",
                              &SliderMember::order_y_series));
    c.push_back(vector_column("series/energy", samples, "magnetic plus kinetic energy, J",
                              &SliderMember::energy_series));
    if (scene.angles)
      c.push_back(vector_column("series/angles", samples,
                                "θ of rotor j·columns + i (column i along x, row j), rad, unwrapped",
                                &SliderMember::angles, hsize_t(scene.sizes.front().rotors())));
    if (scene.energies) {
      c.push_back(vector_column("series/substrate_energy", samples, "the substrate's energy −Σ m·B, J",
                                &SliderMember::substrate_energy_series));
      c.push_back(
          vector_column("series/pair_energy", samples,
                        "the slider's internal energy: its dipole pairs, J (energy − the two: kinetic)",
                        &SliderMember::pair_energy_series));
    }
    if (scene.field) {
      c.push_back(
          vector_column("series/field_axis", samples,
                        "mean substrate field at the rotors' sites along their in-plane axis (x unless "
                        "slider.tilt), T",
                        &SliderMember::field_axis_series));
      c.push_back(vector_column("series/field_z", samples,
                                "mean substrate field at the rotors' sites along z, T",
                                &SliderMember::field_z_series));
    }
    if (scene.sublattices)
      for (const auto& [parity, axis, z, torque] :
           {std::tuple{"even", &SliderMember::moment_axis_even_series, &SliderMember::moment_z_even_series,
                       &SliderMember::torque_even_series},
            {"odd", &SliderMember::moment_axis_odd_series, &SliderMember::moment_z_odd_series,
             &SliderMember::torque_odd_series}}) {
        const std::string rows = std::string(parity) + " rows (j = " + (parity[0] == 'e' ? "0, 2" : "1, 3") +
                                 ", …" + (parity[0] == 'o' ? "; NaN for a slider of one row)" : ")");
        c.push_back(vector_column("series/moment_axis_" + std::string(parity), samples,
                                  "mean unit moment of the " + rows + ": its in-plane part cos θ", axis));
        c.push_back(vector_column("series/moment_z_" + std::string(parity), samples,
                                  "mean unit moment of the " + rows + ": its z part −sin θ", z));
        c.push_back(vector_column("series/torque_" + std::string(parity), samples,
                                  "mean substrate torque on a rotor of the " + rows + ", N m", torque));
      }
    if (scene.forces) {
      c.push_back(
          vector_column("series/force_x", samples,
                        "the substrate's force on the slider along x, N (−friction: the drive holds it)",
                        &SliderMember::force_x_series));
      c.push_back(vector_column("series/force_y", samples, "the substrate's force on the slider along y, N",
                                &SliderMember::force_y_series));
      c.push_back(vector_column("series/force_z", samples,
                                "the substrate's force on the slider along z (up, away from it), N",
                                &SliderMember::force_z_series));
    }
    if (scene.torques)
      c.push_back(vector_column("series/torques", samples, "substrate torque on rotor j·columns + i, N m",
                                &SliderMember::torques, hsize_t(scene.sizes.front().rotors())));
  }
  // SI units of the dimensional columns; the others are "1"
  const std::map<std::string, std::string> units{{"members/separation", "m"},
                                                 {"members/speed", "m/s"},
                                                 {"members/damping", "kg m²/s"},
                                                 {"members/friction", "N"},
                                                 {"members/friction_shadow", "N"},
                                                 {"members/friction_error", "N"},
                                                 {"members/period_friction", "N"},
                                                 {"members/period_work", "J"},
                                                 {"members/period_dissipation", "J"},
                                                 {"members/period_stored", "J"},
                                                 {"series/friction", "N"},
                                                 {"series/energy", "J"},
                                                 {"series/angles", "rad"},
                                                 {"series/substrate_energy", "J"},
                                                 {"series/pair_energy", "J"},
                                                 {"series/field_axis", "T"},
                                                 {"series/field_z", "T"},
                                                 {"series/torque_even", "N m"},
                                                 {"series/torque_odd", "N m"},
                                                 {"series/torques", "N m"},
                                                 {"series/force_x", "N"},
                                                 {"series/force_y", "N"},
                                                 {"series/force_z", "N"},
                                                 {"members/period_force_y", "N"},
                                                 {"members/period_force_z", "N"}};
  for (auto& column : c)
    if (const auto at = units.find(column.name); at != units.end()) column.units = at->second;
  return c;
}

SliderResultFile::SliderResultFile(const std::string& path, const ensemble::SliderScene& scene,
                                   const Provenance& provenance, const std::optional<ShardLabel>& shard)
    : SliderResultFile(Hdf5Location::create_file(creating_path(path)), scene, shard) {
  settle_on_disk(path, [&] { create(provenance); });
}

SliderResultFile SliderResultFile::reopen(const std::string& path, const ensemble::SliderScene& scene) {
  auto location = Hdf5Location::open_file_for_writing(path);
  check_file(location, scene);
  auto shard = shard_label(location);
  SliderResultFile file(std::move(location), scene, shard);
  file.adopt_reopened();
  return file;
}

void SliderResultFile::check_file(const Hdf5Location& file, const ensemble::SliderScene& scene) {
  const hsize_t rows = check_table(file, "slider", scene.member_count());
  check_table_columns(file, slider_columns(scene, ensemble::slider_timeline(scene)), rows, file.path(), "/");
}

SliderResultFile::SliderResultFile(Hdf5Location file, const ensemble::SliderScene& scene,
                                   std::optional<ShardLabel> shard)
    : MemberTableFile(std::move(file), scene.member_count(), shard),
      scene_(scene),
      timeline_(ensemble::slider_timeline(scene)),
      columns_(slider_columns(scene, timeline_)) {}

void SliderResultFile::create(const Provenance& provenance) const {
  const ensemble::SliderUnits units(scene_);
  const bool one_speed = scene_.speeds.size() == 1, one_damping = scene_.dampings.size() == 1;
  file_.set_attribute("kind", std::string("slider"));
  create_table(scene_.text, provenance);
  // the speed's and the damping's own values where the scene has one of each (else /curve has them)
  if (one_speed) file_.set_attribute("period", timeline_.period.front());
  file_.set_attribute("spacing", scene_.spacing);
  if (one_speed && one_damping) file_.set_attribute("g", scene_.damping / (units.energy * units.time));
  file_.set_attribute("periods", std::int64_t(timeline_.periods));
  file_.set_attribute("energy_unit", units.energy);
  if (one_speed) file_.set_attribute("time_unit", units.time);
  file_.set_attribute("wall_seconds", 0.0);
  file_.set_attribute("threads", std::int64_t(0));
  create_table_columns(file_, columns_, rows_);
  if (scene_.series) {
    const auto series = file_.open_group("series");
    if (one_speed) {
      series.write("time", timeline_.sample_times.front(), {},
                   "s since the start of the rest; sliding starts at drive.rest");
    } else {
      std::vector<double> times;
      for (const auto& t : timeline_.sample_times) times.insert(times.end(), t.begin(), t.end());
      series.write("time", times, {hsize_t(scene_.speeds.size()), hsize_t(timeline_.samples)},
                   "per speed (/curve speed order: drive.speed's): s since the start of the rest, sliding "
                   "from drive.rest; columns aligned at the start of sliding, NaN before a speed's first "
                   "sample");
    }
    series.set_units("time", "s");
  }
}

void SliderResultFile::write_members(const std::vector<ensemble::SliderMember>& members) const {
  if (members.empty()) return;
  std::vector<ensemble::SliderMember> sorted(members);
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& a, const auto& b) { return a.plan_index < b.plan_index; });
  std::vector<hsize_t> rows;
  for (const auto& m : sorted) rows.push_back(row_of(m.plan_index));
  write_table_rows(file_, columns_, rows, sorted);
  mark_done(rows);
}

std::size_t SliderResultFile::copy_done_rows(const Hdf5Location& source) const {
  constexpr hsize_t block = 256;
  const auto members = source.open_group("members");
  const auto done = members.read_flags("done");
  const auto plan_index =
      members.has("plan_index") ? members.read_integers("plan_index") : std::vector<std::int64_t>{};
  std::size_t copied = 0;
  for (hsize_t first = 0; first < done.size(); first += block) {
    const hsize_t count = std::min<hsize_t>(block, done.size() - first);
    std::vector<hsize_t> picked, rows;  // rows of the source block, and their rows here
    for (hsize_t k = first; k < first + count; ++k)
      if (done[k]) {
        picked.push_back(k - first);
        rows.push_back(row_of(plan_index.empty() ? std::size_t(k) : std::size_t(plan_index[k])));
      }
    if (picked.empty()) continue;
    for (const auto& column : columns_) {
      const std::size_t width = column.values();
      switch (column.type) {
        case ColumnType::float64: {
          const auto all = source.read_rows_doubles(column.name, first, count);
          std::vector<double> kept;
          for (const auto k : picked)
            kept.insert(kept.end(), all.begin() + std::ptrdiff_t(k * width),
                        all.begin() + std::ptrdiff_t((k + 1) * width));
          file_.write_rows(column.name, rows, kept.data());
          break;
        }
        case ColumnType::int64: {
          const auto all = source.read_rows_integers(column.name, first, count);
          std::vector<std::int64_t> kept;
          for (const auto k : picked) kept.push_back(all[k]);
          file_.write_rows(column.name, rows, kept.data());
          break;
        }
        case ColumnType::text: {
          const auto all = source.read_rows_strings(column.name, first, count);
          std::vector<std::string> kept;
          for (const auto k : picked) kept.push_back(all[k]);
          file_.write_rows(column.name, rows, kept);
          break;
        }
        case ColumnType::flag: break;
      }
    }
    mark_done(rows);
    copied += rows.size();
  }
  return copied;
}

void SliderResultFile::keep_partial(std::size_t members_done, double wall_seconds, int threads) const {
  set_members_done(members_done);
  file_.set_attribute("wall_seconds", wall_seconds);
  file_.set_attribute("threads", std::int64_t(threads));
  file_.flush();
}

namespace {

/// Bytes of /curve's data: 16 columns of 8 bytes per point (size, speed, damping, separation).
double curve_data_bytes(const ensemble::SliderScene& scene) {
  return double(scene.member_count() / scene.replicas) * 16 * 8;
}

}  // namespace

double SliderResultFile::finishing_bytes(const ensemble::SliderScene& scene, bool shard) {
  return shard ? 0.0 : reserved_bytes(curve_data_bytes(scene));
}

void SliderResultFile::finish(double wall_seconds, int threads) const {
  if (!shard_) {
    reserve(curve_data_bytes(scene_), "/curve");
    write_curve(file_, scene_);
  }
  set_members_done(rows_);
  file_.set_attribute("wall_seconds", wall_seconds);
  file_.set_attribute("threads", std::int64_t(threads));
  set_complete();
}

}  // namespace rotorsweep::io
