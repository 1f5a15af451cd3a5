#!/usr/bin/env bash
# Rotating drum: builds the drum mesh and runs the scene. Usage: ./run.sh [path/to/mpdem]
set -euo pipefail
cd "$(dirname "$0")"
MPDEM=${1:-${MPDEM:-mpdem}}
# Closed cylinder of radius 50 mm, 20 mm long, about z, turned 90 deg about x: axis along y.
"$MPDEM" mesh cylinder --radius 0.05 --height 0.02 --segments 48 --closed --rotate-deg 90 0 0 -o drum.csv --group drum
"$MPDEM" run scene.toml --overwrite --threads "${THREADS:-1}"
