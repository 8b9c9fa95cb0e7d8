#!/usr/bin/env bash
# Configures and builds rotorsweep (Release) into build/ with a preset of CMakePresets.json:
# scripts/build.sh [dev|portable|gpu] [target...]; the executable is build/bin/rotorsweep.
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-portable}"
shift || true
case "$preset" in
  dev | portable | gpu) ;;
  *)
    echo "scripts/build.sh: unknown preset '$preset'; allowed: dev, portable, gpu" >&2
    exit 2
    ;;
esac
# The presets use Ninja (scripts/setup.sh installs ninja-build); Makefiles where it is missing.
generator=Ninja
command -v ninja > /dev/null || generator="Unix Makefiles"
# build/ made by another generator cannot be reconfigured with this one
if [ -f build/CMakeCache.txt ] && ! grep -q "^CMAKE_GENERATOR:INTERNAL=$generator\$" build/CMakeCache.txt; then
  echo "build.sh: build/ was configured with another generator; configuring it afresh"
  rm -rf build/CMakeCache.txt build/CMakeFiles
fi
cmake --preset "$preset" -G "$generator"
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
