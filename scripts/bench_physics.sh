#!/usr/bin/env bash
# The physics beds (docs/benchmark.md "Physics beds"): the settled bed plain, as tetrahedral
# clumps, with JKR or SJKR adhesion, with liquid bridges and bonded, `mpdem bench` Verlet, runs
# interleaved, medians; the cost per member-step (a sphere of the plain, cohesive and bonded beds,
# a clump's member sphere in the clump bed) against the plain bed's.
#
# Usage: scripts/bench_physics.sh [20k|100k]   (default 20k)
# Environment:
#   MPDEM        mpdem executable (default: build/mpdem)
#   MPDEM_OLD    a second (older) mpdem: run interleaved on the beds it knows (new / old reported)
#   WORK         scratch folder for the decompressed bed and logs (default: build/bench-bed)
#   RUNS         repetitions of every bed, median reported (default 3)
#   THREADS      thread counts to run (default "1")
#   STEPS        timed steps (default 2000)
#   RELAX        untimed steps first (default 1000)
#   CLUMP_RELAX  untimed steps of the clump bed, whose clumps start inscribed in the spheres and
#                settle (default 15000)
#   BEDS         the beds to run (default "plain clumps jkr sjkr bridges bonds")
#   SHARED       folder with the beds (default: ../shared/bench beside the repository)
#   NO_INSTALL   accepted for symmetry with the other scripts: this one installs nothing
# Exit status 1 when a bonded bed broke a bond (the bed is then not the one documented).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
MPDEM="${MPDEM:-$ROOT/build/mpdem}"
WORK="${WORK:-$ROOT/build/bench-bed}"
RUNS="${RUNS:-3}"
THREADS="${THREADS:-1}"
STEPS="${STEPS:-2000}"
RELAX="${RELAX:-1000}"
CLUMP_RELAX="${CLUMP_RELAX:-15000}"
BEDS="${BEDS:-plain clumps jkr sjkr bridges bonds}"
SHARED="${SHARED:-$ROOT/../shared/bench}"
[ -d "$SHARED" ] || SHARED=/work/shared/bench
size="${1:-20k}"
# shellcheck source=bench_lib.sh
. "$ROOT/scripts/bench_lib.sh"

[ -x "$MPDEM" ] || { echo "no mpdem executable at $MPDEM (build it, or set MPDEM)" >&2; exit 2; }
"$MPDEM" bench --help 2>/dev/null | grep -q -- --bonds || { echo "$MPDEM has no 'bench --bonds'" >&2; exit 2; }
# bed_options BED: the `mpdem bench` options of a bed
bed_options() {
  case "$1" in
    plain) echo "" ;;
    clumps) echo "--clumps" ;;
    jkr | sjkr | bridges) echo "--cohesion $1" ;;
    bonds) echo "--bonds" ;;
    *) echo "unknown bed '$1' (plain, clumps, jkr, sjkr, bridges or bonds)" >&2; return 2 ;;
  esac
}
for bed in $BEDS; do bed_options "$bed" > /dev/null || exit 2; done
# knows EXE BED: whether EXE's bench has the bed's option
knows() { local o; o=$(bed_options "$2"); [ -z "$o" ] || "$1" bench --help 2>/dev/null | grep -q -- "${o%% *}"; }
mkdir -p "$WORK"
data=$(bed_file "$size" "$WORK" "$SHARED")
n=$(awk '$2 == "atoms" {print $1; exit}' "$data")
echo "== bed $size: $n spheres, $RELAX untimed (clumps $CLUMP_RELAX) + $STEPS timed Verlet steps, $RUNS runs per bed =="

declare -A SAMPLES=() CONT=() BONDS=() BRIDGES=() MEMBERS=() BROKEN=()
status=0
for th in $THREADS; do
  for r in $(seq 1 "$RUNS"); do
    for bed in $BEDS; do
      order="new old"; [ $((r % 2)) -eq 0 ] && order="old new"
      for which in $order; do
        exe=$MPDEM; code=$bed
        if [ "$which" = old ]; then
          if [ -z "${MPDEM_OLD:-}" ] || ! knows "$MPDEM_OLD" "$bed"; then continue; fi
          exe=$MPDEM_OLD; code=old_$bed
        fi
        rx=$RELAX; [ "$bed" = clumps ] && rx=$CLUMP_RELAX
        log="$WORK/physics_${size}_${code}_t${th}_r$r"
        # shellcheck disable=SC2046  # the bed's options are words
        env "${MPDEM_OMP_ENV[@]}" "$exe" bench "$data" $(bed_options "$bed") --threads "$th" --steps "$STEPS" \
          --relax "$rx" > "$log.out" 2>&1 || { echo "mpdem failed, see $log.out" >&2; exit 1; }
        line=$(grep '^BENCH_RESULT' "$log.out")
        ns=$(echo "$line" | field ns_per_pstep)
        m=$(echo "$line" | field particles)
        SAMPLES[$code,$th]+=" $ns"
        MEMBERS[$code,$th]=$m
        CONT[$code,$th]=$(echo "$line" | field coordination)
        # Per member: 2 bonds / N and bridges / N (bridges with the walls included); old binaries print neither.
        BONDS[$code,$th]=$(echo "$line" | field bonds | awk -v m="$m" '{printf "%.3f", 2 * $1 / m}')
        BRIDGES[$code,$th]=$(echo "$line" | field bridges | awk -v m="$m" '{printf "%.3f", $1 / m}')
        BROKEN[$code,$th]=$(echo "$line" | field bonds_broken)
        echo "  $code threads=$th run $r: $ns ns/member-step, contacts/member ${CONT[$code,$th]}"
      done
    done
  done
done

echo
echo "Bed $size ($n spheres; $RELAX + $STEPS Verlet steps, clumps $CLUMP_RELAX + $STEPS; medians of $RUNS interleaved runs)"
printf '| %-12s | %7s | %8s | %14s | %-30s | %8s | %10s | %9s | %10s |\n' bed threads members "ns/member-step" \
  "runs" "vs plain" contacts/m "bonds/m" "bridges/m"
printf '|%s|\n' "--------------|---------|----------|----------------|--------------------------------|----------|------------|-----------|------------"
codes=""
for bed in $BEDS; do
  codes+=" $bed"
  [ -n "${MPDEM_OLD:-}" ] && knows "$MPDEM_OLD" "$bed" && codes+=" old_$bed"
done
declare -A MED=()
for th in $THREADS; do
  for code in $codes; do MED[$code,$th]=$(echo "${SAMPLES[$code,$th]}" | median); done
  for code in $codes; do
    base=plain; [ "${code#old_}" != "$code" ] && base=old_plain
    ratio="-"
    [ -n "${MED[$base,$th]:-}" ] && ratio=$(awk -v a="${MED[$code,$th]}" -v b="${MED[$base,$th]}" 'BEGIN {printf "%.2f", a / b}')
    runs=$(echo "${SAMPLES[$code,$th]}" | awk '{for (i = 1; i <= NF; i++) printf "%s%.1f", (i > 1 ? ", " : ""), $i}')
    printf '| %-12s | %7s | %8s | %14.1f | %-30s | %8s | %10s | %9s | %10s |\n' "$code" "$th" "${MEMBERS[$code,$th]}" \
      "${MED[$code,$th]}" "$runs" "$ratio" "${CONT[$code,$th]}" "${BONDS[$code,$th]:--}" "${BRIDGES[$code,$th]:--}"
    if [ -n "${BROKEN[$code,$th]:-}" ] && [ "${BROKEN[$code,$th]}" != 0 ]; then
      echo "bonds broke in bed $code (${BROKEN[$code,$th]}): not the bed documented" >&2
      status=1
    fi
  done
done
if [ -n "${MPDEM_OLD:-}" ]; then
  for th in $THREADS; do
    for bed in $BEDS; do
      [ -n "${MED[old_$bed,$th]:-}" ] || continue
      awk -v a="${MED[$bed,$th]}" -v b="${MED[old_$bed,$th]}" -v t="$th" -v d="$bed" 'BEGIN {
        printf "new vs old, %s, %s thread(s): %.1f vs %.1f ns/member-step, %+.1f%%\n", d, t, a, b, 100 * (a / b - 1) }'
    done
  done
fi
exit $status
