#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian 12 packages STRIELAD builds and tests with, only when missing.
# Usage: scripts/install-deps.sh [--tests]   (--tests adds Slurm, munge, real data and
# clang with libFuzzer and the sanitizer runtimes for scripts/fuzz.sh)
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config
  libhdf5-dev libnetcdf-dev netcdf-bin libgdal-dev libblosc-dev libzstd-dev libxxhash-dev libfpzip-dev
  libzfp-dev
  libproj-dev libeccodes-dev libopenvdb-dev libopenvdb-tools libboost-iostreams-dev libtbb-dev
  libcli11-dev libspdlog-dev libfmt-dev nlohmann-json3-dev libvtk9-dev
  libgtest-dev libgmock-dev
  libopenmpi-dev openmpi-bin
  libglfw3-dev libepoxy-dev libimgui-dev libstb-dev libegl-dev libegl-mesa0 libgl1-mesa-dri
)
if [[ "${1:-}" == "--tests" ]]; then
  packages+=(libncarg-data proj-bin slurm-wlm munge xvfb xauth gnuplot-nox
             clang libclang-rt-14-dev llvm)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi

echo "installing ${#missing[@]} missing packages: ${missing[*]}" >&2
sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "error: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
