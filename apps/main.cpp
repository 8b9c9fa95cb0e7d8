// Entry point of the rotorsweep command line: parses the subcommand and its options (CLI11).
// Bad options end with one message and exit code 2; any later failure with one message and exit code 1.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "apps/launcher/isa_choice.hpp"
#include "commands.hpp"
#include "ensemble/engine/instruction_set.hpp"
#include "kernels/steppers/stepper_list.hpp"

int main(int argc, char** argv) {
  using namespace rotorsweep::apps;
  CLI::App app{"rotorsweep: ensemble sweeper for magnetic rotor arrays over a magnetic substrate"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text(argv[0]));
  const auto own_isa = rotorsweep::ensemble::instruction_set().name;
  // a native build has no launcher to read ROTORSWEEP_ISA: a bad value is still an error, a good one
  // is said to have no effect
  if (const char* requested = std::getenv("ROTORSWEEP_ISA"); own_isa == "native" && requested && *requested) {
    const auto allowed = rotorsweep::launcher::allowed_requests();
    if (std::find(allowed.begin(), allowed.end(), requested) == allowed.end()) {
      std::string names;
      for (const auto& name : allowed) names += (names.empty() ? "" : ", ") + name;
      std::fprintf(stderr, "rotorsweep: ROTORSWEEP_ISA = '%s' is not an instruction set; allowed: %s\n",
                   requested, names.c_str());
      return 2;
    }
    if (std::string(requested) != "auto")
      std::fprintf(stderr,
                   "warning: ROTORSWEEP_ISA = '%s' has no effect: this build runs one instruction set "
                   "(-march=native)\n",
                   requested);
  }
  std::string isa = "auto";
  if (own_isa != "native")
    app.add_option(
           "--isa", isa,
           "Instruction set to run (auto: the widest this CPU runs); the rotorsweep launcher reads it, "
           "as it reads ROTORSWEEP_ISA")
        ->check(CLI::IsMember(rotorsweep::launcher::allowed_requests()))
        ->capture_default_str();
  const CLI::Validator finite(
      [](const std::string& text) {
        double x = 0;
        return CLI::detail::lexical_cast(text, x) && std::isfinite(x) ? std::string()
                                                                      : "must be a finite number";
      },
      "FINITE");
  const std::vector<std::string> steppers(rotorsweep::kernels::stepper_names.begin(),
                                          rotorsweep::kernels::stepper_names.end());

  TableOptions table;
  auto* table_cmd = app.add_subcommand(
      "table",
      "Reproduce the paper's table of dissipation integrals (N = 20, g = 0.0011, A = 1, 4, 6, 8, 11)");
  table_cmd->add_option("--stepper", table.stepper, "Stepper")
      ->check(CLI::IsMember(steppers))
      ->capture_default_str();
  table_cmd->add_option("--rtol", table.rtol, "Relative tolerance (atol = rtol/1000)")
      ->check(finite & CLI::Range(1e-14, 1e-2))
      ->capture_default_str();
  table_cmd
      ->add_option(
          "--estimator-rtol", table.estimator_rtol,
          "Tolerance of the run W and S come from (they do not steer the step: at 1e-9 they are off by "
          "up to 5e-4)")
      ->check(finite & CLI::Range(1e-14, 1e-2))
      ->capture_default_str();
  table_cmd
      ->add_option(
          "--replicas", table.replicas,
          "Noise draws of each CP entry for its spread, global error and symmetry-limited count (1: none)")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  const CLI::Validator seed_value(
      [](const std::string& text) {  // as a scene's seeds: 0 … 2⁶³ − 1, no sign, exponent or rounding
        const bool digits =
            !text.empty() && text.size() <= 19 && text.find_first_not_of("0123456789") == std::string::npos;
        return digits && std::stoull(text) <= std::uint64_t(INT64_MAX)
                   ? std::string()
                   : "must be an integer from 0 to 9223372036854775807";
      },
      "SEED");
  table_cmd->add_option("--seed", table.seed, "Seed of those draws")
      ->check(seed_value)
      ->capture_default_str();
  table_cmd
      ->add_option("--window", table.window,
                   "triangular: the paper's average over periods [tau, tau + 2 pi], tau in [4 pi, 6 pi]; "
                   "uniform: the mean of periods 3 and 4")
      ->check(CLI::IsMember({"triangular", "uniform"}))
      ->capture_default_str();
  table_cmd
      ->add_option(
          "--disorder", table.disorder,
          "sigma_A of a quenched disorder of the rows' substrate strength, A_j = A (1 + sigma xi_j): "
          "a physical symmetry breaking, so that the CP entries' errors are bounds (0: none)")
      ->check(finite & CLI::Range(0.0, 1.0))
      ->capture_default_str();
  table_cmd->add_option("--disorder-seed", table.disorder_seed, "Seed of the disorder's realizations")
      ->check(seed_value)
      ->capture_default_str();
  table_cmd->add_option("-o,--output", table.output, "Write the table as CSV to this file");
  table_cmd->add_flag("--force", table.force,
                      "Replace an existing file that is not a table this command wrote");

  // the scene, -o, --threads, -q and --force of a command that runs a scene file
  const auto add_scene_options = [](CLI::App* cmd, SceneCommandOptions& options, const char* scene_help,
                                    const char* force_help) {
    cmd->add_option("scene", options.scene, scene_help)->required();
    cmd->add_option("-o,--output", options.output, "Result file (overrides the scene's output.path)");
    cmd->add_option("--threads", options.threads, "OpenMP threads (default: all cores)")
        ->check(CLI::Range(1, 4096));
    cmd->add_flag("-q,--quiet", options.quiet, "No progress line");
    cmd->add_flag("--force", options.force, force_help);
  };
  // --resume and --shard of a command that streams its members into OUT.h5.partial
  const auto add_partial_options = [](CLI::App* cmd, bool& resume, std::string& shard) {
    cmd->add_flag("--resume", resume,
                  "Continue the run that stopped early (from OUT.h5.partial): same scene, same program");
    cmd->add_option("--shard", shard,
                    "Run part I of N of the plan (I/N; members I-1, I-1+N, ...); `merge` joins the parts");
  };
  RunOptions run;
  auto* run_cmd =
      app.add_subcommand("run", "Run the sweep a scene file describes and write its HDF5 result file");
  add_scene_options(run_cmd, run, "Scene file (TOML)",
                    "Replace an existing output file even if it is not an HDF5 file, or a partial file");
  add_partial_options(run_cmd, run.resume, run.shard);
  run_cmd
      ->add_option("--flush-seconds", run.flush_seconds,
                   "Write finished members to the file at least this often (seconds)")
      ->check(finite)  // CLI::Range lets NaN through (no comparison with it is true)
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  run_cmd
      ->add_option("--flush-members", run.flush_members,
                   "... and whenever this many finished members are waiting")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 30))
      ->capture_default_str();
  run_cmd->add_option("--device", run.device, "Where members run: cpu or gpu (overrides numerics.device)")
      ->check(CLI::IsMember({"cpu", "gpu"}));

  SliderOptions slider;
  auto* slider_cmd = app.add_subcommand(
      "slider", "Run the experiment's many-body slider over the separations a slider scene describes");
  add_scene_options(slider_cmd, slider, "Slider scene file (TOML)",
                    "Replace an existing output file even if it is not an HDF5 file, or a partial file");
  add_partial_options(slider_cmd, slider.resume, slider.shard);
  slider_cmd
      ->add_option("--device", slider.device, "Where members run: cpu or gpu (overrides numerics.device)")
      ->check(CLI::IsMember({"cpu", "gpu"}));

  InfoOptions info;
  MergeOptions merge;
  auto* merge_cmd =
      app.add_subcommand("merge", "Join the shard files of one plan (run --shard I/N) into one result file");
  merge_cmd->add_option("shards", merge.shards, "Shard files, in any order")->required();
  merge_cmd->add_option("-o,--output", merge.output, "Result file to write")->required();
  merge_cmd->add_flag("--force", merge.force,
                      "Replace an existing output file even if it is not an HDF5 file");
  merge_cmd->add_flag("-q,--quiet", merge.quiet, "No summary line (errors are still printed)");

  auto* info_cmd = app.add_subcommand("info", "Summarise a result file");
  info_cmd->add_option("file", info.file, "Result file (HDF5)")->required();
  info_cmd->add_flag("--scene", info.scene, "Also print the scene the file was made from");

  LandscapeOptions landscape;
  auto* landscape_cmd = app.add_subcommand(
      "landscape",
      "The two-angle energy landscape: chamber map, bifurcation curves, quasi-static friction J(A)");
  landscape_cmd->require_subcommand(1);
  const CLI::Validator row_length(
      [](const std::string& text) {
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        return text == "infinite" || (digits && text.size() < 10 && std::stoul(text) >= 1)
                   ? std::string()
                   : "must be a positive integer (rotors per row) or 'infinite'";
      },
      "L|infinite");
  const auto output_option = [&](CLI::App* cmd) {
    cmd->add_option("-o,--output", landscape.output, "HDF5 file to write")->required();
    cmd->add_flag("-q,--quiet", landscape.quiet, "No progress line");
    cmd->add_flag("--force", landscape.force,
                  "Replace an existing output file even if it is not an HDF5 file");
    auto* range =
        cmd->add_option("--range", landscape.range,
                        "Point-dipole rows up to M apart (docs/model.md §8); default: nearest neighbours")
            ->check(CLI::Range(std::size_t(1), std::size_t(100000)));
    cmd->add_option("--row-length", landscape.row_length, "Rotors per row for --range, or 'infinite'")
        ->check(row_length)
        ->needs(range)
        ->capture_default_str();
    cmd->add_option("--coefficients", landscape.coefficients, "The two-angle coefficients a, b, c themselves")
        ->expected(3)
        ->delimiter(',')
        ->check(finite)
        ->excludes(range);
  };
  auto* chambers_cmd = landscape_cmd->add_subcommand(
      "chambers", "Raster over (A, τ ∈ [0, π/2]): Morse signature, alignment classes, zones and chambers");
  output_option(chambers_cmd);
  chambers_cmd->add_option("--A-min", landscape.A_min, "Smallest A")->check(finite)->capture_default_str();
  chambers_cmd->add_option("--A-max", landscape.A_max, "Largest A")->check(finite)->capture_default_str();
  chambers_cmd->add_option("--A-cells", landscape.A_cells, "Cells along A")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  chambers_cmd->add_option("--tau-cells", landscape.tau_cells, "Cells along τ")
      ->check(CLI::Range(2, 100000))
      ->capture_default_str();
  chambers_cmd
      ->add_option("--min-zone-cells", landscape.min_zone_cells,
                   "Smallest component counted as a zone or chamber (0: max(10, cells/10^4))")
      ->check(CLI::Range(0, 1 << 30));
  auto* curves_cmd = landscape_cmd->add_subcommand(
      "curves", "The four bifurcation curves and the alignment curve, sampled and folded into τ ∈ [0, π/2]");
  output_option(curves_cmd);
  curves_cmd->add_option("--samples", landscape.samples, "Points per curve")
      ->check(CLI::Range(2, 10000000))
      ->capture_default_str();
  curves_cmd->add_option("--A-max", landscape.A_max, "Drop off-diagonal points above this A (> 0)")
      ->check(finite & CLI::PositiveNumber)
      ->capture_default_str();
  auto* jump_cmd = landscape_cmd->add_subcommand(
      "jump-friction", "Quasi-static CP friction J(A) on a uniform grid over [A_-, A_*]");
  output_option(jump_cmd);
  jump_cmd->add_option("--count", landscape.count, "Number of A values")
      ->check(CLI::Range(1, 100000000))
      ->capture_default_str();
  jump_cmd->add_option("--A-min", landscape.J_A_min, "Smallest A (default: A_-)")->check(finite);
  jump_cmd->add_option("--A-max", landscape.J_A_max, "Largest A (default: A_*)")->check(finite);

  CouplingsOptions couplings;
  auto* couplings_cmd = app.add_subcommand(
      "couplings",
      "Print the point-dipole coupling table a, b_u, c_u (docs/model.md §8) that a range of rows gives");
  couplings_cmd->add_option("--range", couplings.range, "Rows u = 1 .. M apart")
      ->check(CLI::Range(std::size_t(1), std::size_t(100000)))
      ->capture_default_str();
  couplings_cmd->add_option("--row-length", couplings.row_length, "Rotors per row, or 'infinite'")
      ->check(row_length)
      ->capture_default_str();
  couplings_cmd->add_option("-o,--output", couplings.output, "Also write the table as CSV to this file");
  couplings_cmd->add_flag("--force", couplings.force,
                          "Replace an existing file that is not a table this command wrote");

  auto* bench_cmd = app.add_subcommand("bench", "Measure speed");
  bench_cmd->require_subcommand(1);
  BenchKernelOptions bench;
  auto* kernels_cmd = bench_cmd->add_subcommand(
      "kernels", "RHS evaluations/s, the bare sincos bound, and steps/s per stepper, scalar and SIMD");
  kernels_cmd->add_option("--rows", bench.rows, "Rows N")->check(CLI::Range(2, 4096))->capture_default_str();
  kernels_cmd->add_option("--repeats", bench.repeats, "Timed repeats (the median is reported)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  BenchGpuOptions bench_gpu;
  auto* gpu_cmd = bench_cmd->add_subcommand(
      "gpu",
      "Step attempts/s per member and per rotor of whole sweeps on the GPU (N = 2, 20, 128, 1024, each "
      "stepper, a member per thread and per team) and a 10^6-member friction curve");
  gpu_cmd
      ->add_option("--device", bench_gpu.device,
                   "Where the sweeps run ('cpu': this machine's cores, for scale)")
      ->check(CLI::IsMember({"gpu", "cpu"}))
      ->capture_default_str();
  gpu_cmd->add_option("--scale", bench_gpu.scale, "Fraction of each scene's random starts to run")
      ->check(finite & CLI::Range(1e-6, 1.0))
      ->capture_default_str();
  gpu_cmd->add_option("--threads", bench_gpu.threads, "Host threads (0: OpenMP's default)")
      ->check(CLI::Range(0, 4096));
  gpu_cmd->add_flag("!--no-curve", bench_gpu.curve, "Skip the 10^6-member curve");
  gpu_cmd->add_flag("--curve-only", bench_gpu.curve_only, "Only the 10^6-member curve");
  gpu_cmd
      ->add_option("--rows", bench_gpu.rows,
                   "The scenes to measure, by N (48: dipolar open rows, as the slider's)")
      ->check(CLI::IsMember({2, 20, 48, 128, 1024}))
      ->delimiter(',')
      ->capture_default_str();
  gpu_cmd
      ->add_option(
          "--teams", bench_gpu.teams,
          "Threads per member to measure on the GPU (1: a member per thread; 2 … 32: a team of a warp)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32}))
      ->delimiter(',')
      ->capture_default_str();
  gpu_cmd->add_option("--scratch", bench_gpu.scratch, "Where a team's scratch lives: shared, global or both")
      ->check(CLI::IsMember({"shared", "global", "both"}))
      ->capture_default_str();
  BenchHostOptions bench_host;
  auto* host_cmd = bench_cmd->add_subcommand(
      "host",
      "The host's share of a GPU sweep per member, without a GPU: a chunk's fill, the members' summaries, "
      "and the result file's writes (the 10^6-member curve's scene)");
  host_cmd->add_option("--rows", bench_host.rows, "The scenes to measure, by N")
      ->check(CLI::Range(2, 4096))
      ->delimiter(',')
      ->capture_default_str();
  host_cmd->add_option("--members", bench_host.members, "Members per chunk (of the curve's 10^6)")
      ->check(CLI::Range(1, 1000000))
      ->capture_default_str();
  host_cmd->add_option("--threads", bench_host.threads, "Host threads (0: OpenMP's default)")
      ->check(CLI::Range(0, 4096));
  host_cmd->add_option("--repeats", bench_host.repeats, "Timed repeats (the median is reported)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  host_cmd->add_option("--scratch", bench_host.scratch, "Directory for the result file written and removed")
      ->check(CLI::ExistingDirectory)
      ->capture_default_str();

  try {
    app.parse(argc, argv);
    for (const auto* cmd :
         {run_cmd, slider_cmd, merge_cmd, table_cmd, chambers_cmd, curves_cmd, jump_cmd, couplings_cmd})
      if (cmd->parsed() && cmd->count("-o") > 0 && cmd->get_option("-o")->as<std::string>().empty())
        throw CLI::ValidationError("--output", "the output path is empty");
    if (isa != "auto" && isa != own_isa)
      throw CLI::ValidationError(
          "--isa", "this is rotorsweep-" + own_isa + "; the rotorsweep launcher runs " + "rotorsweep-" + isa);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  // a write beyond the file-size limit fails with EFBIG (and is reported) instead of killing us
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    if (*run_cmd) return run_sweep_command(run);
    if (*slider_cmd) return run_slider(slider);
    if (*merge_cmd) return run_merge(merge);
    if (*info_cmd) return run_info(info);
    if (*couplings_cmd) return run_couplings(couplings);
    if (*table_cmd) return run_table(table);
    if (*kernels_cmd) return run_bench_kernels(bench);
    if (*gpu_cmd) return run_bench_gpu(bench_gpu);
    if (*host_cmd) return run_bench_host(bench_host);
    if (*chambers_cmd) return run_landscape_chambers(landscape);
    if (*curves_cmd) return run_landscape_curves(landscape);
    if (*jump_cmd) return run_landscape_jump_friction(landscape);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 2;
}
