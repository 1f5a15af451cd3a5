#!/usr/bin/env bash
# Configures and builds mpdem (Release, with MPI: mpirun -np N build/mpdem run SCENE) into build/.
# Usage: scripts/build.sh [extra cmake args]  (-DMPDEM_MPI=OFF: the serial build)
set -euo pipefail
cd "$(dirname "$0")/.."
gen=()
command -v ninja >/dev/null 2>&1 && gen=(-G Ninja)
if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DMPDEM_MPI=ON "$@"
fi
cmake --build build -j "$(nproc)"
