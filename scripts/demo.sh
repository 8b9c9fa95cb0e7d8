#!/usr/bin/env bash
# The demonstration from a bare Debian machine: install, build, sweep the default scene
# (examples/friction_curve.toml) and plot its friction curve (results/friction_curve.{h5,png}).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
build/bin/rotorsweep run examples/friction_curve.toml -o results/friction_curve.h5
build/bin/rotorsweep info results/friction_curve.h5
/usr/bin/python3 scripts/plot_friction.py results/friction_curve.h5 results/friction_curve.png
