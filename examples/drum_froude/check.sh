#!/usr/bin/env bash
# Short check of the drum example for the test suite (ctest -L examples, tests/CMakeLists.txt):
# a reduced drum (radius 40 mm, 30 mm long = 6 bead diameters, 680 beads of radius 2.5 mm, about
# half full) settles while it turns at Fr = omega^2 R / g = 1e-2 (omega = 1.566 rad/s) for 1.6 s
# (2.5 rad); the surface angle of the 7 snapshots from t = 1.0 s (1.57 rad turned; the surface
# reaches its plateau after about 0.8 rad) on, measured as in the full example (drum_angle.py),
# must be positive (the surface raised on the rising wall's side, i.e. inclined in the direction
# the drum turns) and their mean within [15, 45] deg. About 15-25 s on one thread.
#
# Why that range: this reduced drum gives 36.8 +- 1.7 deg (the full example 31-35 deg, README.md;
# the reduced drum is smaller and shorter, so its end walls hold the surface a little steeper).
# Measured negative controls (README.md): a drum that does not turn leaves the settled bed flat
# (1.9 deg), one turning the wrong way gives -36.8 deg, a frictionless wall lets the bed slip
# (0.0 +- 0.9 deg) and frictionless beads flow flat (1.7 deg): all far below 15 deg, and a wall
# with a wrong surface velocity would fail the same way. Above 45 deg the bed would
# be held far past any angle of repose of frictional spheres (mu = 0.5, small rolling resistance).
# The range is wide on purpose: it catches a broken drum, not a change of a few degrees.
#
# Usage: check.sh path/to/mpdem WORK_DIR      (python3 with the standard library only)
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
MPDEM=$1
WORK=$2
PY=${PYTHON:-python3}
rm -rf "$WORK"
mkdir -p "$WORK"
cd "$WORK"
R=0.04
L=0.03
W=$("$PY" -c "print(repr((1e-2*9.81/$R)**0.5))")
"$MPDEM" mesh cylinder --radius $R --height $L --segments 48 --closed --rotate-deg 90 0 0 \
         --translate 0 0.015 0 -o drum.csv --group drum
GEN='generate = { region = "cylinder", base = [0, -0.0148, 0], axis = [0, 0.0296, 0], cylinder_radius = 0.0398, count = 680, radius = 0.0025, seed = 1, gap = 0.00005, max_attempts = 1000000, material = "glass" }'
sed -e "s|@RDRUM@|$R|; s|@LDRUM@|$L|; s|@OMEGA@|$W|g; s|@DURATION@|1.6|; s|@DT@|2.35e-5|" \
    -e "s|@YOUNG@|1e6|; s|@PARTICLES@|$GEN|; s|@CSVEVERY@|0.1|; s|@MAXOVERLAP@|0.3|" \
    -e "s|@VTUEVERY@|0|; s|@OUTDIR@|output|" "$HERE/drum.toml.in" > scene.toml
"$MPDEM" run scene.toml --overwrite --threads 1 --quiet
# The slab is |y| <= L/2 - 1.5 d (the central 3 of the 6 bead layers), as in the full example.
"$PY" "$HERE/drum_angle.py" output --drum-radius $R --length $L --omega "$W" --t-from 1.0 \
      --expect-min 15 --expect-max 45
