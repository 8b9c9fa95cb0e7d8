#!/usr/bin/env bash
# The GPU backend's device checks and timings in one call, each step under its own time limit
# (docs/performance.md "GPU"): the register kernels against the host's emulation, the default mapping
# against the CPU, the other GPU tests, `bench gpu` per N and mapping (kernel-only and end-to-end
# rates; the team mappings, measured slower than a thread on 2026-11-22, with --teams 8 where wanted),
# the host's work per member on the device machine's cores (`bench host`, N = 2 and 20), the 10⁶-member
# curve as a run (its progress in the log) without and with its reruns, and the slider's 8 100-member scan.
# Usage: scripts/bench/gpu_session.sh [BIN (build/bin, from `scripts/build.sh gpu`)] [OUT ($OUT, or
# bench-results/gpu)]. Writes summary.txt (one line per step: exit code, seconds) and log.txt (every
# step's output, as it comes) to OUT, result files to a scratch folder it removes; prints each step's
# line as the step ends, so a session stopped early still shows what it measured. The limits add up
# to 415 s (a step that ignores its stop is killed 10 s later); on an H100 the register test took 18 s
# for twelve shapes (its host emulation then on one core), the mappings 25 s, the curve 11 s and the
# scan 22 s (docs/performance.md). test_gpu's hidden "[long]" cases (the examples against the CPU)
# are left to a session with time to spare: `test_gpu -d yes "[long]"`.
set -uo pipefail
cd "$(dirname "$0")/../.."
bin=$(realpath "${1:-build/bin}")
out=${2:-${OUT:-bench-results/gpu}}
mkdir -p "$out"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
: > "$out/summary.txt"
: > "$out/log.txt"

# step NAME LIMIT_SECONDS COMMAND...: runs COMMAND, its output into log.txt, a line into summary.txt and
# onto stdout.
step() {
  local name=$1 limit=$2
  shift 2
  echo "== $name: $*" >> "$out/log.txt"
  local start rc ms
  start=$(date +%s%N)
  timeout -k 10 "$limit" "$@" >> "$out/log.txt" 2>&1
  rc=$?
  ms=$((($(date +%s%N) - start) / 1000000))
  printf '%-22s exit %3d  %5d.%d s%s\n' "$name" "$rc" $((ms / 1000)) $((ms % 1000 / 100)) \
    "$([ "$rc" = 124 ] && echo "  (stopped at the ${limit} s limit)")" | tee -a "$out/summary.txt"
}

if command -v nvidia-smi > /dev/null; then
  nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm --format=csv >> "$out/log.txt" 2>&1
fi
step gpu_registers 30 "$bin/test_gpu" -d yes "[registers]"
step gpu_mappings 40 "$bin/test_gpu" -d yes "[mappings]"
step gpu_tests 90 "$bin/test_gpu" -d yes "~[registers]~[mappings]~[.]"
step bench_2_20 50 "$bin/rotorsweep" bench gpu --rows 2,20 --teams 1 --no-curve
step bench_128_1024 50 "$bin/rotorsweep" bench gpu --rows 128,1024 --teams 1,32 --scratch shared --no-curve \
  --scale 0.2
step bench_host 20 "$bin/rotorsweep" bench host --rows 2,20 --scratch "$scratch"
# the curve as its earlier figures measured it: no shadow runs or symmetry probes (with them a uniform
# scene takes a disordered register shape and runs its members' averaged periods again)
sed 's/^\[numerics\]$/[numerics]\nglobal_error = "local"/' examples/friction_curve_gpu.toml > "$scratch/curve.toml"
step curve_run 30 "$bin/rotorsweep" run "$scratch/curve.toml" -o "$scratch/curve.h5"
step curve_info 10 "$bin/rotorsweep" info "$scratch/curve.h5"
# the curve as the example runs it: shadow runs on the members that slip and symmetry probes on those that
# slip or end on a symmetric set (65 % more attempts on the CPU), every chunk on the disordered shape 8x3ds6b3
rm -f "$scratch/curve.h5"
step curve_reruns 45 "$bin/rotorsweep" run examples/friction_curve_gpu.toml -o "$scratch/curve.h5"
# the scan as its earlier figures measured it, without shadow runs (they add 2.4x: the members once more)
sed 's/^\[numerics\]$/[numerics]\nglobal_error = "local"/' examples/experiment_7x7_gpu.toml > "$scratch/slider.toml"
step slider_scan 40 "$bin/rotorsweep" slider "$scratch/slider.toml" -q -o "$scratch/slider.h5"
step slider_info 10 "$bin/rotorsweep" info "$scratch/slider.h5"
