#!/usr/bin/env bash
# Discharge of a flat-bottomed silo: tetrahedral clumps against spheres of the same volume
# (examples/clumps/silo). For each orifice diameter D0 and shape, make_scene.py writes the scene
# and `mpdem run` fills the silo (generated bodies settle on a lid over the orifice), removes the
# lid at T_OPEN and lets the bodies fall onto a floor 0.1 m below; plot_silo.py measures the
# discharge rates (silo_rate.py), writes silo.png and prints results.txt.
# Usage: ./run.sh [path/to/mpdem]      (default: $MPDEM, else mpdem on PATH; THREADS overrides 1;
#        DS and SEEDS override the orifice diameters and the fills' seeds)
set -euo pipefail
cd "$(dirname "$0")"
MPDEM=${1:-${MPDEM:-mpdem}}
THREADS=${THREADS:-1}   # one thread: on a busy 2-core machine OpenMP threads wait on each other
PY=/usr/bin/python3     # with numpy and matplotlib
L=0.06                  # m, silo width (square)
DS=${DS:-"0.024 0.03"}  # m, orifice diameters
SEEDS=${SEEDS:-"1 2"}   # fills per shape and orifice (generator seeds)
COUNT=2000              # bodies of each shape
T_OPEN=0.4              # s
DURATION=0.9            # s
T0=$(date +%s)

"$MPDEM" mesh box --size $L $L 0.25 -o walls_tmp.csv --group walls
awk -F, 'NR <= 2 || ($1 != 0 && $1 != 1)' walls_tmp.csv > walls.csv   # without the box's floor
rm walls_tmp.csv
"$MPDEM" mesh box --size 0.5 0.5 0.05 --translate 0 0 -0.1 -o catcher.csv --group catcher --first-id 2000   # open box: spheres roll
: > times.txt
RUNS=()
for D in $DS; do
  N=$("$PY" -c "print(round($D * 1e3))")
  "$MPDEM" mesh plate --size $L $L --hole-radius "$("$PY" -c "print($D / 2)")" --segments 48 -o "floor_$N.csv" \
    --group floor --first-id 100
  "$MPDEM" mesh rect --size $D $D -o "lid_$N.csv" --group lid --first-id 1000
  for SEED in $SEEDS; do
    for shape in tetra sphere; do
      NAME=${shape}_${N}_s$SEED
      "$PY" make_scene.py $shape $D "scene_$NAME.toml" "output/$NAME" --width $L --count $COUNT \
        --t-open $T_OPEN --duration $DURATION --seed $SEED
      SECONDS=0
      nice -n 5 "$MPDEM" run "scene_$NAME.toml" --overwrite --threads "$THREADS"
      echo "$NAME: $SECONDS" | tee -a times.txt
      RUNS+=("output/$NAME:$shape:$D")
    done
  done
done
"$PY" plot_silo.py --t-open $T_OPEN --width $L times.txt "${RUNS[@]}" | tee results.txt
echo "run.sh: total wall time $(( $(date +%s) - T0 )) s"
