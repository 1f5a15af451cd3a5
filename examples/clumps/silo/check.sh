#!/usr/bin/env bash
# Short check of the silo example for the test suite (ctest -L examples, tests/CMakeLists.txt,
# Examples.ClumpSiloShort): the example's set-up scaled down to a silo 45 mm wide with a 24 mm
# orifice and 400 bodies of each shape (tetrahedral clumps, spheres of the same volume), the lid
# removed at 0.15 s, 0.4 s in all (20-40 s on one thread); silo_rate.py's measures, asserted by
# check_silo.py (tolerances and their reasons there).
# Usage: check.sh path/to/mpdem WORK_DIR      (python3 with the standard library only)
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
MPDEM=$1
WORK=$2
PY=${PYTHON:-python3}
L=0.045
D=0.024
T_OPEN=0.15
rm -rf "$WORK"
mkdir -p "$WORK"
cd "$WORK"
"$MPDEM" mesh box --size $L $L 0.25 -o walls_tmp.csv --group walls > /dev/null
awk -F, 'NR <= 2 || ($1 != 0 && $1 != 1)' walls_tmp.csv > walls.csv
"$MPDEM" mesh box --size 0.5 0.5 0.05 --translate 0 0 -0.1 -o catcher.csv --group catcher --first-id 2000 > /dev/null
"$MPDEM" mesh plate --size $L $L --hole-radius 0.012 --segments 48 -o floor_24.csv --group floor --first-id 100 > /dev/null
"$MPDEM" mesh rect --size $D $D -o lid_24.csv --group lid --first-id 1000 > /dev/null
SECONDS=0
for shape in tetra sphere; do
  "$PY" "$HERE/make_scene.py" $shape $D "$shape.toml" "output/$shape" --width $L --count 400 --height 0.07 \
    --t-open $T_OPEN --duration 0.4 > /dev/null
  "$MPDEM" run "$shape.toml" --overwrite --threads 1 --quiet
done
echo "silo check runs: wall time ${SECONDS} s"
"$PY" "$HERE/check_silo.py" $T_OPEN $L output/tetra output/sphere
