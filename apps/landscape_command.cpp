// `rotorsweep landscape chambers|curves|jump-friction -o FILE.h5`: the chamber raster, the sampled
// bifurcation and alignment curves, and J(A) on [A_-, A_*] (model.md §4–5), each as an HDF5 file.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>

#include "build_info.hpp"
#include "commands.hpp"
#include "ensemble/rows/coupling_table.hpp"
#include "io/hdf5_file.hpp"
#include "io/output_target.hpp"
#include "landscape/bifurcation_curves.hpp"
#include "landscape/chamber_map.hpp"
#include "landscape/jump_friction.hpp"
#include "landscape/quasi_static_cycle.hpp"
#include "progress_line.hpp"
#include "remove_on_signal.hpp"
#include "run_needs.hpp"
#include "run_support.hpp"
#include "usable_memory.hpp"

namespace rotorsweep::apps {

namespace {

using Clock = std::chrono::steady_clock;

/// Creates the file (beside its final path, see io/output_target.hpp) with `complete` = FALSE,
/// lets `fill` write it, records the wall time, sets `complete` = TRUE and puts it in place.
/// Exit code 2 when the path cannot be used, 1 on a later failure (no file is left behind).
int write_landscape_file(const std::string& path, bool force, const std::string& kind,
                         const std::function<void(const io::Hdf5Location&)>& fill) {
  std::optional<io::OutputTarget> target;
  std::optional<RemoveOnSignal> on_signal;
  std::optional<io::Hdf5Location> file;
  try {
    target.emplace(path, std::vector<std::string>{}, io::Replaceable::hdf5, force);
    on_signal.emplace(*target);
    file = io::Hdf5Location::create_file(target->temporary());
    target->claim_temporary();
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << " (-o)\n";
    return 2;
  }
  try {
    file->set_flag("complete", false);
    file->set_attribute("kind", "landscape " + kind);
    file->set_attribute("version", std::string(version));
    file->set_attribute("revision", std::string(revision));
    file->flush();
    const auto start = Clock::now();
    fill(*file);
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    file->set_attribute("wall_seconds", wall);
    file->set_flag("complete", true);
    file->close();
    on_signal.reset();  // from here the file is whole: a signal ends the process as usual
    target->commit();
    std::printf("wrote %s (%s)%s in %s\n", path.c_str(), kind.c_str(),
                target->replaced() ? " replacing the previous file" : "", format_duration(wall).c_str());
  } catch (const std::exception& e) {
    std::cerr << "error: writing '" << path << "' failed: " << e.what() << "; "
              << (target->replaced() ? "the previous file is unchanged" : "no file was written") << "\n";
    return 1;
  }
  return 0;
}

/// The landscape's coefficients: given, from a point-dipole table (computed once, with a progress
/// line: long ranges take minutes), or nearest neighbours.
landscape::TwoAngleCoefficients coefficients(const LandscapeOptions& o) {
  if (o.coefficients.size() == 3) return {o.coefficients[0], o.coefficients[1], o.coefficients[2]};
  if (o.range == 0) return {};
  static std::optional<landscape::TwoAngleCoefficients> table_coefficients;  // one command per process
  if (!table_coefficients) {
    ProgressLine progress(o.range, !o.quiet, "row distances");
    table_coefficients = ensemble::two_angle_coefficients(ensemble::dipolar_table(
        o.range, row_length_value(o.row_length), [&](std::size_t u) { progress.update(u); }));
    progress.finish();
  }
  return *table_coefficients;
}

/// The coefficients and the CP interval as file attributes; the alignment curve's type changes.
void write_landscape_constants(const io::Hdf5Location& file, const LandscapeOptions& o) {
  const auto k = coefficients(o);
  file.set_attribute("a", k.a);
  file.set_attribute("b", k.b);
  file.set_attribute("c", k.c);
  file.set_attribute("couplings", o.coefficients.size() == 3 ? std::string("coefficients given")
                                  : o.range > 0 ? "point dipoles, range " + std::to_string(o.range) +
                                                      ", row length " + o.row_length
                                                : std::string("nearest neighbours"));
  file.set_attribute("A_minus", landscape::A_minus(k));
  file.set_attribute("A_star", landscape::A_star(k));
  file.set_attribute("zeta0", landscape::lower_curve_zeta0(k));
  file.write("alignment_type_changes", landscape::alignment_type_changes(k), {},
             "folded phases τ where the alignment curve's ρ = 1/2 point changes Morse type");
}

std::vector<std::int64_t> cell_field(const landscape::ChamberMap& map,
                                     const std::function<int(const landscape::ChamberCell&)>& field) {
  std::vector<std::int64_t> out;
  out.reserve(map.cells.size());
  for (const auto& c : map.cells) out.push_back(field(c));
  return out;
}

/// Given coefficients must give a finite CP window [A_−, A_*] (all zero, for one, give none: every curve and
/// J would be NaN); says so (exit code 2) where they do not.
bool coefficients_usable(const LandscapeOptions& o) {
  if (o.coefficients.size() != 3) return true;
  const auto k = coefficients(o);
  const double lo = landscape::A_minus(k), hi = landscape::A_star(k);
  if (std::isfinite(lo) && std::isfinite(hi)) return true;
  char text[200];
  std::snprintf(text, sizeof text, "a, b, c = %g, %g, %g give no CP window (A_- = %g, A_* = %g)", k.a, k.b,
                k.c, lo, hi);
  std::cerr
      << "error: --coefficients: " << text
      << "; give coefficients with a finite window, or leave them out (nearest neighbours, or --range)\n";
  return false;
}

}  // namespace

int run_landscape_chambers(const LandscapeOptions& o) {
  if (!coefficients_usable(o)) return 2;
  if (!(o.A_max > o.A_min) || o.A_min < 0) {
    std::cerr << "error: --A-min, --A-max: need 0 <= A-min < A-max (got " << o.A_min << ", " << o.A_max
              << ")\n";
    return 2;
  }
  if (refused(chamber_memory_refusal(o.A_cells, o.tau_cells))) return 2;
  const RemoveOnSignal on_start;  // a long coupling table comes first
  const landscape::ChamberGrid grid{o.A_min, o.A_max, o.A_cells, o.tau_cells, coefficients(o)};
  const std::size_t cells = std::size_t(grid.A_cells) * grid.tau_cells;
  const int min_cells =
      o.min_zone_cells > 0 ? o.min_zone_cells : int(std::max<std::size_t>(10, cells / 10000));
  return write_landscape_file(o.output, o.force, "chambers", [&](const io::Hdf5Location& file) {
    ProgressLine progress(std::size_t(grid.A_cells), !o.quiet, "A rows");
    const auto map = landscape::chamber_map(grid, [&](int rows) { progress.update(std::size_t(rows)); });
    progress.finish();
    const std::vector<hsize_t> dims{hsize_t(grid.A_cells), hsize_t(grid.tau_cells)};
    const std::string per_cell = " (A cells × τ cells; critical points on the torus)";
    file.write("A", map.A, {}, "A at the cell centres");
    file.write("tau", map.tau, {}, "drive phase τ at the cell centres, in [0, π/2]");
    file.write("minima", cell_field(map, [](const auto& c) { return c.minima; }), dims, "minima" + per_cell);
    file.write("saddles", cell_field(map, [](const auto& c) { return c.saddles; }), dims,
               "saddles" + per_cell);
    file.write("maxima", cell_field(map, [](const auto& c) { return c.maxima; }), dims, "maxima" + per_cell);
    file.write("degenerate", cell_field(map, [](const auto& c) { return c.degenerate; }), dims,
               "critical points with a singular Hessian" + per_cell);
    constexpr const char* classes[] = {"strict_fm", "fm_like", "afm_like"};
    for (int k = 0; k < 3; ++k)
      file.write(std::string("minima_") + classes[k],
                 cell_field(map, [k](const auto& c) { return c.by_type_and_class[0][k]; }), dims,
                 std::string("minima of alignment class ") + classes[k] + per_cell);
    std::vector<std::int64_t> counts;
    for (const auto& c : map.cells)
      for (const auto& row : c.by_type_and_class) counts.insert(counts.end(), row.begin(), row.end());
    file.write("counts", counts, {dims[0], dims[1], 3, 3},
               "critical points by Morse type (minimum, saddle, maximum) × alignment class (strict FM, "
               "FM-like, AFM-like)" +
                   per_cell);
    file.write("zone", std::vector<std::int64_t>(map.zone.begin(), map.zone.end()), dims,
               "connected component of equal Morse signature; -1: degenerate cell");
    file.write("chamber", std::vector<std::int64_t>(map.chamber.begin(), map.chamber.end()), dims,
               "connected component of equal Morse signature and alignment classes; -1: degenerate cell");
    file.set_attribute("zones", std::int64_t(map.zones_at_least(min_cells)));
    file.set_attribute("chambers", std::int64_t(map.chambers_at_least(min_cells)));
    file.set_attribute("components_min_cells", std::int64_t(min_cells));
    file.set_attribute("zone_components_all", std::int64_t(map.zones));
    file.set_attribute("chamber_components_all", std::int64_t(map.chambers));
    write_landscape_constants(file, o);
    std::printf(
        "%d zones of constant Morse signature, %d chambers (components of >= %d cells; %d and %d "
        "counting slivers along the curves)\n",
        map.zones_at_least(min_cells), map.chambers_at_least(min_cells), min_cells, map.zones, map.chambers);
    const auto unresolved = std::count_if(map.cells.begin(), map.cells.end(),
                                          [](const landscape::ChamberCell& c) { return c.degenerate != 0; });
    if (unresolved > 0)
      std::printf("%ld of %zu cells degenerate (critical points not resolved there; zone and chamber -1)\n",
                  long(unresolved), map.cells.size());
  });
}

int run_landscape_curves(const LandscapeOptions& o) {
  if (!coefficients_usable(o)) return 2;
  if (refused(curve_memory_refusal(o.samples))) return 2;
  const RemoveOnSignal on_start;
  return write_landscape_file(o.output, o.force, "curves", [&](const io::Hdf5Location& file) {
    for (auto curve : landscape::all_curves) {
      const auto points = landscape::sample_curve(curve, o.samples, o.A_max, coefficients(o));
      std::vector<double> A, tau, parameter;
      for (const auto& p : points) A.push_back(p.A), tau.push_back(p.tau), parameter.push_back(p.parameter);
      const auto group = file.create_group(std::string(landscape::curve_name(curve)));
      group.write("A", A, {}, "A along the curve");
      group.write("tau", tau, {}, "drive phase τ folded into [0, π/2]");
      group.write("parameter", parameter, {},
                  curve == landscape::Curve::alignment ? "χ of the ρ = 1/2 point (χ ± π/4), in [0, π/2]"
                  : (curve == landscape::Curve::fm_tangential || curve == landscape::Curve::fm_transverse)
                      ? "strict-FM angle χ in [0, π/2]"
                      : "ζ = cos((θe − θo)/2) of the degenerate point");
    }
    write_landscape_constants(file, o);
  });
}

int run_landscape_jump_friction(const LandscapeOptions& o) {
  if (!coefficients_usable(o)) return 2;
  // the eleven columns written, one value per A
  if (!fits_in_memory(double(o.count) * 11 * sizeof(double), "landscape jump-friction",
                      " for " + std::to_string(o.count) + " A values", "use a smaller --count"))
    return 2;
  const RemoveOnSignal on_start;  // a long coupling table comes first
  const auto k = coefficients(o);
  const bool cp_grid = o.J_A_min == 0 && o.J_A_max == 0;
  const double lo = cp_grid ? landscape::A_minus(k) : o.J_A_min,
               hi = cp_grid ? landscape::A_star(k) : o.J_A_max;
  if (!(hi >= lo) || lo < 0) {
    std::cerr << "error: --A-min, --A-max: need 0 <= A-min <= A-max (got " << lo << ", " << hi << ")\n";
    return 2;
  }
  return write_landscape_file(o.output, o.force, "jump-friction", [&](const io::Hdf5Location& file) {
    std::vector<double> A, J, J_cycle, rho_cycle, drop_transverse, drop_low, zeta_low, zeta_landing,
        tau_transverse, tau_low;
    std::vector<std::int64_t> jumps;
    ProgressLine progress(std::size_t(o.count), !o.quiet, "A values");
    for (int i = 0; i < o.count; ++i) {
      const auto e = landscape::jump_events(o.count > 1 ? lo + (hi - lo) * i / (o.count - 1) : lo, k);
      const auto cycle = landscape::quasi_static_cycle(e.A, k);
      A.push_back(e.A);
      J.push_back(e.J);
      J_cycle.push_back(cycle.J);
      rho_cycle.push_back(cycle.mean_rho);
      jumps.push_back(std::int64_t(cycle.jumps.size()));
      drop_transverse.push_back(e.energy_fm_transverse - e.landing_transverse);
      drop_low.push_back(e.energy_low - e.landing_low);
      zeta_low.push_back(e.zeta_low);
      zeta_landing.push_back(e.zeta_landing);
      tau_transverse.push_back(landscape::fundamental_phase(e.tau_transverse));
      tau_low.push_back(landscape::fundamental_phase(e.tau_low));
      progress.update(std::size_t(i + 1));
    }
    progress.finish();
    file.write("A", A, {}, cp_grid ? "A, uniform on [A_-, A_*]" : "A, uniform on [A-min, A-max]");
    file.write("J", J, {},
               "quasi-static CP friction J(A) by the paper's recipe (NaN outside [A_-, A_*] and where its "
               "sequence of jumps does not occur)");
    file.write("J_cycle", J_cycle, {},
               "friction of the quasi-static cycle from the AFM state: energy dropped per row and period "
               "(D/N → J_cycle as g → 0)");
    file.write("rho_cycle", rho_cycle, {}, "alignment averaged over the quasi-static cycle");
    file.write("jumps_cycle", jumps, {}, "jumps per period of the quasi-static cycle");
    file.write("drop_transverse", drop_transverse, {},
               "energy drop when strict FM loses transverse stability");
    file.write("drop_low", drop_low, {}, "energy drop when the off-diagonal minimum ends on B_off^-");
    file.write("zeta_low", zeta_low, {},
               "ζ of the off-diagonal minimum where it ends (larger root of A_L = A)");
    file.write("zeta_landing", zeta_landing, {}, "ζ of the off-diagonal minimum reached from strict FM");
    file.write("tau_transverse", tau_transverse, {}, "phase of the transverse jump, folded into [0, π/2]");
    file.write("tau_low", tau_low, {}, "phase of the jump from B_off^-, folded into [0, π/2]");
    write_landscape_constants(file, o);
    file.set_attribute("J_at_A_minus", landscape::jump_friction(landscape::A_minus(k), k));
  });
}

}  // namespace rotorsweep::apps
