#!/usr/bin/env bash
# SIGTERM to `mpirun -np N mpdem run` (docs/parallel.md "Stopping a run", README "Exit status"):
# every rank stops at the same step, a checkpoint is written, rank 0 prints one resume command that
# starts N ranks through the launcher again, and, pasted, that command resumes on N ranks.
#  - SIGTERM to the ranks (what a batch system's time limit does: it signals every task): the job
#    exits 143, the ranks' status;
#  - SIGTERM to mpirun: Open MPI's mpirun forwards SIGTERM to the ranks (a second later, and
#    kills them another second later) and exits 1 whatever the ranks return; the checkpoint and the
#    resume command are the same.
# Registered in tests/CMakeLists.txt (MPDEM_MPI). No timing: each signal is sent once the run has
# printed a progress line, and the scene runs far longer than the test.
# Usage: mpirun_signal.sh MPDEM MPIEXEC NP WORKDIR   (NP >= 2)
set -uo pipefail
MPDEM=$1 MPIEXEC=$2 NP=$3 WORK=$4
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1
fails=0
fail() { echo "FAIL $*"; fails=1; }

# Spheres at rest along x, no gravity: cheap steps; 5e7 of them, never reached.
cat > spheres.csv <<'CSV'
id,x,y,z,vx,vy,vz,radius
1,0.005,0.0,0.0,0,0,0,0.001
2,0.030,0.0,0.0,0,0,0,0.001
3,0.055,0.0,0.0,0,0,0,0.001
4,0.080,0.0,0.0,0,0,0,0.001
CSV
cat > scene.toml <<'TOML'
[time]
duration = 100.0
integrator = "verlet"
dt = 2e-6
[gravity]
vector = [0.0, 0.0, 0.0]
[contact.particle_particle]
restitution = 0.5
mu_static = 0.5
mu_dynamic = 0.5
[[material]]
name = "glass"
density = 2500.0
young = 1e7
poisson = 0.3
[[particles]]
file = "spheres.csv"
material = "glass"
[domain]
min = [0.0, -0.01, -0.01]
max = [0.1, 0.01, 0.01]
[output]
dir = "out"
log_every = 100
progress_every = 0.05
TOML

# Waits (at most 300 s) until the run's stderr ($1) holds a progress line.
wait_for_progress() {
  for _ in $(seq 3000); do
    grep -q '^t = ' "$1" 2> /dev/null && return 0
    sleep 0.1
  done
  return 1
}
# The ranks of the mpirun job $1 (its children).
ranks_of() { pgrep -P "$1"; }

# stop NAME TARGET STATUS COMMAND...: runs COMMAND in the background, sends SIGTERM to TARGET
# ("mpirun" or "ranks") once it has printed a progress line, and checks the exit status, the
# checkpoint and the message.
stop() {
  local name=$1 target=$2 want=$3
  shift 3
  RESUME=
  touch start.mark && sleep 1  # a checkpoint written from here on is newer (1 s: mtime resolution)
  "$@" > "$name.out" 2> "$name.err" &
  local job=$!
  if ! wait_for_progress "$name.err"; then
    fail "$name: no progress line within 300 s"; kill -KILL "$job"; wait "$job"; return
  fi
  if [ "$target" = mpirun ]; then
    kill -TERM "$job"
  else
    local ranks
    ranks=$(ranks_of "$job")
    if [ "$(printf '%s\n' "$ranks" | grep -c .)" -eq "$NP" ]; then
      # shellcheck disable=SC2086  # one word per rank
      kill -TERM $ranks
    else
      fail "$name: $NP ranks expected as the children of process $job, found: $ranks"
      kill -TERM "$job"
    fi
  fi
  wait "$job"
  local got=$?
  echo "--- $name (np $NP, SIGTERM to $target): exit $got; stderr without the progress lines:"
  grep -v '^t = ' "$name.err"
  [ "$got" -eq "$want" ] || fail "$name: exit status $got, expected $want"
  [ out/checkpoint.bin -nt start.mark ] || fail "$name: no checkpoint written"
  [ "$(grep -c '^stopped by signal 15 ' "$name.err")" -eq 1 ] || fail "$name: not one 'stopped by signal 15' line"
  local resume
  resume=$(grep '^resume with: ' "$name.err")
  [ "$(printf '%s\n' "$resume" | grep -c .)" -eq 1 ] || { fail "$name: not one 'resume with:' line"; return; }
  case "$resume" in
    "resume with: mpirun -np $NP --oversubscribe $MPDEM run scene.toml --output "*" --resume "*out/checkpoint.bin) ;;
    *) fail "$name: the resume command is not 'mpirun -np $NP --oversubscribe $MPDEM run ... --resume ...'" ;;
  esac
  RESUME=${resume#resume with: }
}

export OMP_NUM_THREADS=1
stop to_ranks ranks 143 "$MPIEXEC" -n "$NP" --oversubscribe "$MPDEM" run scene.toml
first=$RESUME
rm -rf out
stop to_mpirun mpirun 1 "$MPIEXEC" -n "$NP" --oversubscribe "$MPDEM" run scene.toml
# The command pasted as printed (the shell splits it; `mpirun` from PATH) resumes on NP ranks:
# stopped again, it prints the same command (its launcher part comes from the resumed run's own
# rank count) and its log goes on past the checkpoint's time.
if [ -n "$first" ] && [ -n "$RESUME" ]; then
  [ "$first" = "$RESUME" ] || fail "the two runs printed different resume commands"
  rows=$(wc -l < out/log.csv)
  stop resumed ranks 143 bash -c "exec $RESUME"
  [ "$(wc -l < out/log.csv)" -gt "$rows" ] || fail "resumed: the log did not go on"
  [ "$RESUME" = "$first" ] || fail "resumed: it printed another resume command (not $NP ranks?)"
fi
exit $fails
