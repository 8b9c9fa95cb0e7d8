// The checks a run or scan makes before any work (apps/run_needs.hpp): a run's lane blocks and a scan's
// threads against usable_memory_bytes, their files' bytes against the disk's free space.
#include "run_needs.hpp"

#include <cstdint>
#include <cstdio>
#include <filesystem>

#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/rows/row_models.hpp"
#include "ensemble/rows/working_set.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "io/member_columns.hpp"
#include "io/result_file.hpp"
#include "io/slider_result_file.hpp"
#include "landscape/bifurcation_curves.hpp"
#include "landscape/chamber_map.hpp"
#include "usable_memory.hpp"

namespace rotorsweep::apps {

void throw_refusal(const std::optional<std::string>& refusal) {
  if (refusal) throw RunRefused(*refusal);
}

std::optional<std::string> disk_refusal(double needed, const std::string& what, const std::string& partial,
                                        const std::string& advice) {
  std::error_code error;
  auto directory = std::filesystem::absolute(partial, error).parent_path();
  const auto space = std::filesystem::space(directory, error);
  if (error || needed <= 0.95 * double(space.available)) return std::nullopt;
  const auto amount = [](double bytes) {
    char text[32];
    std::snprintf(text, sizeof text, bytes < 0x1p27 ? "%.3g MiB" : "%.3g GiB",
                  bytes < 0x1p27 ? bytes / 0x1p20 : bytes / 0x1p30);
    return std::string(text);
  };
  return what + " need about " + amount(needed) + " on disk; " + directory.string() + " has " +
         amount(double(space.available)) + " free. " + advice + ".";
}

std::optional<std::string> gpu_refusal(ensemble::Device device) {
  if (device != ensemble::Device::gpu || ensemble::gpu_info().available) return std::nullopt;
  return "numerics.device = \"gpu\" (or --device gpu): " + ensemble::gpu_info().why + "; run with --device cpu";
}

std::optional<std::string> sweep_memory_refusal(const ensemble::Scene& scene, int threads, double held_bytes) {
  // the GPU's scratch is checked by the parser
  const double block = scene.device == ensemble::Device::gpu ? 0.0 : ensemble::lane_block_bytes(scene);
  char how[200];
  std::snprintf(how, sizeof how, " to work in (%d threads × %.3g GiB, one lane block each at N = %zu%s)", threads,
                block / 0x1p30, scene.max_rows(), held_bytes > 0 ? ", and the result held in memory" : "");
  return memory_refusal(double(threads) * block + held_bytes, "the sweep", how,
                        std::string("use fewer --threads or rows") +
                            (ensemble::row_model_traits(scene.model).coupling_table
                                 ? " (a dense coupling table grows as N²: a shorter range)"
                                 : "") +
                            (held_bytes > 0 ? ", or write the result to a file (output=)" : ""));
}

double sweep_disk_bytes(const ensemble::Scene& scene, std::size_t rows, bool shard) {
  return double(rows) * io::member_row_bytes(io::member_columns(scene)) +
         io::ResultFile::finishing_bytes(scene, shard);
}

std::optional<std::string> sweep_disk_refusal(const ensemble::Scene& scene, std::size_t rows, bool shard,
                                              const std::string& partial) {
  char what[96];
  std::snprintf(what, sizeof what, "the results of the plan's %.3g members and the curves written at the end",
                double(rows));
  return disk_refusal(sweep_disk_bytes(scene, rows, shard), what, partial,
                      std::string("Split the sweep (fewer A, g, replicas per scene, or --shard)") +
                          (scene.period_series ? " or switch off observables.period_series" : ""));
}

namespace {

double scan_row_bytes(const ensemble::SliderScene& scene) {
  return io::table_row_bytes(io::slider_columns(scene, ensemble::slider_timeline(scene)));
}

}  // namespace

std::optional<std::string> scan_memory_refusal(const ensemble::SliderScene& scene, int threads) {
  if (scene.device == ensemble::Device::gpu) return std::nullopt;  // the GPU's members live on the GPU
  const double row_bytes = scan_row_bytes(scene);
  const double lanes = double(ensemble::slider_thread_lanes(scene));
  const double thread = ensemble::slider_thread_bytes(scene) + lanes * row_bytes;
  char how[160];
  std::snprintf(how, sizeof how,
                " to work in (%d threads × %.3g GiB: a lane block, substrate tables and %g members' series each)",
                threads, thread / 0x1p30, lanes);
  return memory_refusal(double(threads) * thread + 2 * row_bytes, "the scan", how,
                        "use fewer --threads, a smaller slider, fewer samples or series, or fewer periods");
}

std::optional<std::string> scan_disk_refusal(const ensemble::SliderScene& scene, std::size_t members, bool shard,
                                             const std::string& partial) {
  char what[96];
  std::snprintf(what, sizeof what, "the results of the plan's %zu members and the curve written at the end",
                members);
  return disk_refusal(double(members) * (1 + scan_row_bytes(scene)) +
                          io::SliderResultFile::finishing_bytes(scene, shard),
                      what, partial,
                      "Split the scan (fewer separations or replicas per scene, or --shard) or switch off "
                      "observables.series");
}

std::optional<std::string> chamber_memory_refusal(int A_cells, int tau_cells) {
  // per cell: its counts, zone and chamber, the labelling's scratch, and the counts and a field written
  const double cell_bytes = sizeof(landscape::ChamberCell) + 5 * sizeof(std::int32_t) + 10 * sizeof(std::int64_t);
  return memory_refusal(double(A_cells) * double(tau_cells) * cell_bytes, "landscape chambers",
                        " for its " + std::to_string(A_cells) + " × " + std::to_string(tau_cells) + " cells",
                        "use fewer --A-cells or --tau-cells");
}

std::optional<std::string> curve_memory_refusal(long long samples) {
  // a curve at a time: its points and the three columns written
  const double point_bytes = sizeof(landscape::BifurcationPoint) + 3 * sizeof(double);
  return memory_refusal(double(samples) * point_bytes, "landscape curves",
                        " for " + std::to_string(samples) + " samples per curve", "use fewer --samples");
}

}  // namespace rotorsweep::apps
