#!/bin/sh
# The dumbbell on the incline: mu = 0.3 (rolls) and 0.05 (slides), both integrators, then the
# plot and results.txt. Usage: examples/clumps/incline/run.sh [path/to/mpdem]
set -e
MPDEM=${1:-mpdem}
cd "$(dirname "$0")"
for integ in verlet trapezoidal; do
  for mu in 0.3 0.05; do
    out="output/${integ}_mu${mu}"
    rm -rf "$out"
    sed -e "s/@MU@/$mu/g" -e "s/@INTEGRATOR@/$integ/" -e "s#@OUT@#$out#" scene.toml.in > "scene_${integ}_mu${mu}.toml"
    "$MPDEM" run "scene_${integ}_mu${mu}.toml" --threads 1
  done
done
/usr/bin/python3 plot_incline.py
