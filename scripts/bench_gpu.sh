#!/usr/bin/env bash
# GPU throughput of `rotorsweep run --device gpu` (docs/performance.md "GPU"): step attempts per second
# per member and per rotor (rows × attempts) for N = 2, 20, 128 and each stepper, and a whole
# 10^6-member N = 20 friction curve; with --cpu, the same scenes on this machine's cores for scale.
# Usage: scripts/bench_gpu.sh ROTORSWEEP OUT_DIR [--cpu] [--curve-only]
set -euo pipefail
exe=$1
out=$2
shift 2
device=gpu
curve_only=0
for a in "$@"; do
  case $a in
    --cpu) device=cpu ;;
    --curve-only) curve_only=1 ;;
    *) echo "unknown option $a" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"
python=${PYTHON:-python3}

# scene N STEPPER A_COUNT REPLICAS RTOL -> file
scene() {
  local file=$out/bench_N$1_$2_$3x$4.toml
  cat >"$file" <<TOML
[model]
rows = $1
[drive]
g = [0.01]
[sweep]
A = {from = 0.25, to = 16, count = $3}
[initial]
kinds = ["random"]
replicas = $4
[schedule]
relax_periods = 2
average_periods = 2
[numerics]
stepper = "$2"
rtol = $5
atol = 1e-9
device = "$device"
[output]
path = "${file%.toml}_$device.h5"
TOML
  echo "$file"
}

# report FILE.h5 N STEPPER: members, wall seconds, attempts/s per member and per rotor
report() {
  "$python" - "$1" "$2" "$3" <<'PY'
import sys, h5py, numpy as np
path, rows, stepper = sys.argv[1], int(sys.argv[2]), sys.argv[3]
with h5py.File(path, "r") as f:
    m = f["members"]
    attempts = float(np.sum(m["steps_accepted"][:]) + np.sum(m["steps_rejected"][:]))
    wall = float(f.attrs["wall_seconds"])
    device = f.attrs["device"]
    device = device.decode() if isinstance(device, bytes) else str(device)
    ok = int(np.sum(m["status"][:] == b"ok")) if m["status"].dtype.kind == "S" else -1
    n = m["status"].shape[0]
print(f"| {device} | {rows} | {stepper} | {n} | {wall:.2f} | {attempts / n:.0f} | {attempts / wall:.3g} | {rows * attempts / wall:.3g} | {ok} |")
PY
}

echo "| device | N | stepper | members | wall s | attempts/member | member-attempts/s | rotor-attempts/s | ok |"
echo "|---|---|---|---|---|---|---|---|---|"
if [ "$curve_only" = 0 ]; then
  for spec in "2 rodas4 1000 100" "20 rodas4 1000 100" "20 rodas5p 1000 100" "20 ros2 1000 100" \
              "20 rodas4p2 1000 100" "20 dopri5 1000 100" "128 rodas4 1000 20"; do
    set -- $spec
    [ "$device" = cpu ] && set -- "$1" "$2" "$3" $(( $4 / 50 > 0 ? $4 / 50 : 1 ))
    f=$(scene "$1" "$2" "$3" "$4" 1e-6)
    "$exe" run "$f" -q --force >/dev/null
    report "${f%.toml}_$device.h5" "$1" "$2"
  done
fi
# the whole curve: 1000 A × 1000 random starts, N = 20, 4 periods, rtol 1e-6
replicas=1000
[ "$device" = cpu ] && replicas=10
f=$(scene 20 rodas4 1000 $replicas 1e-6)
/usr/bin/env time -f "curve wall %e s (whole run: plan, GPU, summaries, HDF5)" "$exe" run "$f" -q --force >/dev/null
report "${f%.toml}_$device.h5" 20 rodas4
