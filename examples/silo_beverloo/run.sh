#!/usr/bin/env bash
# Silo discharge through a square orifice in a flat floor: Beverloo's law W = C rho_b sqrt(g) (D0 - k d)^(5/2).
# Usage:  ./run.sh [path/to/mpdem]      (default: $MPDEM, else mpdem on PATH; THREADS overrides 1)
# 1. fill: an [[inlet]] rains 20 000 beads into the closed silo (solid floor), which then settles;
# 2. one discharge run per orifice side D0, each seeded with the settled fill (last particle CSV
#    snapshot): the floor is a plate with a D0 x D0 hole closed by a lid (active = [0, T_OPEN]),
#    the beads leave through the hole into a [[sink]] 4 bead diameters below the floor;
# 3. plot_silo.py: W from the sink's log columns, the Beverloo fit, results.txt, silo_beverloo.png.
set -euo pipefail
cd "$(dirname "$0")"
MPDEM=${1:-${MPDEM:-mpdem}}
THREADS=${THREADS:-1}   # one thread: on a busy 2-core machine OpenMP threads wait on each other
PY=/usr/bin/python3     # with numpy and matplotlib
T0=$(date +%s)

L=0.14                  # m, silo width (square, x and y in [-L/2, L/2]); walls 0.25 m high
DT=1.7e-5               # s
NFILL=${NFILL:-20000}             # beads, radius uniform in [2.25, 2.75] mm (mean diameter d = 5 mm)
T_FEED=${T_FEED:-0.5}              # s, the inlet inserts NFILL beads in [0, T_FEED] ...
T_FILL=${T_FILL:-0.8}              # s, ... and the bed settles until T_FILL
T_OPEN=0.03             # s, discharge runs: the lid (re)settles the seeded bed, then opens at T_OPEN
T_DIS=${T_DIS:-0.6}               # s of discharge after T_OPEN
DS=${DS:-"0.0275 0.035 0.0425 0.05 0.0575"}   # m, orifice sides D0 = 5.5, 7, 8.5, 10, 11.5 d

calc() { "$PY" -c "from math import *; print(repr($1))"; }
scene() {  # scene FILE WHAT DURATION FLOOR PARTICLES INLET OUTDIR CSVEVERY
  "$PY" - "$@" <<'PYEOF'
import sys
f, what, dur, floor, parts, inlet, out, csv = sys.argv[1:9]
t = open("silo.toml.in").read()
for k, v in {"WHAT": what, "DURATION": dur, "DT": "@DT@", "FLOOR": floor, "PARTICLES": parts,
             "INLET": inlet, "OUTDIR": out, "CSVEVERY": csv}.items():
    t = t.replace("@" + k + "@", v)
open(f, "w").write(t)
PYEOF
  sed -i "s|@DT@|$DT|" "$1"
}

# Side walls: the open box of mpdem mesh without its two floor triangles (ids 0 and 1).
"$MPDEM" mesh box --size $L $L 0.25 -o walls_tmp.csv --group walls
awk -F, 'NR <= 2 || ($1 != 0 && $1 != 1)' walls_tmp.csv > walls.csv
rm walls_tmp.csv
"$MPDEM" mesh rect --size $L $L -o floor_solid.csv --group floor --first-id 100

mkdir -p output
: > output/runs.txt
: > output/times.txt

# 1. Fill and settle.
H=$(calc "$L/2-0.003")
INLET="[[inlet]]
name = \"feed\"
region = \"box\"
min = [-$H, -$H, 0.125]
max = [$H, $H, 0.175]
count_rate = $(calc "$NFILL/$T_FEED")   # 1/s
start = 0.0
end = $T_FEED
radius = { distribution = \"uniform\", min = 0.00225, max = 0.00275 }
material = \"beads\"
velocity = [0.0, 0.0, -0.5]
seed = 1
"
FLOOR="[[barriers]]
file = \"floor_solid.csv\"   # closed floor while filling
material = \"beads\"
"
scene scene_fill.toml "Fill: the inlet rains $NFILL beads in; they settle on the closed floor." \
      "$T_FILL" "$FLOOR" "" "$INLET" output/fill "$T_FILL"
SECONDS=0
nice -n 5 "$MPDEM" run scene_fill.toml --overwrite --threads "$THREADS"
echo "fill: $NFILL beads in $T_FEED s, settled until $T_FILL s, wall time ${SECONDS} s" | tee -a output/times.txt
"$PY" restart.py output/fill restart.csv

# 2. Discharge through each orifice.
for D in $DS; do
  NAME=d$(calc "round($D*1e4)")
  "$MPDEM" mesh plate --size $L $L --hole-size $D $D -o "floor_$NAME.csv" --group floor --first-id 100
  "$MPDEM" mesh rect --size $D $D -o "lid_$NAME.csv" --group lid --first-id 200
  FLOOR="[[barriers]]
file = \"floor_$NAME.csv\"   # plate with a $D m square hole
material = \"beads\"

[[barriers]]
file = \"lid_$NAME.csv\"     # the lid closing the hole, flush with the plate, removed at t = $T_OPEN s
material = \"beads\"
active = [0.0, $T_OPEN]
"
  PARTS="[[particles]]
file = \"restart.csv\"       # the settled fill
material = \"beads\"
"
  scene "scene_$NAME.toml" "Discharge through a $D m square orifice, from the settled fill." \
        "$(calc "$T_OPEN+$T_DIS")" "$FLOOR" "$PARTS" "" "output/$NAME" 0
  SECONDS=0
  nice -n 5 "$MPDEM" run "scene_$NAME.toml" --overwrite --threads "$THREADS"
  echo "D0 = $D m: $(calc "$T_OPEN+$T_DIS") s, wall time ${SECONDS} s" | tee -a output/times.txt
  echo "$NAME $D $T_OPEN output/$NAME" >> output/runs.txt
done

"$PY" plot_silo.py --width $L --fill output/fill output/runs.txt | tee results.txt
echo "run.sh: total wall time $(( $(date +%s) - T0 )) s" | tee -a output/times.txt
