#!/usr/bin/env bash
# Regenerates scripts/bench/reference.csv: the reference members at rtol 1e-12 with rotorsweep's
# rodas4 and with scipy's Radau (about 5 minutes for Radau on one core). Needs a built rotorsweep.
set -euo pipefail
cd "$(dirname "$0")/../.."
work=bench-results/reference
mkdir -p "$work"
build/bin/rotorsweep run scripts/bench/reference.toml -o "$work/rodas4_1e-12.h5" -q --threads 1
/usr/bin/python3 scripts/bench/peers.py "$work/rodas4_1e-12.h5" "$work/radau_1e-12.csv" \
  --methods Radau --rtols 1e-12 --atol 1e-14
/usr/bin/python3 scripts/bench/reference_table.py "$work/rodas4_1e-12.h5" "$work/radau_1e-12.csv" \
  scripts/bench/reference.csv
