#!/usr/bin/env bash
# Periodic inclined chute flow (Silbert et al. 2001; LAMMPS in.chute): writes the particles (a
# rough base of fixed spheres and a loose lattice above it), runs the flow to a steady state and
# fits Bagnold's law to the velocity profile.
# Usage:  ./run.sh [path/to/mpdem]      (default: mpdem on PATH)
set -euo pipefail
cd "$(dirname "$0")"
MPDEM=${1:-${MPDEM:-mpdem}}
THREADS=${THREADS:-1}   # one thread: on a busy 2-core machine OpenMP threads wait on each other
PY=/usr/bin/python3     # Debian's, with python3-numpy and python3-matplotlib

SECONDS=0
# Base: 86 spheres at random in a 0.6 d slab (L_x = 10.5 d, L_y = 10.91 d, the periods of scene.toml);
# flow: 9 x 9 x 62 lattice sites = 5022 spheres (about 41 d deep once settled; top layer at
# z = 72 mm, below the domain top at 100 mm), started with v_x = 1.6 m/s [1 - (1 - k/62)^1.5] in
# layer k, a guess of the steady profile (Bagnold scaling of the 22 d run's profile).
"$PY" make_particles.py --nx 10 --ny 12 --layers 62 --seed 1 --base random --v-surface 1.6 --out particles.csv
"$MPDEM" check scene.toml
nice -n 5 "$MPDEM" run scene.toml --overwrite --threads "$THREADS"
echo "chute flow: wall time ${SECONDS} s"
"$PY" plot_chute.py | tee results.txt
