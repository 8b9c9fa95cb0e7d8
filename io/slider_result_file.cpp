// Writes a slider scan: /members (one row per member), /series (members × samples), /curve (per separation:
// replica mean and spread of the friction and order parameters) and the provenance attributes.
#include "io/slider_result_file.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

#include "io/hdf5_file.hpp"

namespace rotorsweep::io {

namespace {

using ensemble::SliderMember;

/// One value per member.
template <class F>
std::vector<double> column(const ensemble::SliderResult& result, F&& value) {
  std::vector<double> out;
  for (const auto& m : result.members) out.push_back(value(m));
  return out;
}

/// A members × width table from one vector per member.
std::vector<double> table(const ensemble::SliderResult& result, std::vector<double> SliderMember::*field) {
  std::vector<double> out;
  for (const auto& m : result.members) out.insert(out.end(), (m.*field).begin(), (m.*field).end());
  return out;
}

/// Per (size, separation): the replicas' mean and spread of the friction, the order parameters, and the
/// row model's A at that separation.
void write_curve(const Hdf5Location& curve, const ensemble::SliderScene& scene,
                 const ensemble::SliderResult& result) {
  std::vector<double> separation, friction, spread, order_x, order_y, paper_A, field_A;
  std::vector<std::int64_t> columns, rows, valid;
  for (std::size_t z = 0; z < scene.sizes.size(); ++z)
    for (std::size_t s = 0; s < scene.separations.size(); ++s) {
      const auto size = scene.sizes[z];
      const double h = scene.separations[s];
      double sum = 0, sum2 = 0, sx = 0, sy = 0;
      std::int64_t count = 0;
      for (std::size_t r = 0; r < scene.replicas; ++r) {
        const auto& m = result.members[(z * scene.separations.size() + s) * scene.replicas + r];
        if (m.status != "ok") continue;
        sum += m.friction;
        sum2 += m.friction * m.friction;
        sx += m.order_x;
        sy += m.order_y;
        ++count;
      }
      const double n = double(count);
      separation.push_back(h);
      columns.push_back(std::int64_t(size.columns));
      rows.push_back(std::int64_t(size.rows));
      friction.push_back(count ? sum / n : std::nan(""));
      spread.push_back(count > 1 ? std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1))) : std::nan(""));
      order_x.push_back(count ? sx / n : std::nan(""));
      order_y.push_back(count ? sy / n : std::nan(""));
      valid.push_back(count);
      paper_A.push_back(ensemble::paper_drive_amplitude(scene, h));
      field_A.push_back(ensemble::field_drive_amplitude(scene, size, h));
    }
  curve.write("separation", separation, {}, "layer separation h, m");
  curve.write("columns", columns, "the slider's rotors along x");
  curve.write("rows", rows, "the slider's rotors along y");
  curve.write("friction", friction, {}, "mean drive force over the replicas, N (NaN: no replica finished)");
  curve.write("friction_std", spread, {}, "standard deviation over the replicas, N (NaN below 2 replicas)");
  curve.write("order_x", order_x, {}, "mean alignment of x-neighbours, cos(θ_i − θ_j), while sliding");
  curve.write("order_y", order_y, {}, "mean alignment of y-neighbours while sliding");
  curve.write("replicas", valid, "replicas that finished (status ok)");
  curve.write("A_paper", paper_A, {}, "row model's A = (a/h)³ m_sub/m (docs/model.md §9)");
  curve.write("A_field", field_A, {},
              "row model's A from the substrate field's first harmonic (docs/model.md §9)");
}

}  // namespace

void write_slider_result(const std::string& path, const ensemble::SliderScene& scene,
                         const ensemble::SliderResult& result, const Provenance& provenance, int threads) {
  auto file = Hdf5Location::create_file(path);
  const ensemble::SliderUnits units(scene);
  file.set_attribute("kind", std::string("slider"));
  write_provenance(file, scene.text, provenance);
  file.set_attribute("period", result.period);
  file.set_attribute("spacing", scene.spacing);
  file.set_attribute("g", scene.damping / (units.energy * units.time));
  file.set_attribute("periods", std::int64_t(result.periods));
  file.set_attribute("energy_unit", units.energy);
  file.set_attribute("time_unit", units.time);
  file.set_attribute("wall_seconds", result.seconds);
  file.set_attribute("threads", std::int64_t(threads));

  const auto members = file.create_group("members");
  const hsize_t count = result.members.size(), periods = result.periods;
  members.write("separation", column(result, [](const SliderMember& m) { return m.separation; }), {},
                "layer separation h, m");
  std::vector<std::int64_t> columns, rows, replica;
  for (const auto& m : result.members) {
    columns.push_back(std::int64_t(m.size.columns));
    rows.push_back(std::int64_t(m.size.rows));
    replica.push_back(std::int64_t(m.index.replica));
  }
  members.write("columns", columns, "the slider's rotors along x");
  members.write("rows", rows, "the slider's rotors along y");
  members.write("replica", replica, "replica index at this size and separation");
  members.write("friction", column(result, [](const SliderMember& m) { return m.friction; }), {},
                "mean drive force over the whole periods of sliding, N (NaN where status is not ok)");
  members.write("order_x", column(result, [](const SliderMember& m) { return m.order_x; }), {},
                "mean over the sliding samples of cos(θ_i − θ_j) for x-neighbours");
  members.write("order_y", column(result, [](const SliderMember& m) { return m.order_y; }), {},
                "mean over the sliding samples of cos(θ_i − θ_j) for y-neighbours");
  members.write("steps_accepted", column(result, [](const SliderMember& m) { return m.steps_accepted; }));
  members.write("steps_rejected", column(result, [](const SliderMember& m) { return m.steps_rejected; }));
  std::vector<std::string> status;
  for (const auto& m : result.members) status.push_back(m.status);
  members.write("status", status, "ok, or why the member stopped (its values are then NaN or partial)");
  members.write("period_friction", table(result, &SliderMember::period_friction), {count, periods},
                "mean drive force per substrate period a/v, N");
  members.write("period_work", table(result, &SliderMember::period_work), {count, periods},
                "work of the drive per period, J");
  members.write("period_dissipation", table(result, &SliderMember::period_dissipation), {count, periods},
                "γ ∫ Σ θ̇² dt per period, J");
  members.write("period_stored", table(result, &SliderMember::period_stored), {count, periods},
                "change of magnetic plus kinetic energy over the period, J");
  members.write("period_balance", table(result, &SliderMember::period_balance), {count, periods},
                "(work − dissipation − stored) / max(|work|, dissipation): the energy balance's residual");

  if (scene.series) {
    const auto series = file.create_group("series");
    const hsize_t samples = result.sample_times.size();
    series.write("time", result.sample_times, {},
                 "s since the start of the rest; sliding starts at drive.rest");
    series.write("friction", table(result, &SliderMember::friction_series), {count, samples},
                 "drive force F = ∂E/∂x_s, N");
    series.write("order_x", table(result, &SliderMember::order_x_series), {count, samples},
                 "mean cos(θ_i − θ_j) over x-neighbours");
    series.write("order_y", table(result, &SliderMember::order_y_series), {count, samples},
                 "mean cos(θ_i − θ_j) over y-neighbours");
    series.write("energy", table(result, &SliderMember::energy_series), {count, samples},
                 "magnetic plus kinetic energy, J");
    if (scene.angles)
      series.write("angles", table(result, &SliderMember::angles),
                   {count, samples, hsize_t(scene.sizes.front().rotors())},
                   "θ of rotor j·columns + i (column i along x, row j), rad, unwrapped");
  }
  write_curve(file.create_group("curve"), scene, result);
  file.set_flag("complete", true);  // written whole, and put in place only after this
  file.close();
}

}  // namespace rotorsweep::io
