#!/usr/bin/env bash
# Case study 1: dry granular flow down the Hutter chute. Builds the geometry and the particles,
# runs the tilt test (effective basal friction angle) and the chute flow, and plots.
# Usage:  ./run.sh [path/to/mpdem]      (default: mpdem on PATH)
set -euo pipefail
cd "$(dirname "$0")"
MPDEM=${1:-${MPDEM:-mpdem}}
THREADS=${THREADS:-1}   # one thread: on a busy 2-core machine OpenMP threads wait on each other

# Chute: 0.6 m incline at 40 deg, circular transition of radius 0.2 m, 1.4 m horizontal run-out
# (x in [0, 1.4]), 0.1 m wide with 0.1 m side walls. Upper end of the incline: (-0.58818, 0.43246).
"$MPDEM" mesh chute --length 0.6 --angle 40 --transition-radius 0.2 --runout 1.4 --width 0.1 \
         --wall-height 0.1 -o chute.csv --group chute
# Back wall closing the incline's upper end: a 0.12 x 0.1 m rect whose normal (+z) is turned by
# 90 + 40 deg about y to point down the slope, centred 60 mm above the top edge along the incline
# normal (sin 40, 0, cos 40). The id column is dropped so that ids continue after the chute's.
"$MPDEM" mesh rect --size 0.12 0.1 --rotate-deg 0 130 0 --translate -0.54962 0 0.47843 -o backwall_tmp.csv --group backwall
cut -d, -f2- backwall_tmp.csv > backwall.csv
rm backwall_tmp.csv
# Release box (generation region only): 90 mm along the slope x 100 mm x 60 mm normal to it,
# floor on the incline, floor centre 47 mm down-slope of the top edge.
"$MPDEM" mesh box --size 0.09 0.1 0.06 --closed --rotate-deg 0 40 0 --translate -0.55218 0 0.40225 -o release_box.stl
"$MPDEM" generate -o particles.csv --region mesh --mesh release_box.stl --distribution uniform \
         --rmin 0.0018 --rmax 0.0022 --count 5000 --gap 0.0001 --seed 1 --material beads

# Tilt test: a thin block of the same beads on a floor of the same barrier material, gravity
# tilted by 50 deg (tilt_test.toml). Floor 0.8 x 0.1 m with 0.1 m walls.
"$MPDEM" mesh box --size 0.8 0.1 0.1 -o tilt_box.csv --group tilt_box
"$MPDEM" generate -o tilt_particles.csv --min -0.39 -0.05 0 --max -0.30 0.05 0.012 --distribution uniform \
         --rmin 0.0018 --rmax 0.0022 --solid-fraction 0.3 --gap 0.0001 --seed 2 --material beads

SECONDS=0
"$MPDEM" run tilt_test.toml --overwrite --threads "$THREADS"
echo "tilt test: wall time ${SECONDS} s"
SECONDS=0
"$MPDEM" run scene.toml --overwrite --threads "$THREADS"
echo "chute flow: wall time ${SECONDS} s"
/usr/bin/python3 plot_hutter.py | tee results.txt
