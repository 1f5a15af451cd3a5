#!/usr/bin/env bash
# Output cost on the settled bed (docs/benchmark.md "Output cost"): the same run steps with and
# without a particle VTU snapshot every N steps, for each VTK format, runs interleaved, medians.
#
# Usage: scripts/bench_output_cost.sh [20k|100k]
# Environment:
#   MPDEM     mpdem executable (default: build/mpdem)
#   WORK      scratch folder (default: build/bench-bed); the snapshots go to WORK/output-cost
#   RUNS      repetitions of every configuration, median reported (default 3)
#   THREADS   OpenMP threads (default 1)
#   EVERY     steps between snapshots (default 100)
#   STEPS     timed steps (default 1000), RELAX untimed steps first (default 100)
#   FORMATS   VTK formats to measure (default "binary compressed ascii")
#   SHARED    folder with the beds (default: ../shared/bench beside the repository)
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
MPDEM="${MPDEM:-$ROOT/build/mpdem}"
WORK="${WORK:-$ROOT/build/bench-bed}"
RUNS="${RUNS:-3}"
THREADS="${THREADS:-1}"
EVERY="${EVERY:-100}"
STEPS="${STEPS:-1000}"
RELAX="${RELAX:-100}"
FORMATS="${FORMATS:-binary compressed ascii}"
SHARED="${SHARED:-$ROOT/../shared/bench}"
[ -d "$SHARED" ] || SHARED=/work/shared/bench
bed="${1:-100k}"
# shellcheck source=bench_lib.sh
. "$ROOT/scripts/bench_lib.sh"
mkdir -p "$WORK"
data=$(bed_file "$bed" "$WORK" "$SHARED")
out="$WORK/output-cost"

run() {  # label, extra arguments: prints the timed seconds
  rm -rf "$out" && mkdir -p "$out"
  OMP_NUM_THREADS="$THREADS" "$MPDEM" bench "$data" --threads "$THREADS" --steps "$STEPS" --relax "$RELAX" \
    --output "$out" "${@:2}" | grep '^BENCH_RESULT' | field seconds
}

declare -A T=()
for r in $(seq 1 "$RUNS"); do
  T[none]+=" $(run none)"
  for f in $FORMATS; do T[$f]+=" $(run "$f" --snapshot-every "$EVERY" --format "$f")"; done
done
n=$(awk '$2 == "atoms" {print $1; exit}' "$data")
base=$(echo "${T[none]}" | median)
echo "== bed $bed ($n particles), $STEPS timed steps, $THREADS thread(s), a particle VTU every $EVERY steps, median of $RUNS =="
printf '%-12s %10s %10s %14s\n' "snapshots" "seconds" "slowdown" "MB/snapshot"
printf '%-12s %10.3f %10s %14s\n' "none" "$base" "-" "-"
for f in $FORMATS; do
  s=$(echo "${T[$f]}" | median)
  rm -rf "$out" && mkdir -p "$out"
  OMP_NUM_THREADS="$THREADS" "$MPDEM" bench "$data" --threads "$THREADS" --steps 1 --relax 0 --output "$out" \
    --snapshot-every 1 --format "$f" > /dev/null
  mb=$(du -b "$out"/particles/particles_000000.vtu | awk '{printf "%.1f", $1 / 1e6}')
  printf '%-12s %10.3f %+9.1f%% %14s\n' "$f" "$s" "$(echo "$s $base" | awk '{print 100 * ($1 / $2 - 1)}')" "$mb"
done
rm -rf "$out"
