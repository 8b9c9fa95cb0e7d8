#!/usr/bin/env bash
# The numerical-stability study behind docs/stability.md "Numerical stability": the stress
# scene, the quasi-static limit g → 0 and the tolerance sweep, then a summary of all three.
set -euo pipefail
cd "$(dirname "$0")/../.."
[ -x build/bin/rotorsweep ] || scripts/build.sh
mkdir -p results
build/bin/rotorsweep run examples/stress.toml -o results/stress.h5
build/bin/rotorsweep run scripts/stress/g_to_zero.toml -o results/stress_g_to_zero.h5
build/bin/rotorsweep run scripts/stress/tolerance.toml -o results/stress_tolerance.h5
/usr/bin/python3 scripts/stress/summarize_stress.py results
