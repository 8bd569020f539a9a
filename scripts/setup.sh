#!/usr/bin/env bash
# Installs the Debian packages Conforma needs, only those that are missing, then configures and builds.
# Usage: scripts/setup.sh [build-dir [cmake options...]]   (default: build; options after the Release default, so
# they may override it: scripts/sanitize.sh)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"
shift $(($# > 0 ? 1 : 0))
packages=(cmake g++ make pkg-config libeigen3-dev libboost-dev libsuitesparse-dev libfftw3-dev libceres-dev libgtest-dev libgmock-dev
          libbenchmark-dev nlohmann-json3-dev libcli11-dev libyaml-cpp-dev python3 python3-matplotlib
          python3-numpy python3-pytest pybind11-dev python3-dev python3-setuptools python3-wheel python3-pip
          python3-venv ccache libhdf5-dev python3-h5py python3-yaml python3-distributed)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing missing packages: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
jobs="$(nproc 2>/dev/null || echo 2)"
# ccache (when installed) lets the python_pip_install test's separate CMake build reuse this build's objects
launcher=()
if command -v ccache >/dev/null 2>&1; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" "$@" >/dev/null
cmake --build "$build" -j "$jobs"
