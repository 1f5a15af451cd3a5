#!/usr/bin/env bash
# Case study 3: dry granular flow impacting a vertical rigid wall. Builds the slide, the wall and
# the particles, runs the scene and plots the wall force. Usage: ./run.sh [path/to/mpdem]
set -euo pipefail
cd "$(dirname "$0")"
MPDEM=${1:-${MPDEM:-mpdem}}
THREADS=${THREADS:-1}   # one thread: on a busy 2-core machine OpenMP threads wait on each other

# Slide: 0.35 m incline at 40 deg, arc of radius 0.1 m, 0.2 m horizontal run-out (x in [0, 0.2]),
# 80 mm wide with 80 mm side walls. The incline's upper end is at (-0.33239, 0.24837).
"$MPDEM" mesh chute --length 0.35 --angle 40 --transition-radius 0.1 --runout 0.2 --width 0.08 \
         --wall-height 0.08 -o slide.csv --group slide
# Vertical wall closing the run-out at x = 0.2, normal -x (towards the flow), 0.15 m high.
# Rect normal +z rotated -90 deg about y -> -x. Ids dropped so that they follow the slide's.
"$MPDEM" mesh rect --size 0.15 0.08 --rotate-deg 0 -90 0 --translate 0.2 0 0.075 -o wall_tmp.csv --group wall
cut -d, -f2- wall_tmp.csv > wall.csv
# Back wall closing the incline's upper end: normal down-slope (rotation 90 + 40 deg about y),
# centred 50 mm above the incline's top edge along the incline normal (sin 40, 0, cos 40).
"$MPDEM" mesh rect --size 0.1 0.08 --rotate-deg 0 130 0 --translate -0.30025 0 0.28667 -o back_tmp.csv --group backwall
cut -d, -f2- back_tmp.csv > backwall.csv
rm wall_tmp.csv back_tmp.csv
# Release box: 70 mm along the slope x 80 mm x 45 mm normal to it, its floor on the incline,
# floor centre 37 mm down-slope of the top edge (closed mesh used only as the generation region).
"$MPDEM" mesh box --size 0.07 0.08 0.045 --closed --rotate-deg 0 40 0 --translate -0.30405 0 0.22459 -o release_box.stl
"$MPDEM" generate -o particles.csv --region mesh --mesh release_box.stl --distribution uniform \
         --rmin 0.0018 --rmax 0.0022 --count 2000 --gap 0.0001 --seed 4 --material beads

SECONDS=0
"$MPDEM" run scene.toml --overwrite --threads "$THREADS"
echo "run: wall time ${SECONDS} s"
/usr/bin/python3 plot_wall_impact.py | tee results.txt
