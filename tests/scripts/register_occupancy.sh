#!/usr/bin/env bash
# The register kernels' occupancy from their machine code: compiles tests/device/register_occupancy.cu
# for sm_90 with ptxas's resource report, and checks that the kernel bounded to 3 blocks of 128 threads
# per SM (8x3s6b3) fits 168 registers, so that 12 warps stay resident, against the unbounded kernel's
# fewer; prints registers, stack frame, spills and resident warps per SM for both.
# Usage: register_occupancy.sh NVCC SOURCE_DIR SCRATCH_DIR
set -euo pipefail
nvcc=$1 source=$2 scratch=$3
mkdir -p "$scratch"
report=$("$nvcc" -std=c++20 -arch=sm_90 --expt-relaxed-constexpr --fmad=false -Xcompiler=-ffp-contract=off \
  -O3 -DNDEBUG --resource-usage -I"$source" -c "$source/tests/device/register_occupancy.cu" \
  -o "$scratch/register_occupancy.o" 2>&1)
# one line per kernel: name registers stack spill-stores spill-loads
summary=$(awk '
  /Compiling entry function/ { kernel = ($0 ~ /bounded/) ? "bounded" : "unbounded" }
  /bytes stack frame/ && kernel != "" { stack = $1; stores = $5; loads = $9 }
  /Used [0-9]+ registers/ && kernel != "" {
    for (i = 1; i <= NF; ++i) if ($i == "Used") registers = $(i + 1)
    print kernel, registers, stack, stores, loads; kernel = ""
  }' <<< "$report")
[ "$(wc -l <<< "$summary")" -eq 2 ] || { echo "$report"; echo "expected two kernels' reports" >&2; exit 1; }
status=0
while read -r kernel registers stack stores loads; do
  # an SM holds 65 536 registers, allocated per warp in units of 256 (8 per thread)
  per_thread=$(( (registers + 7) / 8 * 8 ))
  warps=$(( 65536 / (per_thread * 32) ))
  [ "$warps" -gt 64 ] && warps=64
  printf '8x3s6 %-9s %3d registers, %4d B stack frame, %4d / %4d B spill stores / loads, %2d warps per SM\n' \
    "$kernel" "$registers" "$stack" "$stores" "$loads" "$warps"
  if [ "$kernel" = bounded ] && [ "$warps" -lt 12 ]; then
    echo "the bounded kernel keeps $warps warps resident, fewer than its bound's 12" >&2
    status=1
  fi
  if [ "$kernel" = unbounded ] && [ "$warps" -ge 12 ]; then
    echo "the unbounded kernel already keeps $warps warps: the bound no longer buys occupancy" >&2
    status=1
  fi
done <<< "$summary"
exit $status
