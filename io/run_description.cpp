// The description of a row sweep: the plan's axes, the stepper (or the Langevin stepper at T > 0)
// with its tolerances or steps, the threads, lanes, device and couplings, as `run` prints it.
#include "io/run_description.hpp"

#include <cstdio>

#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/rows/row_models.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::io {

namespace {

std::string format(const char* pattern, auto... values) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

/// The integrator that runs the members: the stepper and its tolerances, or at T > 0 the Langevin stepper.
std::string integrator(const ensemble::Scene& scene) {
  if (scene.thermal.on())
    return format(
        "Langevin (Leimkuhler–Matthews) at T = %g, at least %d steps per period and h ≤ %g g / "
        "max(κ, 11 T)",
        scene.thermal.temperature, scene.thermal.steps_per_period, scene.thermal.step_fraction);
  std::string tolerances;
  for (double r : scene.rtol_values) tolerances += format("%s%g", tolerances.empty() ? "" : ",", r);
  return std::string(kernels::stepper_names[std::size_t(scene.stepper)]) + " rtol " + tolerances;
}

/// The start axes of the plan: "n noise × m offset × k kinds × r replicas" where every kind uses noise
/// and offset, otherwise per group of kinds, e.g. "FM, AFM: 2 noise × 1 offset × 8 replicas; random: 8
/// replicas; exact: once" (MemberPlan).
std::string start_axes(const ensemble::Scene& scene) {
  std::string noisy, plain;
  for (auto kind : scene.kinds) {
    std::string& names = ensemble::kind_uses_noise(kind) ? noisy : plain;
    names += (names.empty() ? "" : ", ") + std::string(ensemble::kind_name(kind));
  }
  const std::string noise_offset =
      format("%zu noise × %zu offset", scene.noise_values.size(), scene.offset_values.size());
  if (plain.empty())
    return format("%s × %zu kinds × %d replicas", noise_offset.c_str(), scene.kinds.size(), scene.replicas);
  std::string text =
      noisy.empty() ? "" : noisy + ": " + noise_offset + format(" × %d replicas; ", scene.replicas);
  for (auto kind : scene.kinds)
    if (!ensemble::kind_uses_noise(kind)) {
      const std::size_t replicas = scene.replicas_of(kind);
      text += std::string(ensemble::kind_name(kind)) + ": " +
              (replicas == 1 ? std::string("once") : format("%zu replicas", replicas)) + "; ";
    }
  return text.substr(0, text.size() - 2);
}

}  // namespace

std::string run_description(const ensemble::Scene& scene, const std::string& name, std::size_t members,
                            int threads, std::size_t simd_lanes) {
  const std::size_t lanes = scene.lanes == ensemble::LaneKind::simd ? simd_lanes : 1;
  std::string rows;
  for (std::size_t n : scene.row_counts) {
    if (!rows.empty()) rows += ',';
    rows += std::to_string(n);
  }
  std::string text = format(
      "rotorsweep run %s: %zu members (%zu N × %zu rtol × %zu A × %zu g × %s), N = %s, %s, "
      "%d threads × %zu lanes\n",
      name.c_str(), members, scene.row_counts.size(), scene.rtol_values.size(), scene.A_values.size(),
      scene.g_values.size(), start_axes(scene).c_str(), rows.c_str(), integrator(scene).c_str(), threads,
      lanes);
  if (scene.device == ensemble::Device::gpu)
    text += format("device: %s (%d host threads summarize)\n", ensemble::device_label(scene).c_str(), threads);
  const auto& couplings = scene.couplings;
  if (!ensemble::row_model_traits(scene.model).coupling_table) return text;
  std::string what = "nearest neighbours";
  if (couplings.kind == ensemble::RowCouplings::Kind::table)
    what = "the table of model.coupling_table (range " + std::to_string(couplings.table.range()) + ")";
  else if (couplings.kind == ensemble::RowCouplings::Kind::dipolar)
    what = "point dipoles over " +
           (couplings.all_rows ? std::string("all rows") : std::to_string(couplings.range) + " rows") +
           (couplings.row_length ? ", rows of " + std::to_string(couplings.row_length) + " rotors"
                                 : std::string(", infinite rows"));
  return text + "couplings: " + what + "; " + (couplings.open ? "open" : "periodic") +
         " boundary (LDLT over the Jacobian's envelope)\n";
}

}  // namespace rotorsweep::io
