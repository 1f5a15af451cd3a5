#!/usr/bin/env bash
# Smoke test of scripts/bench_physics.sh (docs/benchmark.md "Physics beds") on a bed of 9 spheres
# instead of the shared 20k bed (a few seconds): the script runs all six beds and prints one row
# each, with the counts of this bed known by hand: a 3 x 3 grid of 2 mm spheres, neighbours 1.998 mm
# apart (2 um overlap), 1 um into the floor: 12 bonds (2 x 12 / 9 = 2.667 per member), 12 + 9
# bridges (21 / 9 = 2.333 per member), a clump bed of 36 members, the plain bed's ratio 1.00.
# Usage: tests/scripts/bench_physics_smoke.sh MPDEM WORKDIR
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
mpdem=$1 work=$2
rm -rf "$work"
mkdir -p "$work/shared" "$work/bench"
{
  printf '# 3 x 3 grid\n\n9 atoms\n1 atom types\n\n0 0.014 xlo xhi\n0 0.014 ylo yhi\n0 0.01 zlo zhi\n\nAtoms\n\n'
  id=1
  for i in 0 1 2; do
    for j in 0 1 2; do
      awk -v id=$id -v i=$i -v j=$j 'BEGIN {printf "%d 1 0.002 2500 %.9g %.9g %.9g\n", id, 0.002 + i * 0.001998, 0.008 + j * 0.001998, 0.000999}'
      id=$((id + 1))
    done
  done
} | gzip > "$work/shared/bed20k.data.gz"

out="$work/out.txt"
MPDEM=$mpdem SHARED="$work/shared" WORK="$work/bench" RUNS=1 STEPS=5 RELAX=1 CLUMP_RELAX=1 \
  OMP_WAIT_POLICY=passive "$ROOT/scripts/bench_physics.sh" 20k > "$out" 2>&1 || { cat "$out"; echo "FAIL: exit status"; exit 1; }
cat "$out"
fail=0
# row BED COLUMN EXPECTED: the table's cell (columns: bed threads members ns runs ratio contacts bonds bridges)
row() {
  local got
  got=$(awk -F'|' -v b="$1" -v c="$2" '{gsub(/ /, "", $2)} $2 == b {v = $(c + 1); gsub(/ /, "", v); print v}' "$out")
  if [ "$got" != "$3" ]; then echo "FAIL: bed $1 column $2: '$got', expected '$3'"; fail=1; fi
}
for bed in plain clumps jkr sjkr bridges bonds; do row "$bed" 2 1; done
row plain 6 1.00
row plain 3 9
row clumps 3 36
row bonds 8 2.667
row bridges 9 2.333
row jkr 9 0.000
[ "$fail" = 0 ] && echo "bench_physics smoke: ok"
exit "$fail"
