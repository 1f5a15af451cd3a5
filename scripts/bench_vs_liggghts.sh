#!/usr/bin/env bash
# Settled-bed benchmark, mpdem against LIGGGHTS 3.8 on the same machine (docs/benchmark.md).
#
# Usage: scripts/bench_vs_liggghts.sh [20k|100k] ...
# Environment:
#   MPDEM      mpdem executable with the `bench` subcommand (default: build/mpdem)
#   MPDEM_OLD  a second (older) mpdem executable: run interleaved with MPDEM, same arguments, and
#              reported beside it (new / old time per particle-step), for before/after measurements
#   WORK       scratch folder for the decompressed beds and logs (default: build/bench-bed)
#   RUNS       repetitions of every configuration, median reported (default 3, at least 3 advised)
#   THREADS    thread / rank counts to run (default "1 2")
#   STEPS      timed steps (default: 5000 for 20k, 2000 for 100k - the bench README protocol)
#   RELAX      untimed steps first (default 1000)
#   TRAP_STEPS timed steps of the trapezoidal runs (default: STEPS; it costs ~5 evaluations a step,
#              so a shorter window keeps the script's run time reasonable - the bed is static)
#   TRAP_RELAX untimed steps of the trapezoidal runs (default: RELAX)
#   SHARED     folder with the reference inputs (default: ../shared/bench beside the repository)
#   NO_INSTALL=1  do not apt-get install missing LIGGGHTS / Open MPI / GNU time
#   NO_LEDGER=1   also run MPDEM's Verlet with --no-energy-ledger ([checks] energy_ledger = false),
#                 interleaved like the others, as the row "mpdem verlet, no ledger"
# Exit status 1 when the two codes' contact counts differ by more than 2 %.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
MPDEM="${MPDEM:-$ROOT/build/mpdem}"
WORK="${WORK:-$ROOT/build/bench-bed}"
RUNS="${RUNS:-3}"
THREADS="${THREADS:-1 2}"
RELAX="${RELAX:-1000}"
SHARED="${SHARED:-$ROOT/../shared/bench}"
[ -d "$SHARED" ] || SHARED=/work/shared/bench
BEDS=("$@")
[ ${#BEDS[@]} -gt 0 ] || BEDS=(20k)

# shellcheck source=bench_lib.sh
. "$ROOT/scripts/bench_lib.sh"
bench_tools
[ -x "$MPDEM" ] || { echo "no mpdem executable at $MPDEM (build it, or set MPDEM)" >&2; exit 2; }
"$MPDEM" bench --help >/dev/null 2>&1 || { echo "$MPDEM has no 'bench' subcommand" >&2; exit 2; }
mkdir -p "$WORK"
status=0
for bed in "${BEDS[@]}"; do
  case "$bed" in
    20k) steps="${STEPS:-5000}" ;;
    100k) steps="${STEPS:-2000}" ;;
    *) echo "unknown bed '$bed' (20k or 100k)" >&2; exit 2 ;;
  esac
  data=$(bed_file "$bed" "$WORK" "$SHARED")
  n=$(awk '$2 == "atoms" {print $1; exit}' "$data")
  echo "== bed $bed: $n particles, $RELAX untimed + $steps timed steps, $RUNS runs per configuration =="

  declare -A NS=() RSS=() CONT=() REB=() EVAL=() SAMPLES=() MEMS=()
  # Runs interleave the codes (LIGGGHTS, mpdem Verlet, mpdem trapezoidal, then again), so that
  # a slow phase of a shared machine hits all of them alike.
  for th in $THREADS; do
    for r in $(seq 1 "$RUNS"); do
      # LIGGGHTS: "Loop time" of the timed run; one MPI rank per thread. Memory: every rank's own
      # peak RSS (GNU time around each rank), summed - the whole job's memory, like one mpdem process.
      log="$WORK/liggghts_${bed}_np${th}_r$r"
      SAMPLES[liggghts,$th]+=" $(liggghts_ns "$data" "$steps" "$RELAX" "$th" "$log")"
      MEMS[liggghts,$th]+=" $(cat "$log".rank* | awk '{s += $1} END {print s}')"
      CONT[liggghts,$th]=$(grep '^BENCH_STATE' "$log.out" | field contacts_per_particle)
      REB[liggghts,$th]="-"; EVAL[liggghts,$th]=1
      echo "  liggghts np=$th run $r: $(echo "${SAMPLES[liggghts,$th]}" | awk '{print $NF}') ns/particle-step, contacts/particle ${CONT[liggghts,$th]}"

      CONFIGS="verlet trapezoidal"; [ "${NO_LEDGER:-0}" = 1 ] && CONFIGS="verlet verlet_noledger trapezoidal"
      for config in $CONFIGS; do
        integ=${config%_noledger}; extra=()
        [ "$config" = verlet_noledger ] && extra=(--no-energy-ledger)
        # Alternate which binary runs first after LIGGGHTS (whose MPI job may still be winding down).
        order="new old"; [ $((r % 2)) -eq 0 ] && order="old new"
        for which in $order; do
          exe=$MPDEM; code=$config
          if [ "$which" = old ]; then
            [ -n "${MPDEM_OLD:-}" ] && [ ${#extra[@]} -eq 0 ] || continue
            exe=$MPDEM_OLD; code=old_$integ
          fi
          log="$WORK/mpdem_${bed}_${code}_t${th}_r$r"
          k=$steps; rx=$RELAX
          [ "$integ" = trapezoidal ] && k=${TRAP_STEPS:-$steps} && rx=${TRAP_RELAX:-$RELAX}
          env "${MPDEM_OMP_ENV[@]}" /usr/bin/time -v "$exe" bench "$data" --integrator "$integ" --phi 0.5 --threads "$th" \
            --steps "$k" --relax "$rx" "${extra[@]}" > "$log.out" 2> "$log.time"
          line=$(grep '^BENCH_RESULT' "$log.out")
          SAMPLES[$code,$th]+=" $(echo "$line" | field ns_per_pstep)"
          MEMS[$code,$th]+=" $(peak_kib "$log.time")"
          CONT[$code,$th]=$(echo "$line" | field coordination)
          REB[$code,$th]=$(echo "$line" | field rebuilds)
          EVAL[$code,$th]=$(echo "$line" | field evals_per_step)
          echo "  mpdem $code threads=$th run $r: $(echo "$line" | field ns_per_pstep) ns/particle-step, contacts/particle ${CONT[$code,$th]}, rebuilds ${REB[$code,$th]}"
        done
      done
    done
    CODES="liggghts verlet trapezoidal"
    [ -n "${MPDEM_OLD:-}" ] && CODES="liggghts verlet old_verlet trapezoidal old_trapezoidal"
    [ "${NO_LEDGER:-0}" = 1 ] && CODES="${CODES/verlet /verlet verlet_noledger }"
    for code in $CODES; do
      NS[$code,$th]=$(echo "${SAMPLES[$code,$th]}" | median)
      RSS[$code,$th]=$(echo "${MEMS[$code,$th]}" | median)
    done
  done

  echo
  echo "Bed $bed ($n particles, $RELAX + $steps steps (trapezoidal ${TRAP_RELAX:-$RELAX} + ${TRAP_STEPS:-$steps}); medians of $RUNS interleaved runs; peak RSS of the job (LIGGGHTS: sum over its ranks))"
  printf '| %-22s | %7s | %9s | %12s | %6s | %8s | %9s | %8s | %14s |\n' code threads ns/p-step "p-steps/s" \
    evals rebuilds contacts/p "RSS MiB" "mpdem/LIGGGHTS"
  printf '|%s|\n' "------------------------|---------|-----------|--------------|--------|----------|-----------|----------|----------------"
  for th in $THREADS; do
    for code in $CODES; do
      ns=${NS[$code,$th]}
      ratio=$(awk -v a="$ns" -v b="${NS[liggghts,$th]}" 'BEGIN {printf "%.2f", a / b}')
      [ "$code" = liggghts ] && ratio="1"
      label=$code; [ "$code" = liggghts ] && label="LIGGGHTS 3.8 (MPI)"; [ "$code" = verlet ] && label="mpdem verlet"
      [ "$code" = trapezoidal ] && label="mpdem trapezoidal 0.5"
      [ "$code" = old_verlet ] && label="old mpdem verlet"
      [ "$code" = verlet_noledger ] && label="mpdem verlet, no ledger"
      [ "$code" = old_trapezoidal ] && label="old mpdem trapezoidal"
      printf '| %-22s | %7s | %9.1f | %12.3g | %6.2f | %8s | %9.4f | %8.1f | %14s |\n' "$label" "$th" "$ns" \
        "$(awk -v x="$ns" 'BEGIN {print 1e9 / x}')" "${EVAL[$code,$th]}" "${REB[$code,$th]}" "${CONT[$code,$th]}" \
        "$(awk -v k="${RSS[$code,$th]}" 'BEGIN {print k / 1024}')" "$ratio"
    done
  done
  # Same physics check: settled contact counts within 2 %.
  for th in $THREADS; do
    for code in verlet trapezoidal; do
      ok=$(awk -v a="${CONT[$code,$th]}" -v b="${CONT[liggghts,$th]}" \
        'BEGIN {d = (a - b) / b; if (d < 0) d = -d; printf "%.3f%% %s", 100 * d, (d <= 0.02 ? "ok" : "FAIL")}')
      echo "contact check ($code, $th threads vs LIGGGHTS $th ranks): ${CONT[$code,$th]} vs ${CONT[liggghts,$th]}: $ok"
      case "$ok" in *FAIL) status=1 ;; esac
    done
  done
  # The issue's targets (Verlet): >= 2x LIGGGHTS's particle-steps/s at every thread count, a
  # 2-thread speed-up >= 1.7, peak memory <= LIGGGHTS's.
  echo
  for th in $THREADS; do
    awk -v m="${NS[verlet,$th]}" -v l="${NS[liggghts,$th]}" -v th="$th" 'BEGIN {
      printf "target speed, %s thread(s): mpdem verlet %.2fx LIGGGHTS (>= 2 wanted): %s\n", th, l / m, (l / m >= 2 ? "met" : "NOT met") }'
    awk -v m="${RSS[verlet,$th]}" -v l="${RSS[liggghts,$th]}" -v th="$th" 'BEGIN {
      printf "target memory, %s thread(s): mpdem %.1f MiB vs LIGGGHTS %.1f MiB: %s\n", th, m / 1024, l / 1024, (m <= l ? "met" : "NOT met") }'
  done
  # Before/after: the new binary's time per particle-step relative to the old one's (medians).
  if [ -n "${MPDEM_OLD:-}" ]; then
    for th in $THREADS; do
      for integ in verlet trapezoidal; do
        awk -v a="${NS[$integ,$th]}" -v b="${NS[old_$integ,$th]}" -v th="$th" -v i="$integ" 'BEGIN {
          printf "new vs old, %s, %s thread(s): %.1f vs %.1f ns/particle-step, %+.1f%%\n", i, th, a, b, 100 * (a / b - 1) }'
      done
    done
  fi
  set -- $THREADS
  if [ $# -ge 2 ]; then
    awk -v a="${NS[verlet,$1]}" -v b="${NS[verlet,$2]}" -v la="${NS[liggghts,$1]}" -v lb="${NS[liggghts,$2]}"       -v t1="$1" -v t2="$2" 'BEGIN {
      printf "speed-up %s -> %s threads: mpdem verlet %.2fx (>= 1.7 wanted: %s), LIGGGHTS %.2fx\n", t1, t2, a / b,
             (a / b >= 1.7 ? "met" : "NOT met"), la / lb }'
  fi
  unset NS RSS CONT REB EVAL SAMPLES MEMS
done
exit $status
