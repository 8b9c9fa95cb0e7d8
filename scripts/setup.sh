#!/usr/bin/env bash
# Installs the Debian packages rotorsweep needs to build, test, run and plot (idempotent).
# Skips what is present; needs root (or sudo) only when something is missing. Extra packages
# (e.g. libsundials-dev for the benchmarks) may be given as arguments.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libxsimd-dev xtl-dev libhdf5-dev catch2 libtomlplusplus-dev libcli11-dev libfftw3-dev
  python3 python3-numpy python3-h5py python3-matplotlib python3-scipy python3-xarray python3-pytest
  python3-dev pybind11-dev python3-pybind11
  openmpi-bin libopenmpi-dev
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
# the package lists an image holds are tried first: an `apt-get update` costs a minute on a slow mirror
if ! "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" 2>/dev/null; then
  "${sudo_cmd[@]}" apt-get update -qq
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
