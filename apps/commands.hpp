// The subcommands of the rotorsweep command line and their options.
// Each returns the process exit code.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::apps {

struct TableOptions {
  std::string stepper = std::string(kernels::default_stepper_name);
  double rtol = 1e-9;
  double estimator_rtol = 1e-12;  ///< W and S come from a run at this tolerance
  double disorder = 0;            ///< σ_A of a quenched disorder of the rows' substrate strength (0: none)
  std::uint64_t disorder_seed = 1;  ///< the seed of its realizations (draw r takes realization r)
  int replicas = 8;               ///< noise draws of each CP entry for its spread (1: none)
  std::uint64_t seed = 1;         ///< their seed
  std::string output;             ///< CSV path; empty: stdout only
  bool force = false;             ///< replace an existing file that is not a table CSV of this command
  /// "triangular": the paper's window, every period [τ, τ + 2π] with τ in [4π, 6π] averaged
  /// (docs/model.md §3); "uniform": the plain mean of periods 3 and 4
  std::string window = "triangular";
};
int run_table(const TableOptions& options);

struct BenchKernelOptions {
  int rows = 20;
  int repeats = 5;
};
int run_bench_kernels(const BenchKernelOptions& options);

struct BenchGpuOptions {
  std::string device = "gpu";  ///< "gpu", or "cpu" for this machine's figures beside
  double scale = 1;            ///< fraction of each scene's replicas to run (at least one per A)
  int threads = 0;             ///< host threads (OpenMP's default: 0)
  bool curve = true;           ///< also the 10⁶-member friction curve
  bool curve_only = false;
  std::vector<int> rows{2, 20, 48, 128, 1024};               ///< the scenes' N to measure (48: dipolar)
  std::vector<int> teams{1, 2, 4, 8, 16, 32};                ///< threads per member to measure on the GPU
  std::string scratch = "both";                              ///< a team's scratch: shared, global or both
};
int run_bench_gpu(const BenchGpuOptions& options);

struct BenchHostOptions {
  std::vector<int> rows{2, 20, 128};  ///< the scenes' N
  int members = 65536;  ///< a chunk of the GPU path (run_chunks' smallest)
  int threads = 0;      ///< host threads (0: OMP_NUM_THREADS, else every core)
  int repeats = 3;
  std::string scratch = "/tmp";  ///< where the result file is written, and removed
};
int run_bench_host(const BenchHostOptions& options);

/// What every command that runs a scene file takes.
struct SceneCommandOptions {
  std::string scene;
  std::string output;  ///< overrides the scene's output.path
  int threads = 0;     ///< 0: OpenMP's default
  bool quiet = false;  ///< no progress line
  bool force = false;  ///< replace an existing file that is not an HDF5 file
};

struct RunOptions : SceneCommandOptions {
  std::string shard;                 ///< "I/N": run part I of N of the plan (ensemble::shard_members)
  bool resume = false;               ///< continue from OUTPUT.partial, left by an interrupted run
  double flush_seconds = 5;          ///< finished members go to the file at least this often ...
  std::size_t flush_members = 4096;  ///< ... and whenever this many are waiting
  std::string device;                ///< "cpu" or "gpu": overrides numerics.device; empty: the scene's
};
int run_sweep_command(const RunOptions& options);

struct SliderOptions : SceneCommandOptions {
  std::string shard;    ///< "I/N": run part I of N of the plan; `merge` joins the parts
  bool resume = false;  ///< continue from OUTPUT.partial, left by a scan that stopped early
  std::string device;   ///< "cpu" or "gpu": overrides numerics.device; empty: the scene's
};
int run_slider(const SliderOptions& options);

struct MergeOptions {
  std::vector<std::string> shards;
  std::string output;
  bool force = false;
  bool quiet = false;  ///< no summary line
};
int run_merge(const MergeOptions& options);

/// Rotors per row from "infinite" (0) or a positive integer (checked by the command line).
std::size_t row_length_value(const std::string& text);

struct CouplingsOptions {
  std::size_t range = 1;                ///< rows u = 1 .. range
  std::string row_length = "infinite";  ///< rotors per row, or "infinite"
  std::string output;                   ///< CSV path; empty: stdout only
  bool force = false;                   ///< replace an existing file that is not a couplings CSV
};
int run_couplings(const CouplingsOptions& options);

struct InfoOptions {
  std::string file;
  bool scene = false;  ///< also print the scene text
};
int run_info(const InfoOptions& options);

struct LandscapeOptions {
  std::string output;
  bool quiet = false;
  bool force = false;  ///< replace an existing output file even if it is not an HDF5 file
  // whose landscape: nearest neighbours, point-dipole rows (range, row length) or (a, b, c) given
  std::size_t range = 0;  ///< 0: nearest neighbours
  std::string row_length = "infinite";
  std::vector<double> coefficients;  ///< a, b, c; empty: from range
  // chambers
  double A_min = 0, A_max = 12;
  int A_cells = 400, tau_cells = 300;
  int min_zone_cells = 0;  ///< 0: max(10, cells / 10⁴)
  // curves
  int samples = 2000;
  // jump-friction
  int count = 1000;
  double J_A_min = 0, J_A_max = 0;  ///< A grid of jump-friction; both 0: [A_-, A_*]
};
int run_landscape_chambers(const LandscapeOptions& options);
int run_landscape_curves(const LandscapeOptions& options);
int run_landscape_jump_friction(const LandscapeOptions& options);

/// The text of `rotorsweep --version` (program, instruction set, the sets built and runnable).
std::string version_text(const char* argv0);

}  // namespace rotorsweep::apps
