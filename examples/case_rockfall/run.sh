#!/usr/bin/env bash
# Case study 2: rockfall on a granular layer over a rigid plate. Builds the plate and walls,
# runs the four variants (bare plate, thin layer, thick layer, thick frictionless layer) and
# plots the plate forces. Usage:  ./run.sh [path/to/mpdem]   (default: mpdem on PATH)
set -euo pipefail
cd "$(dirname "$0")"
MPDEM=${1:-${MPDEM:-mpdem}}
THREADS=${THREADS:-1}   # one thread each: on a busy 2-core machine OpenMP threads wait on each other

# Plate: 0.14 x 0.14 m at z = 0, 4 x 4 cells (32 triangles), normal +z.
"$MPDEM" mesh rect --size 0.14 0.14 --divisions 4 4 -o plate.csv --group plate
# Side walls 60 mm high: an open box without its floor (the floor is the plate above); ids are
# dropped so that they continue after the plate's.
"$MPDEM" mesh box --size 0.14 0.14 0.06 -o walls_tmp.csv --group walls
{ echo "# 8 side-wall triangles of 'mpdem mesh box --size 0.14 0.14 0.06' (floor removed, ids dropped)"
  awk -F, '/^#/ {next} /^id/ {sub(/^id,/, ""); print; next}
           { if (!($4 == 0 && $7 == 0 && $10 == 0)) { sub(/^[^,]*,/, ""); print } }' walls_tmp.csv
} > walls.csv
rm walls_tmp.csv

for s in bare thin thick thick_frictionless; do
  echo "== $s"
  SECONDS=0
  "$MPDEM" run "$s.toml" --overwrite --threads "$THREADS"
  echo "$s: wall time ${SECONDS} s"
done
/usr/bin/python3 plot_rockfall.py | tee results.txt
