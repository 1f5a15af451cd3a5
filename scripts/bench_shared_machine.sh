#!/usr/bin/env bash
# Threads on a shared machine (docs/benchmark.md "Shared machines"): the settled bed at 1 and 2
# OpenMP threads, on an idle machine and with one core kept busy by another process (a shell
# busy loop), runs interleaved, medians. Issue 21 asks that with one core busy, 2 threads never
# take more than 1.3x the time of 1.
#
# Usage: scripts/bench_shared_machine.sh [20k|100k]
#        SCENE=path/scene.toml scripts/bench_shared_machine.sh   (any scene instead of a bed: `mpdem
#        run` of it, the time loop's wall time; e.g. the flowing silo that bench_silo_vs_liggghts.sh
#        writes into its WORK folder)
# Environment:
#   MPDEM    mpdem executable (default: build/mpdem)
#   WORK     scratch folder (default: build/bench-bed)
#   RUNS     repetitions, median reported (default 3)
#   STEPS    timed steps (default 1000), RELAX untimed steps first (default 100)
#   ENVS     OpenMP environments to compare, ';'-separated, each a space-separated list of
#            VAR=value ("-": mpdem's default) (default "-;OMP_WAIT_POLICY=active;OMP_WAIT_POLICY=passive")
#   SHARED   folder with the beds (default: ../shared/bench beside the repository)
#   SCENE    a scene file to run instead of a bed (STEPS and RELAX then do not apply)
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
MPDEM="${MPDEM:-$ROOT/build/mpdem}"
WORK="${WORK:-$ROOT/build/bench-bed}"
RUNS="${RUNS:-3}"
STEPS="${STEPS:-1000}"
RELAX="${RELAX:-100}"
ENVS="${ENVS:--;OMP_WAIT_POLICY=active;OMP_WAIT_POLICY=passive}"
SHARED="${SHARED:-$ROOT/../shared/bench}"
[ -d "$SHARED" ] || SHARED=/work/shared/bench
bed="${1:-20k}"
# shellcheck source=bench_lib.sh
. "$ROOT/scripts/bench_lib.sh"
mkdir -p "$WORK"
SCENE="${SCENE:-}"
if [ -z "$SCENE" ]; then data=$(bed_file "$bed" "$WORK" "$SHARED"); fi

run() {  # env (or -), threads: prints the timed seconds
  local e=() ; [ "$1" = "-" ] || read -r -a e <<< "$1"
  if [ -n "$SCENE" ]; then
    local out="$WORK/shared_machine_run.out"
    env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT -u OMP_NUM_THREADS "${e[@]}" \
      "$MPDEM" run "$SCENE" --threads "$2" --overwrite --output "$WORK/shared_machine_out" > "$out" 2>&1
    run_seconds "$out"
    return
  fi
  env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT -u OMP_NUM_THREADS "${e[@]}" \
    "$MPDEM" bench "$data" --threads "$2" --steps "$STEPS" --relax "$RELAX" | grep '^BENCH_RESULT' | field seconds
}

busy_pid=""
busy_on() { sh -c 'while :; do :; done' & busy_pid=$!; }
busy_off() { [ -z "$busy_pid" ] || kill "$busy_pid" 2> /dev/null || true; wait "$busy_pid" 2> /dev/null || true; busy_pid=""; }
trap busy_off EXIT

IFS=';' read -r -a envs <<< "$ENVS"
declare -A T=()
for r in $(seq 1 "$RUNS"); do
  for load in idle busy; do
    [ "$load" = busy ] && busy_on
    for e in "${envs[@]}"; do
      for th in 1 2; do T[$load,$e,$th]+=" $(run "$e" "$th")"; done
    done
    busy_off
  done
done
if [ -n "$SCENE" ]; then what="scene $SCENE"; else what="bed $bed, $STEPS timed steps"; fi
echo "== $what, median of $RUNS; busy: one shell busy loop beside the run =="
printf '%-34s %-5s %10s %10s %12s\n' "OpenMP environment" "load" "1 thread" "2 threads" "2 / 1"
for e in "${envs[@]}"; do
  for load in idle busy; do
    a=$(echo "${T[$load,$e,1]}" | median)
    b=$(echo "${T[$load,$e,2]}" | median)
    printf '%-34s %-5s %9.3fs %9.3fs %12.2f\n' "$([ "$e" = - ] && echo "(mpdem default)" || echo "$e")" "$load" "$a" "$b" \
      "$(echo "$b $a" | awk '{print $1 / $2}')"
  done
done
