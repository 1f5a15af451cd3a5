#!/usr/bin/env bash
# `mpirun -np N mpdem run` on a bad scene and on a run that one rank cannot continue: one message
# on stderr (rank 0's), the same exit status from the job as on one rank (2: bad input, 1: a failed
# run), and no hang (docs/parallel.md, "Errors"). Registered in tests/CMakeLists.txt (MPDEM_MPI).
# (mpirun adds its own notice that a process exited with a non-zero status.)
# Usage: mpirun_errors.sh MPDEM MPIEXEC NP WORKDIR   (NP >= 2)
set -uo pipefail
MPDEM=$1 MPIEXEC=$2 NP=$3 WORK=$4
rm -rf "$WORK" && mkdir -p "$WORK" || exit 1
fails=0
check() {  # name expected_status text_the_one_message_must_contain scene
  local name=$1 want=$2 pattern=$3 scene=$4
  timeout 300 "$MPIEXEC" -np "$NP" --oversubscribe "$MPDEM" run "$scene" --quiet > "$WORK/$name.out" 2> "$WORK/$name.err"
  local got=$?
  local errors
  errors=$(grep -c '^error' "$WORK/$name.err")
  if [ "$got" -ne "$want" ]; then
    echo "FAIL $name: exit status $got, expected $want"; fails=1
  fi
  if [ "$errors" -ne 1 ]; then
    echo "FAIL $name: $errors lines starting with 'error' on stderr, expected 1"; fails=1
  fi
  if ! grep -q -F -- "$pattern" "$WORK/$name.err"; then
    echo "FAIL $name: the message does not contain '$pattern'"; fails=1
  fi
  echo "--- $name (np $NP): exit $got; stderr:"; cat "$WORK/$name.err"
}

# Two soft spheres at rest near x = 0, two colliding head-on at 20 m/s near x = 0.1: the bricks
# cut along x, so on two ranks or more only the last rank holds the collision, whose overlap
# exceeds checks.max_overlap within a few steps.
cat > "$WORK/spheres.csv" <<'EOF'
id,x,y,z,vx,vy,vz,radius
1,0.000,0.0,0.0,0,0,0,0.001
2,0.003,0.0,0.0,0,0,0,0.001
3,0.097,0.0,0.0,20,0,0,0.001
4,0.100,0.0,0.0,-20,0,0,0.001
EOF
cat > "$WORK/collision.toml" <<'EOF'
[time]
duration = 0.001
integrator = "verlet"
dt = 1e-5
[contact.particle_particle]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.5
[[material]]
name = "soft"
density = 2500.0
young = 1e6
poisson = 0.3
[[particles]]
file = "spheres.csv"
material = "soft"
[output]
dir = "out"
EOF
check collision 1 "particles id 3 and id 4 (on rank $((NP - 1)) of $NP)" "$WORK/collision.toml"

# A misspelt key: every rank finds it, rank 0 names the file, line and key.
sed 's/^restitution = 0.5$/restitutoin = 0.5/' "$WORK/collision.toml" > "$WORK/misspelt.toml"
check misspelt 2 "misspelt.toml:6" "$WORK/misspelt.toml"

# An output folder that cannot be created (a path under a regular file): rank 0 prepares the
# folder, every rank stops with exit 2 (issue 45 item 5: a raw "filesystem error", exit 1).
echo x > "$WORK/afile"
sed 's|^dir = "out"$|dir = "afile/out"|' "$WORK/collision.toml" > "$WORK/unwritable.toml"
check unwritable 2 "cannot create the output folder" "$WORK/unwritable.toml"
# A refused folder that rank 0 finds before creating it (not empty): the same (it hung).
mkdir -p "$WORK/full" && echo x > "$WORK/full/notes.txt"
sed 's|^dir = "out"$|dir = "full"|' "$WORK/collision.toml" > "$WORK/full.toml"
check full 2 "the output folder is not empty" "$WORK/full.toml"

exit $fails
