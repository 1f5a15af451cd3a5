#!/usr/bin/env bash
# Short check of the clump examples for the test suite (ctest -L examples, tests/CMakeLists.txt):
# the incline (a dumbbell rolling with mu = 0.3 and sliding with mu = 0.05, both integrators: the
# accelerations within 1e-3 of the closed forms, rolling without slip within 1e-3) and the
# T-handle (10 flips or more: the flip interval within 1 % of the Jacobi elliptic solution, |L| and
# the energy within 1e-6), exactly as the full examples, which are short. About 5 s on one thread.
#
# Usage: check.sh path/to/mpdem WORK_DIR      (python3 with the standard library only)
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
MPDEM=$1
WORK=$2
PY=${PYTHON:-python3}
rm -rf "$WORK"
mkdir -p "$WORK"
cp -r "$HERE/incline" "$HERE/t_handle" "$WORK/"
cd "$WORK/incline"
rm -rf output scene_*.toml
for integ in verlet trapezoidal; do
  for mu in 0.3 0.05; do
    sed -e "s/@MU@/$mu/g" -e "s/@INTEGRATOR@/$integ/" -e "s#@OUT@#output/${integ}_mu${mu}#" scene.toml.in > s.toml
    "$MPDEM" run s.toml --threads 1 --quiet
  done
done
"$PY" plot_incline.py --check
cd "$WORK/t_handle"
rm -rf output
"$MPDEM" run scene.toml --threads 1 --quiet
"$PY" plot_flip.py --check
