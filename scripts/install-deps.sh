#!/usr/bin/env bash
# Installs the Debian 12 packages Orogen needs, skipping those already present.
set -euo pipefail
packages=(build-essential cmake ninja-build pkg-config libgtest-dev libtomlplusplus-dev libcli11-dev
          libfmt-dev libspdlog-dev libhdf5-dev libcairo2-dev ffmpeg python3 python3-numpy
          python3-matplotlib python3-h5py python3-xarray python3-h5netcdf  # xarray: analysis.h5 from Python
          lammps  # lmp: the export test reads the LAMMPS data file with it, the benchmark (bench/lammps) runs it
          python3-scipy python3-pandas libopenmpi-dev openmpi-bin  # the MPI pair: optional, `orogen ensemble` under mpirun
          python3-paraview xvfb xauth  # the ParaView test (pvpython renders through X: xvfb-run)
          pybind11-dev python3-pybind11 python3-pytest  # the Python module `orogen` (docs/python.md) and its tests
          python3-pip python3-setuptools python3-wheel  # scripts/install-python.sh installs the package orogen
          chromium)  # the atlas's browser test (tests/browser: puppeteer-core drives this chromium)
# node and npm for that test: Debian's, unless a node of another origin (NodeSource's nodejs,
# which ships npm and conflicts with Debian's npm) is already there.
command -v node >/dev/null || packages+=(nodejs)
command -v npm >/dev/null || packages+=(npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "all packages present"
else
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: ${missing[*]}"
  $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
# The browser test's driver and the plotting library at the locked versions; puppeteer-core
# drives the chromium above, so it downloads no browser of its own.
cd "$(dirname "$0")/../tests/browser"
PUPPETEER_SKIP_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error ||
  echo "warning: npm ci in tests/browser failed: the test atlas_browser will fail (orogen report itself needs no npm)"
