#!/usr/bin/env bash
# Silo discharge through a circular (or square) orifice in a flat floor: Beverloo's law W = C rho_b sqrt(g) (D0 - k d)^(5/2).
# Usage:  ./run.sh [path/to/mpdem]      (default: $MPDEM, else mpdem on PATH; THREADS overrides 1)
# Environment: HOLE (circle | square, default circle), OUT (output folder, default output; the
#   results go to results.txt and silo_beverloo.png, with HOLE=square to results_square.txt and
#   silo_beverloo_square.png), REUSE_FILL=1 (keep OUT/fill and restart.csv of an earlier run of
#   the same L), and the rates and times below.
# 1. fill: an [[inlet]] rains beads into the closed silo (solid floor) until the bed reaches the top
#    of its thin box at z = H_TOP (the inlet's shortfall stops it there), then the bed settles;
# 2. one discharge run per orifice size D0, each seeded with the settled fill (last particle CSV
#    snapshot): the floor is a plate with a circular hole of diameter D0 (HOLE=square: a D0 x D0
#    square) closed by a lid (active = [0, T_OPEN]),
#    the beads leave through the hole into a [[sink]] 4 bead diameters below the floor, and the
#    same inlet keeps feeding the top at more than the largest discharge rate, so the head stays
#    at H_TOP (what does not fit is the inlet's shortfall);
# 3. plot_silo.py: W from the sink's log columns, the Beverloo fits, results.txt, silo_beverloo.png.
set -euo pipefail
cd "$(dirname "$0")"
MPDEM=${1:-${MPDEM:-mpdem}}
THREADS=${THREADS:-1}   # one thread: on a busy 2-core machine OpenMP threads wait on each other
PY=/usr/bin/python3     # with numpy and matplotlib
T0=$(date +%s)

L=${L:-0.25}            # m, silo width (square, x and y in [-L/2, L/2]); walls 0.25 m high.
                        # L >= 2.5 D0 and L >= D0 + 30 d for every D0 (Nedderman: no wall effect)
DT=1.7e-5               # s
H_BOT=0.085            # m, the inlet's box: z in [H_BOT, H_TOP] over the whole cross-section
H_TOP=0.100             # m, (3 mm from the walls); the head of the bed = H_TOP = 20 d
FILL_RATE=${FILL_RATE:-95000}  # 1/s, fill: beads (radius uniform in [2.25, 2.75] mm, d = 5 mm) at
T_FEED=${T_FEED:-0.75}         # s, ... this rate until T_FEED (the bed reaches H_TOP before:
T_FILL=${T_FILL:-0.95}         # s, ... the rest is shortfall), then it settles until T_FILL
FEED_RATE=${FEED_RATE:-65000}  # 1/s, discharges: the inlet keeps feeding (largest discharge ~31 000/s)
T_OPEN=0.03             # s, discharge runs: the lid (re)settles the seeded bed, then opens at T_OPEN
T_DIS=${T_DIS:-0.8}               # s of discharge after T_OPEN
DS=${DS:-"0.025 0.03 0.0375 0.045 0.0525 0.06 0.07 0.08"}   # m, orifice sizes D0 = 5, 6, 7.5, 9, 10.5, 12, 14, 16 d
HOLE=${HOLE:-circle}    # circle: D0 = diameter (Beverloo's orifices); square: D0 = side
OUT=${OUT:-output}
case "$HOLE" in
  circle) SUFFIX="" ;;
  square) SUFFIX="_square" ;;
  *) echo "HOLE must be circle or square, not '$HOLE'" >&2; exit 2 ;;
esac

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

mkdir -p "$OUT"
: > "$OUT/runs$SUFFIX.txt"
[ "${REUSE_FILL:-0}" = 1 ] || : > "$OUT/times.txt"

# 1. Fill and settle.
H=$(calc "$L/2-0.003")
INLET="[[inlet]]
name = \"feed\"
region = \"box\"
min = [-$H, -$H, $H_BOT]
max = [$H, $H, $H_TOP]
count_rate = $FILL_RATE   # 1/s; once the bed reaches the box, what does not fit is shortfall
start = 0.0
end = $T_FEED
radius = { distribution = \"uniform\", min = 0.00225, max = 0.00275 }
material = \"beads\"
velocity = [0.0, 0.0, -1.0]
seed = 1
"
FLOOR="[[barriers]]
file = \"floor_solid.csv\"   # closed floor while filling
material = \"beads\"
"
if [ "${REUSE_FILL:-0}" = 1 ] && [ -s restart.csv ] && [ -d "$OUT/fill" ]; then
  echo "fill: reusing $OUT/fill and restart.csv (REUSE_FILL=1)"
else
  scene scene_fill.toml "Fill: the inlet rains beads in up to z = $H_TOP m; they settle on the closed floor." \
        "$T_FILL" "$FLOOR" "" "$INLET" "$OUT/fill" "$T_FILL"
  SECONDS=0
  nice -n 5 "$MPDEM" run scene_fill.toml --overwrite --threads "$THREADS"
  echo "fill: inlet until $T_FEED s, settled until $T_FILL s, wall time ${SECONDS} s" | tee -a "$OUT/times.txt"
  "$PY" restart.py "$OUT/fill" restart.csv
fi

# 2. Discharge through each orifice.
for D in $DS; do
  if [ "$HOLE" = circle ]; then
    NAME=c$(calc "round($D*1e4)")
    "$MPDEM" mesh plate --size $L $L --hole-radius "$(calc "$D/2")" --segments 64 -o "floor_$NAME.csv" --group floor --first-id 100
  else
    NAME=s$(calc "round($D*1e4)")
    "$MPDEM" mesh plate --size $L $L --hole-size $D $D -o "floor_$NAME.csv" --group floor --first-id 100
  fi
  "$MPDEM" mesh rect --size $D $D -o "lid_$NAME.csv" --group lid --first-id 1000   # covers either hole
  FLOOR="[[barriers]]
file = \"floor_$NAME.csv\"   # plate with a $D m $HOLE hole
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
  FEED="[[inlet]]
name = \"feed\"
region = \"box\"
min = [-$H, -$H, $H_BOT]
max = [$H, $H, $H_TOP]
count_rate = $FEED_RATE   # 1/s, more than the discharge: the head stays at H_TOP (the rest is shortfall)
start = 0.0
radius = { distribution = \"uniform\", min = 0.00225, max = 0.00275 }
material = \"beads\"
velocity = [0.0, 0.0, -0.5]
seed = 2
"
  scene "scene_$NAME.toml" "Discharge through a $D m $HOLE orifice, from the settled fill, fed at the top." \
        "$(calc "$T_OPEN+$T_DIS")" "$FLOOR" "$PARTS" "$FEED" "$OUT/$NAME" 0
  SECONDS=0
  nice -n 5 "$MPDEM" run "scene_$NAME.toml" --overwrite --threads "$THREADS"
  echo "$HOLE D0 = $D m: $(calc "$T_OPEN+$T_DIS") s, wall time ${SECONDS} s" | tee -a "$OUT/times.txt"
  echo "$NAME $D $T_OPEN $OUT/$NAME" >> "$OUT/runs$SUFFIX.txt"
done

"$PY" plot_silo.py --width $L --hole "$HOLE" --head $H_TOP --fill "$OUT/fill" --png "silo_beverloo$SUFFIX.png" \
  "$OUT/runs$SUFFIX.txt" | tee "results$SUFFIX.txt"
echo "run.sh: total wall time $(( $(date +%s) - T0 )) s" | tee -a "$OUT/times.txt"
