// `rotorsweep bench gpu`: whole-sweep throughput on the GPU backend, members in registers, per thread and per team
// (or, with --device cpu, on this machine's cores for scale): step attempts/s and a 10⁶-member curve.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/scene_parser.hpp"

namespace rotorsweep::apps {

namespace {

struct BenchScene {
  int rows;
  const char* stepper;
  int A_count;
  int replicas;
  bool dipolar = false;  ///< open rows coupled by point dipoles over every distance (the slider's rows)
  bool every_quadrature = false;  ///< the estimators, the energy and the moments beside R and ρ̄
};

/// The benchmark scenes of docs/performance.md "GPU": g = 0.01, A from 0.25 to 16, random starts,
/// 2 + 2 periods, rtol 1e-6 (atol 1e-9); nearest neighbours, or the experiment's dipolar table; the
/// default observables or every quadrature. Each member runs once (global_error = "local"): the rates
/// count a member's own attempts, and a scene with symmetry probes would take a disordered shape.
std::string scene_text(const BenchScene& s, const std::string& device) {
  const std::string table =
      s.dipolar ? "couplings = \"dipolar\"\nrange = \"all\"\nrow_length = 7\nboundary = \"open\"\n" : "";
  return "[model]\nrows = " + std::to_string(s.rows) + "\n" + table +
         "[drive]\ng = [0.01]\n[sweep]\nA = {from = 0.25, to = 16, count = " + std::to_string(s.A_count) +
         "}\n[initial]\nkinds = [\"random\"]\nreplicas = " + std::to_string(s.replicas) +
         "\n[schedule]\nrelax_periods = 2\naverage_periods = 2\n[numerics]\nstepper = \"" + s.stepper +
         "\"\nrtol = 1e-6\natol = 1e-9\nglobal_error = \"local\"\ndevice = \"" + device + "\"\n" +
         (s.every_quadrature ? "[observables]\nestimators = true\nenergy = true\nmoments = true\n" : "");
}

/// How members are laid on the GPU for a row: threads per member and, for a team, where its
/// scratch lives (the launch's team and scratch, on the environment's block shape); team 0 is the
/// default mapping, and on the CPU the lanes.
struct Mapping {
  int team = 0;
  std::string scratch;
};

/// The executor of mapping m: the environment's launch (gpu_executor) with m's team and scratch.
ensemble::GpuExecutor executor_of(const Mapping& m) {
  ensemble::GpuLaunch launch = ensemble::gpu_executor().launch();
  launch.team = unsigned(m.team);
  launch.scratch = m.scratch == "shared"   ? ensemble::GpuScratch::shared
                   : m.scratch == "global" ? ensemble::GpuScratch::global
                                           : ensemble::GpuScratch::automatic;
  return ensemble::GpuExecutor(launch);
}

std::string mapping_label(const Mapping& m, const ensemble::Scene& scene, int rows, const BenchGpuOptions& options) {
  if (options.device == "cpu") return "lanes";
  if (m.team == 0) {
    const auto shape = executor_of(m).plan(scene, std::size_t(rows)).shape;
    if (!shape) return "default";
    return "registers " + std::to_string(shape->lanes) + " × " + std::to_string(shape->slots) + ", " +
           std::to_string(shape->stages) + " stages";
  }
  if (m.team == 1) return "thread";
  return "team " + std::to_string(m.team) + ", " + m.scratch;
}

/// The mappings a scene is measured with: the lanes on the CPU; on the GPU the registers where a
/// register kernel holds the scene, a member per thread and per team of each size in options.teams up
/// to N where teams run the scene, in shared and/or global memory.
std::vector<Mapping> mappings_of(const ensemble::Scene& scene, int rows, const BenchGpuOptions& options) {
  if (options.device == "cpu") return {Mapping{}};
  std::vector<Mapping> out;
  if (ensemble::GpuExecutor().plan(scene, std::size_t(rows)).mapping == ensemble::GpuMapping::registers)
    out.push_back({});
  for (const int team : options.teams) {
    if (team == 1) out.push_back({1, ""});
    if (team == 1 || team > rows || !ensemble::gpu_teams_fit(scene)) continue;
    for (const char* scratch : {"shared", "global"})
      if (options.scratch == "both" || options.scratch == scratch) out.push_back({team, scratch});
  }
  return out;
}

std::string format_rate(double rate) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", rate);
  return text;
}

/// One sweep (plan, device work, host summaries; no file) with mapping m: a table row; the kernel
/// rate counts only the time the GPU's kernels ran (the wall's rate adds the host's fills and summaries),
/// and on a GPU the host's part of the wall: its chunks' set-up, fills, waits for the GPU and deliveries
/// (SweepStatistics; its chunks of shadow runs included).
void run_row(const BenchScene& s, const BenchGpuOptions& options, const Mapping& m) {
  const auto scene = io::parse_scene_text(scene_text(s, options.device), "bench");
  const auto members = ensemble::plan_members(scene);
  const std::string label = mapping_label(m, scene, s.rows, options);
  try {
    const ensemble::GpuExecutor executor = options.device == "cpu" ? ensemble::GpuExecutor() : executor_of(m);
    const auto t0 = std::chrono::steady_clock::now();
    const auto outcome = ensemble::run_sweep(scene, members, {.threads = options.threads}, &executor);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    double attempts = 0;
    std::size_t ok = 0;
    for (const auto& r : outcome.results) {
      attempts += r.steps_accepted + r.steps_rejected;
      ok += r.status == kernels::LaneStatus::ok;
    }
    const double n = double(members.size());
    const double kernel = outcome.statistics.kernel_seconds;
    const std::string kernel_rate = kernel > 0 ? format_rate(s.rows * attempts / kernel) : "—";
    const auto& st = outcome.statistics;
    char host[96] = "—";
    if (kernel > 0)
      std::snprintf(host, sizeof host, "%.2f / %.2f / %.2f / %.2f", st.setup_seconds, st.fill_seconds,
                    st.wait_seconds, st.deliver_seconds);
    std::printf("| %d%s | %s%s | %s | %zu | %.2f | %.0f | %.3g | %.3g | %s | %s | %zu |\n", s.rows,
                s.dipolar ? " dipolar" : "", s.stepper, s.every_quadrature ? ", every quadrature" : "",
                label.c_str(), members.size(), wall, attempts / n, attempts / wall, s.rows * attempts / wall,
                kernel_rate.c_str(), host, ok);
  } catch (const std::runtime_error& e) {
    std::printf("| %d%s | %s%s | %s | %zu | — | — | — | — | — | — | (%s) |\n", s.rows,
                s.dipolar ? " dipolar" : "", s.stepper, s.every_quadrature ? ", every quadrature" : "",
                label.c_str(), members.size(), e.what());
  }
  std::fflush(stdout);
}

}  // namespace

int run_bench_gpu(const BenchGpuOptions& options) {
  if (options.device == "gpu" && !ensemble::gpu_info().available) {
    std::fprintf(stderr, "error: --device gpu: %s; run with --device cpu for this machine's figures\n",
                 ensemble::gpu_info().why.c_str());
    return 2;
  }
  const bool gpu = options.device == "gpu";
  std::printf("rotorsweep bench gpu: device %s, members × %.3g\n",
              gpu ? ensemble::gpu_info().name.c_str() : "cpu", options.scale);
  if (gpu) {  // the context's creation, outside the first row's wall time
    const auto t0 = std::chrono::steady_clock::now();
    ensemble::use_gpu();
    std::printf("CUDA context created in %.2f s (not in the rows' wall times)\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  // replicas scaled, at least one per A value
  const auto scaled = [&](BenchScene s) {
    s.replicas = std::max(1, int(std::lround(s.replicas * options.scale)));
    return s;
  };
  std::printf(
      "| N | stepper | mapping | members | wall s | attempts/member | member-attempts/s | rotor-attempts/s | "
      "kernel rotor-attempts/s | host s: set-up / fill / wait / deliver | ok |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  if (!options.curve_only) {
    for (const BenchScene s :
         {BenchScene{2, "rodas4", 1000, 100}, BenchScene{2, "rodas4p2", 1000, 100},
          BenchScene{20, "rodas4", 1000, 100}, BenchScene{20, "rodas5p", 1000, 100},
          BenchScene{20, "rodas4p2", 1000, 100}, BenchScene{20, "rodas4p2", 1000, 100, false, true},
          BenchScene{20, "dopri5", 1000, 100}, BenchScene{48, "rodas4p2", 250, 4, true},
          BenchScene{128, "rodas4", 1000, 20}, BenchScene{128, "rodas4p2", 1000, 20},
          BenchScene{1024, "rodas4p2", 250, 4}}) {
      if (std::find(options.rows.begin(), options.rows.end(), s.rows) == options.rows.end()) continue;
      const BenchScene row = scaled(s);
      const auto scene = io::parse_scene_text(scene_text(row, options.device), "bench");
      for (const Mapping& m : mappings_of(scene, row.rows, options)) run_row(row, options, m);
    }
  }
  if (options.curve || options.curve_only) {
    std::printf("whole friction curve: 1000 A × 1000 random starts (× %.3g), N = 20, rodas4, 4 periods\n",
                options.scale);
    run_row(scaled({20, "rodas4", 1000, 1000}), options, Mapping{});
    const bool per_thread = std::find(options.teams.begin(), options.teams.end(), 1) != options.teams.end();
    if (gpu && per_thread) run_row(scaled({20, "rodas4", 1000, 1000}), options, Mapping{1, ""});
  }
  return 0;
}

}  // namespace rotorsweep::apps
