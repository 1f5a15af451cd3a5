#!/usr/bin/env bash
# Short check of the silo example for the test suite (ctest -L examples, tests/CMakeLists.txt).
# One run with two small square silos side by side (width 65 mm, the example's beads: radius
# 2.25-2.75 mm, d = 5 mm, E = 2e6 Pa), each filled by its own [[inlet]] (1100 beads in 0.1 s) on a
# floor with a square orifice closed by a lid (active = [0, 0.2]), orifice sides 30 mm (6 d, silo
# A) and 40 mm (8 d, silo B), each discharging into its own [[sink]] from t = 0.2 s to 0.32 s.
# check_silo.py then asserts (tolerances and their reasons there):
#   - nothing leaves before the lid opens (both sinks and the domain boundary: 0 removed for t < 0.2 s),
#     and the lids carry the beds' weight until then and exactly nothing afterwards;
#   - the flow starts after it: first removal in (0.2, 0.3] s (free fall to the sink: ~0.07 s);
#   - the larger orifice discharges faster: mass removed by t = 0.32 s, B / A in [1.5, 5];
#   - mass is conserved: inserted mass = mass in the silos + removed mass, to 1e-12 relative,
#     and the counts exactly.
# Usage: check.sh path/to/mpdem WORK_DIR      (python3 with the standard library only)
set -euo pipefail
HERE=$(cd "$(dirname "$0")" && pwd)
MPDEM=$1
WORK=$2
PY=${PYTHON:-python3}
rm -rf "$WORK"
mkdir -p "$WORK"
cd "$WORK"
L=0.065
# silo A centred at x = -0.05, silo B at x = +0.05 (walls 35 mm apart)
"$MPDEM" mesh box --size $L $L 0.12 --translate -0.05 0 0 -o boxA.csv --group wallsA
"$MPDEM" mesh box --size $L $L 0.12 --translate 0.05 0 0 -o boxB.csv --group wallsB --first-id 20
awk -F, 'NR <= 2 || ($1 != 0 && $1 != 1)' boxA.csv > wallsA.csv
awk -F, 'NR <= 2 || ($1 != 20 && $1 != 21)' boxB.csv > wallsB.csv
"$MPDEM" mesh plate --size $L $L --hole-size 0.03 0.03 --translate -0.05 0 0 -o floorA.csv --group floorA --first-id 40
"$MPDEM" mesh plate --size $L $L --hole-size 0.04 0.04 --translate 0.05 0 0 -o floorB.csv --group floorB --first-id 60
"$MPDEM" mesh rect --size 0.03 0.03 --translate -0.05 0 0 -o lidA.csv --group lidA --first-id 80
"$MPDEM" mesh rect --size 0.04 0.04 --translate 0.05 0 0 -o lidB.csv --group lidB --first-id 90
cat > check.toml <<'EOF2'
# Two silos (tests: examples/silo_beverloo/check.sh). SI units.
[time]
duration = 0.32
integrator = "verlet"
dt = 1.7e-5

[gravity]
vector = [0.0, 0.0, -9.81]

[contact.particle_particle]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.5

[contact.particle_barrier]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.5

[[material]]
name = "beads"
density = 2500.0
young = 2e6
poisson = 0.3

[[barriers]]
file = "wallsA.csv"
material = "beads"
[[barriers]]
file = "wallsB.csv"
material = "beads"
[[barriers]]
file = "floorA.csv"
material = "beads"
[[barriers]]
file = "floorB.csv"
material = "beads"
[[barriers]]
file = "lidA.csv"
material = "beads"
active = [0.0, 0.2]
[[barriers]]
file = "lidB.csv"
material = "beads"
active = [0.0, 0.2]

[[inlet]]
name = "feedA"
region = "box"
min = [-0.0795, -0.0295, 0.05]
max = [-0.0205, 0.0295, 0.08]
count_rate = 11000.0
end = 0.1
radius = { distribution = "uniform", min = 0.00225, max = 0.00275 }
material = "beads"
velocity = [0.0, 0.0, -0.5]
seed = 1

[[inlet]]
name = "feedB"
region = "box"
min = [0.0205, -0.0295, 0.05]
max = [0.0795, 0.0295, 0.08]
count_rate = 11000.0
end = 0.1
radius = { distribution = "uniform", min = 0.00225, max = 0.00275 }
material = "beads"
velocity = [0.0, 0.0, -0.5]
seed = 2

[[sink]]
name = "outA"
region = "box"
min = [-0.2, -0.2, -0.3]
max = [0.0, 0.2, -0.02]

[[sink]]
name = "outB"
region = "box"
min = [0.0, -0.2, -0.3]
max = [0.2, 0.2, -0.02]

[domain]
min = [-0.2, -0.2, -0.3]
max = [0.2, 0.2, 0.3]
on_exit = "remove"

[checks]
max_overlap = 0.3
energy_drift = 0.5

[output]
dir = "output"
log_every = 100
barrier_log_every = 0.002
particle_csv_every = 0.32
progress_every = 0
EOF2
SECONDS=0
"$MPDEM" run check.toml --overwrite --threads 1 --quiet
echo "silo check run: wall time ${SECONDS} s"
"$PY" "$HERE/check_silo.py" output --t-open 0.2
