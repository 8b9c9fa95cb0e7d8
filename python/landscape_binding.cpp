// Python bindings of the two-angle landscape (docs/model.md §4–5): critical points at (A, τ), the
// chamber map, bifurcation curves, J(A), A_− and A_*, as NumPy arrays (moved, not copied).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "apps/run_needs.hpp"
#include "bindings.hpp"
#include "ensemble/rows/coupling_table.hpp"
#include "landscape/bifurcation_curves.hpp"
#include "landscape/chamber_map.hpp"
#include "landscape/critical_points.hpp"
#include "landscape/jump_friction.hpp"
#include "landscape/quasi_static_cycle.hpp"
#include "numpy_vector.hpp"

namespace py = pybind11;

namespace rotorsweep::python {

namespace {

using namespace rotorsweep::landscape;

constexpr const char* morse_names[] = {"minimum", "saddle", "maximum", "degenerate"};
constexpr const char* alignment_names[] = {"strict_fm", "fm_like", "afm_like"};

py::dict critical_point_arrays(double A, double tau) {
  const CriticalSet set = critical_points(TwoAngleEnergy{A, tau});
  std::vector<double> even, odd, energy, rho;
  py::list type, alignment;
  for (const auto& p : set.points) {
    even.push_back(p.even);
    odd.push_back(p.odd);
    energy.push_back(p.energy);
    rho.push_back(p.rho);
    type.append(morse_names[int(p.type)]);
    alignment.append(alignment_names[int(p.alignment)]);
  }
  py::dict out;
  out["even"] = to_numpy(std::move(even));
  out["odd"] = to_numpy(std::move(odd));
  out["energy"] = to_numpy(std::move(energy));
  out["rho"] = to_numpy(std::move(rho));
  out["type"] = type;
  out["alignment"] = alignment;
  return out;
}

py::dict chamber_arrays(double A_min, double A_max, int A_cells, int tau_cells) {
  apps::throw_refusal(apps::chamber_memory_refusal(A_cells, tau_cells));  // as `landscape chambers`
  ChamberMap map;
  {
    const py::gil_scoped_release unlocked;
    map = chamber_map(ChamberGrid{A_min, A_max, A_cells, tau_cells});
  }
  const std::vector<py::ssize_t> shape{A_cells, tau_cells};
  const std::size_t cells = map.cells.size();
  std::vector<std::int8_t> minima(cells), saddles(cells), maxima(cells), degenerate(cells);
  std::vector<std::int8_t> by_class(cells * 9);
  for (std::size_t i = 0; i < cells; ++i) {
    minima[i] = map.cells[i].minima;
    saddles[i] = map.cells[i].saddles;
    maxima[i] = map.cells[i].maxima;
    degenerate[i] = map.cells[i].degenerate;
    for (int t = 0; t < 3; ++t)
      for (int c = 0; c < 3; ++c)
        by_class[i * 9 + std::size_t(3 * t + c)] = map.cells[i].by_type_and_class[t][c];
  }
  py::dict out;
  out["A"] = to_numpy(std::move(map.A));
  out["tau"] = to_numpy(std::move(map.tau));
  out["minima"] = to_numpy(std::move(minima), shape);
  out["saddles"] = to_numpy(std::move(saddles), shape);
  out["maxima"] = to_numpy(std::move(maxima), shape);
  out["degenerate"] = to_numpy(std::move(degenerate), shape);
  out["by_type_and_class"] = to_numpy(std::move(by_class), {A_cells, tau_cells, 3, 3});
  out["zone"] = to_numpy(std::move(map.zone), shape);
  out["chamber"] = to_numpy(std::move(map.chamber), shape);
  out["zones"] = map.zones;
  out["chambers"] = map.chambers;
  return out;
}

py::dict jump_event_values(double A) {
  const JumpEvents e = jump_events(A);
  py::dict out;
  out["A"] = e.A;
  out["tau_transverse"] = e.tau_transverse;
  out["energy_fm_transverse"] = e.energy_fm_transverse;
  out["landing_transverse"] = e.landing_transverse;
  out["zeta_landing"] = e.zeta_landing;
  out["zeta_low"] = e.zeta_low;
  out["tau_low"] = e.tau_low;
  out["energy_low"] = e.energy_low;
  out["landing_low"] = e.landing_low;
  out["J"] = e.J;
  return out;
}

py::dict curve_arrays(const std::string& name, int count, double A_max) {
  apps::throw_refusal(apps::curve_memory_refusal(count));  // as `landscape curves`
  for (Curve curve : all_curves) {
    if (curve_name(curve) != name) continue;
    std::vector<double> A, tau, parameter;
    for (const auto& p : sample_curve(curve, count, A_max)) {
      A.push_back(p.A);
      tau.push_back(p.tau);
      parameter.push_back(p.parameter);
    }
    py::dict out;
    out["A"] = to_numpy(std::move(A));
    out["tau"] = to_numpy(std::move(tau));
    out["parameter"] = to_numpy(std::move(parameter));
    return out;
  }
  std::string allowed;
  for (Curve curve : all_curves) allowed += (allowed.empty() ? "" : ", ") + std::string(curve_name(curve));
  throw py::value_error("curve '" + name + "' is not one of: " + allowed);
}

}  // namespace

void bind_landscape(py::module_& m) {
  m.def(
      "critical_points", &critical_point_arrays, py::arg("A"), py::arg("tau"),
      "Every critical point of H_r(θe, θo; A, τ): arrays even, odd, energy, rho and lists type, alignment.");
  m.def("chamber_map", &chamber_arrays, py::arg("A_min"), py::arg("A_max"), py::arg("A_cells"),
        py::arg("tau_cells"), "The chamber raster over (A, τ ∈ [0, π/2]) (cell centres).");
  m.def("jump_events", &jump_event_values, py::arg("A"),
        "The two jumps of half a period at A (NaN outside).");
  m.def("jump_friction", py::vectorize([](double A, double a, double b, double c) {
          return jump_friction(A, {a, b, c});
        }),
        py::arg("A"), py::arg("a") = 1.5, py::arg("b") = 2.0, py::arg("c") = 0.0,
        "J(A) by the paper's recipe for coefficients (a, b, c); NaN outside [A_-, A_*].");
  m.def(
      "quasi_static_cycle",
      [](const std::vector<double>& A, double a, double b, double c) {
        std::vector<double> J(A.size()), rho(A.size());
        {
          const py::gil_scoped_release unlocked;
          for (std::size_t i = 0; i < A.size(); ++i) {
            const auto cycle = quasi_static_cycle(A[i], {a, b, c});
            J[i] = cycle.J, rho[i] = cycle.mean_rho;
          }
        }
        return py::make_tuple(to_numpy(std::move(J)), to_numpy(std::move(rho)));
      },
      py::arg("A"), py::arg("a"), py::arg("b"), py::arg("c"),
      "Friction and mean alignment of the quasi-static cycle from the AFM state, per A.");
  m.def(
      "cp_interval",
      [](double a, double b, double c) {
        const auto& interval = cp_interval({a, b, c});
        return py::make_tuple(interval.A_minus, interval.A_star);
      },
      py::arg("a"), py::arg("b"), py::arg("c"), "(A_-, A_*) for coefficients (a, b, c).");
  m.def(
      "two_angle_coefficients",
      [](std::size_t range, bool all_rows, std::size_t row_length, std::size_t rows) {
        ensemble::RowCouplings couplings;
        couplings.kind = ensemble::RowCouplings::Kind::dipolar;
        couplings.range = range, couplings.all_rows = all_rows, couplings.row_length = row_length;
        const auto k = ensemble::two_angle_coefficients(
            rows > 0 ? couplings.for_rows(rows) : ensemble::dipolar_table(range, row_length));
        return py::make_tuple(k.a, k.b, k.c);
      },
      py::arg("range"), py::arg("all_rows"), py::arg("row_length"), py::arg("rows"),
      "a_M, b_M, c_M of point-dipole rows (rows > 0: the periodic ring of that many rows).");
  m.def("bifurcation_curve", &curve_arrays, py::arg("name"), py::arg("count"), py::arg("A_max"),
        "Points of a bifurcation or alignment curve in the folded (A, τ) plane.");
  py::list curves;
  for (Curve curve : all_curves) curves.append(std::string(curve_name(curve)));
  m.attr("curve_names") = curves;
  m.attr("A_minus") = A_minus();
  m.attr("A_star") = A_star();
}

}  // namespace rotorsweep::python
