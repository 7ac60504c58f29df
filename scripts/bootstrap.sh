#!/usr/bin/env bash
# Idempotent set-up for a fresh Debian 12 machine (run as root, or with sudo available):
# installs the Debian packages coldblast needs if any is missing, configures a Release
# build in ./build (with MPI ensembles) and builds it. Fast when everything is already there.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${COLDBLAST_BUILD_DIR:-$here/build}

packages=(build-essential cmake git pkg-config
          libsundials-dev libgsl-dev libeigen3-dev libboost-dev libhwy-dev
          catch2 libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
          libbenchmark-dev gnuplot-nox poppler-utils openmpi-bin libopenmpi-dev clang-format universal-ctags
          python3-dev pybind11-dev python3-numpy python3-pandas python3-pytest python3-matplotlib python3-ase python3-gsd python3-tqdm
          python3-venv python3-wheel)  # the pip route's test: a venv (its pip and setuptools) + wheel's bdist_wheel
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "bootstrap: installing ${missing[*]}" >&2
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

# MPI ensembles (docs/cluster.md) are built and tested; a build/ configured earlier without them
# is reconfigured with the option.
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCOLDBLAST_MPI=ON >&2
elif ! grep -q "^COLDBLAST_MPI:BOOL=ON" "$build/CMakeCache.txt"; then
  cmake -S "$here" -B "$build" -DCOLDBLAST_MPI=ON >&2
fi
cmake --build "$build" -j"$(nproc)" >&2
