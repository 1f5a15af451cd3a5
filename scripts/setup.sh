#!/usr/bin/env bash
# Quick start, step 1: installs the Debian packages, builds mpdem and runs the demo scene.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
./build/mpdem check examples/demo/scene.toml
./build/mpdem run examples/demo/scene.toml --output build/demo-output --overwrite
echo "demo output in build/demo-output (open particles.pvd and barriers.pvd in ParaView)"
