#!/usr/bin/env bash
# The demonstration from a bare Debian machine: install, build, reproduce the paper's table of
# dissipation integrals, and plot it (results/paper_table.csv, results/paper_table.png).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
mkdir -p results
build/bin/rotorsweep table -o results/paper_table.csv
/usr/bin/python3 scripts/plot_table.py results/paper_table.csv results/paper_table.png
