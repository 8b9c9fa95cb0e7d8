#!/usr/bin/env bash
# The benchmark harness end to end on a few members (no timing is checked): our steppers and
# scipy's Radau from the same starts both land near the stored reference, and the report is written;
# the error calibration of D on a few members: rodas5p's reported error bounds its actual error; the
# slider's scaling benchmark on small sizes draws its figure and gives both solvers' friction alike.
# Usage: bench_smoke.sh ROTORSWEEP SOURCE_DIR SCRATCH_DIR
set -euo pipefail
rs=$1 src=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
py=/usr/bin/python3
$py "$src/scripts/bench/ours.py" "$rs" "$src/scripts/bench/reference.toml" "$work/ours.csv" \
  --ladder rodas4p2:1e-7 rodas4:1e-7 --repeats 1 --workdir "$work/ours" > /dev/null
$py "$src/scripts/bench/peers.py" "$work/ours/rodas4p2_1e-07.h5" "$work/radau.csv" --methods Radau \
  --rtols 1e-7 --members 0,1,33 > /dev/null
$py "$src/scripts/bench/work_precision.py" "$src/scripts/bench/reference.csv" "$work/report" \
  "$work/ours.csv" "$work/radau.csv" > /dev/null
test -s "$work/report/work_precision.png"
$py - "$work/report/work_precision.csv" <<'CHECK'
import csv, sys
rows = {r["method"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert set(rows) == {"rodas4", "rodas4p2", "Radau"}, rows.keys()
for method, bound in (("rodas4", 1e-3), ("rodas4p2", 1e-3), ("Radau", 3e-6)):
    error = float(rows[method]["median_error"])
    assert error < bound, f"{method}: median error {error} against the reference"
print("bench harness ok:", {m: float(r["median_error"]) for m, r in rows.items()})
CHECK
$py "$src/scripts/bench/error_calibration.py" --rotorsweep "$rs" --workdir "$work/calibration" --count 4 \
  --steppers rodas5p > "$work/calibration.md"
$py - "$work/calibration.md" <<'CHECK'
import sys
rows = [line.split("|")[1:-1] for line in open(sys.argv[1]) if line.startswith("| rodas5p")]
assert len(rows) == 6, rows
for row in rows:
    ratio, missed = float(row[5]), int(row[8])
    assert ratio <= 1 and missed == 0, f"rodas5p at g {row[1]}, rtol {row[2]}: max ratio {ratio}, {missed} missed"
print("error calibration ok:", [float(r[5]) for r in rows])
CHECK
$py "$src/scripts/bench/slider_scaling.py" --rotorsweep "$rs" --repeats 1 --dense 4,8 --krylov 4,8 \
  --out "$work/scaling" --png "$work/scaling.png" > "$work/scaling.txt"
test -s "$work/scaling.png"
$py - "$work/scaling.txt" <<'CHECK'
import sys
gaps = [abs(float(line.split("= ")[-1])) for line in open(sys.argv[1]) if "krylov's friction over dense's" in line]
assert len(gaps) == 2 and max(gaps) < 1e-6, gaps
print("slider scaling ok:", gaps)
CHECK
