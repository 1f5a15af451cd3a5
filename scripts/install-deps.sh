#!/usr/bin/env bash
# Installs the Debian 12 packages mpdem needs to build, test and plot.
# Idempotent: packages already present are skipped by apt-get.
set -euo pipefail
pkgs=(
  build-essential cmake ninja-build pkg-config
  libtomlplusplus-dev   # scene files (TOML)
  libcli11-dev          # command line
  libfmt-dev            # formatting
  libdeflate-dev        # compressed VTK output (zlib format)
  libgtest-dev libgmock-dev   # unit and physics tests
  libbenchmark-dev      # micro-benchmarks
  libopenmpi-dev openmpi-bin   # MPI domain decomposition (MPDEM_MPI, mpirun)
  clang-format clang-tidy libomp-dev   # scripts/lint.sh (Debian 12: version 14); omp.h for clang-tidy
  python3 python3-numpy python3-matplotlib python3-meshio   # plots; VTU read-back in tests
  python3-vtk9          # VTK's own reader of the VTU output, in tests (tests/read_vtu.py --vtk)
  python3-dev pybind11-dev python3-pytest   # the Python module (import mpdem) and its tests
)
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
echo "mpdem dependencies present."
