#!/usr/bin/env bash
# Quick start, step 2: builds mpdem and runs the whole test suite (ctest).
# Installs missing Debian packages first, so it also works on a fresh machine.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
cd build
# Tests run two at a time on few cores: idle OpenMP threads must sleep, not spin.
export OMP_WAIT_POLICY=passive
ctest --output-on-failure -j "$(nproc)" "$@"
