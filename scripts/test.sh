#!/usr/bin/env bash
# The whole test suite from a bare Debian machine: install what is missing, build the portable
# preset (every instruction set, the launcher, the GPU backend's device code where nvcc is), run ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh portable
ctest --test-dir build --output-on-failure -j"$(nproc)"
