#!/usr/bin/env bash
# Builds mpdem with AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/, -O1)
# and runs the whole test suite under them. Built without MPI (Open MPI's own allocations would
# read as leaks): this is also CI's serial build. Without the Python module: a sanitized extension
# would need the sanitizer runtime preloaded into the interpreter.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
gen=()
command -v ninja >/dev/null 2>&1 && gen=(-G Ninja)
if [ ! -f build-asan/CMakeCache.txt ]; then
  # -O1 without debug info: quick to build, and fast enough for the suite under the sanitizers.
  cmake -S . -B build-asan "${gen[@]}" -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O1" -DMPDEM_SANITIZE=ON -DMPDEM_BUILD_BENCH=OFF -DMPDEM_MPI=OFF -DMPDEM_PYTHON=OFF
fi
cmake --build build-asan -j "$(nproc)"
cd build-asan
export OMP_WAIT_POLICY=passive
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --output-on-failure -j "$(nproc)" "$@"
