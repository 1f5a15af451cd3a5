#!/usr/bin/env bash
# Rotating drum: dynamic angle of repose against the Froude number Fr = omega^2 R / g.
# Usage:  ./run.sh [path/to/mpdem]      (default: mpdem on PATH; THREADS overrides the 1 thread)
# Builds the drum, runs one scene per speed (the same generated bed settles in the turning drum,
# half a turn of transient, then one radian of measurement), measures the angle of the free
# surface from the particle CSV snapshots (drum_angle.py) and plots (plot_drum.py).
set -euo pipefail
cd "$(dirname "$0")"
MPDEM=${1:-${MPDEM:-mpdem}}
THREADS=${THREADS:-1}   # one thread: on a busy 2-core machine OpenMP threads wait on each other
PY=/usr/bin/python3     # Debian's, with matplotlib
T0=$(date +%s)

RDRUM=0.05      # m, drum radius (diameter 0.1 m)
LDRUM=0.042     # m, drum length along its axis (y), end walls at y = +-0.021
RADIUS=0.0025   # m, bead radius (monodisperse)
COUNT=1500      # beads: about half full (settled solid fraction ~0.6)
YOUNG=1e6       # Pa, softened
DT=${DT:-2.35e-5}  # s, just below mpdem check's recommendation 2.39e-5 s (Hertz contact time at 1.4 m/s / 50)
FRS=${FRS:-"3e-4 1e-3 3e-3 1e-2"}   # Froude numbers
TH_TRANS=3.14159  # rad turned before measuring: half a turn (the bed settles in the first ~0.4 s)
TH_MEAS=1.0     # rad turned while measuring
TH_SNAP=0.1     # rad between particle CSV snapshots

calc() { "$PY" -c "from math import *; print(repr($1))"; }

# Closed cylinder about z (z in [0, L]) turned 90 deg about x (axis along y, y in [-L, 0]) and
# shifted by L/2: y in [-L/2, L/2].
"$MPDEM" mesh cylinder --radius "$RDRUM" --height "$LDRUM" --segments 48 --closed \
         --rotate-deg 90 0 0 --translate 0 "$(calc "$LDRUM/2")" 0 -o drum.csv --group drum

# Beads generated loosely in the whole drum (solid fraction 0.31, the same bed at every speed);
# they fall and settle while the drum turns.
GEN="generate = { region = \"cylinder\", base = [0, $(calc "-$LDRUM/2+0.0002"), 0], axis = [0, $(calc "$LDRUM-0.0004"), 0], cylinder_radius = $(calc "$RDRUM-0.0002"), count = $COUNT, radius = $RADIUS, seed = 1, gap = 0.00005, max_attempts = 1000000, material = \"glass\" }"
mkdir -p output
: > output/runs.txt
: > output/times.txt
for FR in $FRS; do
  W=$(calc "sqrt($FR*9.81/$RDRUM)")
  NAME=fr$FR
  T_END=$(calc "($TH_TRANS+$TH_MEAS)/$W")
  sed -e "s|@RDRUM@|$RDRUM|; s|@LDRUM@|$LDRUM|; s|@OMEGA@|$W|g; s|@DURATION@|$T_END|; s|@DT@|$DT|" \
      -e "s|@YOUNG@|$YOUNG|; s|@PARTICLES@|$GEN|; s|@CSVEVERY@|$(calc "$TH_SNAP/$W")|" \
      -e "s|@MAXOVERLAP@|0.3|; s|@VTUEVERY@|$(calc "0.5/$W")|; s|@OUTDIR@|output/$NAME|" \
      drum.toml.in > "scene_$NAME.toml"
  SECONDS=0
  nice -n 5 "$MPDEM" run "scene_$NAME.toml" --overwrite --threads "$THREADS"
  echo "Fr = $FR: omega = $W rad/s for $T_END s, wall time ${SECONDS} s" | tee -a output/times.txt
  echo "$NAME $W $(calc "$TH_TRANS/$W") output/$NAME" >> output/runs.txt
done

"$PY" plot_drum.py --drum-radius "$RDRUM" --length "$LDRUM" output/runs.txt | tee results.txt
echo "run.sh: total wall time $(( $(date +%s) - T0 )) s" | tee -a output/times.txt
