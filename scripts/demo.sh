#!/usr/bin/env bash
# The demonstration from a bare Debian machine: install, build (the dev preset's executable and
# Python module only: this machine's instruction set, no GPU code), sweep the default scene
# (examples/friction_curve.toml), plot its friction curve with the quasi-static J(A) over it
# (results/friction_curve.{h5,png}) and draw the chamber map (results/chambers.png).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh dev rotorsweep rotorsweep_python
build/bin/rotorsweep run examples/friction_curve.toml -o results/friction_curve.h5
build/bin/rotorsweep info results/friction_curve.h5
/usr/bin/python3 scripts/plot_friction.py results/friction_curve.h5 results/friction_curve.png
build/bin/rotorsweep landscape chambers -o results/chambers.h5
build/bin/rotorsweep landscape curves -o results/curves.h5
/usr/bin/python3 scripts/plot_chambers.py results/chambers.h5 results/curves.h5 results/chambers.png
