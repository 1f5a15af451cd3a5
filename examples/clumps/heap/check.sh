#!/usr/bin/env bash
# Short check of the heap example for the test suite (ctest -L examples, tests/CMakeLists.txt,
# Examples.ClumpHeapShort): the example's set-up scaled down to a disk of radius 20 mm and 150
# bodies of each shape (settled for 0.15 s, cylinder lifted at 0.15 m/s, 1 s in all; 30-40 s on
# one thread), then heap_angle.py's measures, asserted by check_heap.py (tolerances and their
# reasons there). RB, COUNT, HEIGHT, SETTLE, LIFT, DURATION and SEED override the set-up.
# Usage: check.sh path/to/mpdem WORK_DIR      (python3 with the standard library only)
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
MPDEM=$1
WORK=$2
PY=${PYTHON:-python3}
RB=${RB:-0.02}
rm -rf "$WORK"
mkdir -p "$WORK"
cd "$WORK"
"$MPDEM" mesh cylinder --radius $RB --height 0.08 --segments 64 -o cylinder.csv --group cylinder > /dev/null
"$MPDEM" mesh cylinder --radius $RB --height 0.08 --segments 64 -o cylinder_lift.csv --group cylinder --first-id 200 > /dev/null
"$MPDEM" mesh box --size 0.38 0.38 0.05 --translate 0 0 -0.06 -o floor.csv --group catcher --first-id 1000 > /dev/null
SECONDS=0
for shape in tetra sphere; do
  "$PY" "$HERE/make_scene.py" $shape "$shape.toml" "output/$shape" --rb $RB --count ${COUNT:-150} --height ${HEIGHT:-0.04} \
    --settle ${SETTLE:-0.15} --lift ${LIFT:-0.15} --duration ${DURATION:-1.0} --seed ${SEED:-1} > /dev/null
  "$MPDEM" run "$shape.toml" --overwrite --threads 1 --quiet
done
echo "heap check runs: wall time ${SECONDS} s"
"$PY" "$HERE/check_heap.py" $RB output/tetra output/sphere
