#!/usr/bin/env bash
# Angle of repose of tetrahedral clumps against spheres of the same volume (examples/clumps/heap):
# for each shape, make_scene.py writes the scene, `mpdem run` settles the bodies in a cylinder on a
# rough disk, lifts the cylinder and lets the heap come to rest; plot_heap.py measures the angles,
# writes heap.png and prints results.txt.
# Usage: ./run.sh [path/to/mpdem]      (default: $MPDEM, else mpdem on PATH; THREADS overrides 1)
set -euo pipefail
cd "$(dirname "$0")"
MPDEM=${1:-${MPDEM:-mpdem}}
THREADS=${THREADS:-1}   # one thread: on a busy 2-core machine OpenMP threads wait on each other
PY=/usr/bin/python3     # with numpy and matplotlib
RB=0.036                # m, radius of the disk and of the cylinder
COUNT=880               # bodies of each shape
T0=$(date +%s)

"$MPDEM" mesh cylinder --radius $RB --height 0.12 --segments 64 -o cylinder.csv --group cylinder
"$MPDEM" mesh cylinder --radius $RB --height 0.12 --segments 64 -o cylinder_lift.csv --group cylinder --first-id 200
"$MPDEM" mesh box --size 0.38 0.38 0.05 --translate 0 0 -0.06 -o floor.csv --group catcher --first-id 1000
: > times.txt
for shape in tetra sphere; do
  "$PY" make_scene.py $shape "scene_$shape.toml" "output/$shape" --rb $RB --count $COUNT --duration 1.6
  SECONDS=0
  nice -n 5 "$MPDEM" run "scene_$shape.toml" --overwrite --threads "$THREADS"
  echo "$shape: $SECONDS" | tee -a times.txt
done
"$PY" plot_heap.py $RB times.txt output/tetra:tetra output/sphere:sphere | tee results.txt
echo "run.sh: total wall time $(( $(date +%s) - T0 )) s"
