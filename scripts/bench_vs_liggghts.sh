#!/usr/bin/env bash
# Settled-bed benchmark, mpdem against LIGGGHTS 3.8 on the same machine (docs/benchmark.md).
#
# Usage: scripts/bench_vs_liggghts.sh [20k|100k] ...
# Environment:
#   MPDEM      mpdem executable with the `bench` subcommand (default: build/mpdem)
#   WORK       scratch folder for the decompressed beds and logs (default: build/bench-bed)
#   RUNS       repetitions of every configuration, median reported (default 3, at least 3 advised)
#   THREADS    thread / rank counts to run (default "1 2")
#   STEPS      timed steps (default: 5000 for 20k, 2000 for 100k - the bench README protocol)
#   RELAX      untimed steps first (default 1000)
#   TRAP_STEPS timed steps of the trapezoidal runs (default: STEPS; it costs ~5 evaluations a step,
#              so a shorter window keeps the script's run time reasonable - the bed is static)
#   SHARED     folder with the reference inputs (default: ../shared/bench beside the repository)
#   NO_INSTALL=1  do not apt-get install missing LIGGGHTS / Open MPI / GNU time
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

# --- tools -----------------------------------------------------------------------------------
need=()
command -v liggghts >/dev/null 2>&1 || need+=(liggghts)
command -v mpirun >/dev/null 2>&1 || need+=(openmpi-bin)
[ -x /usr/bin/time ] || need+=(time)
if [ ${#need[@]} -gt 0 ]; then
  if [ "${NO_INSTALL:-0}" = 1 ]; then echo "missing: ${need[*]}" >&2; exit 2; fi
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q >/dev/null
  $SUDO apt-get install -y -q --no-install-recommends "${need[@]}" >/dev/null
fi
[ -x "$MPDEM" ] || { echo "no mpdem executable at $MPDEM (build it, or set MPDEM)" >&2; exit 2; }
"$MPDEM" bench --help >/dev/null 2>&1 || { echo "$MPDEM has no 'bench' subcommand" >&2; exit 2; }
mkdir -p "$WORK"
PY=/usr/bin/python3

median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR]=$1} END {if (NR%2) print a[(NR+1)/2]; else print (a[NR/2]+a[NR/2+1])/2}'; }
# value of key=... in a BENCH_RESULT / BENCH_STATE line
field() { tr ' ' '\n' | sed -n "s/^$1=//p" | head -1; }
peak_kib() { sed -n 's/.*Maximum resident set size (kbytes): *//p' "$1" | tail -1; }

status=0
for bed in "${BEDS[@]}"; do
  case "$bed" in
    20k) steps="${STEPS:-5000}" ;;
    100k) steps="${STEPS:-2000}" ;;
    *) echo "unknown bed '$bed' (20k or 100k)" >&2; exit 2 ;;
  esac
  data="$WORK/bed$bed.data"
  [ -s "$data" ] || gzip -dc "$SHARED/bed$bed.data.gz" > "$data"
  n=$(awk '$2 == "atoms" {print $1; exit}' "$data")
  echo "== bed $bed: $n particles, $RELAX untimed + $steps timed steps, $RUNS runs per configuration =="

  declare -A NS=() RSS=() CONT=() REB=() EVAL=()
  for th in $THREADS; do
    # LIGGGHTS: "Loop time" of the timed run (the run after TIMED_RUN_BEGIN); one MPI rank per "thread".
    lt=(); lm=(); lc=""
    for r in $(seq 1 "$RUNS"); do
      log="$WORK/liggghts_${bed}_np${th}_r$r"
      cmd=(liggghts -in "$SHARED/liggghts_bench.in" -log "$log.log" -var data "$data" -var nrelax "$RELAX"
           -var nsteps "$steps" -var dt 4e-6)
      [ "$th" -gt 1 ] && cmd=(mpirun -np "$th" --allow-run-as-root --oversubscribe "${cmd[@]}")
      (cd "$WORK" && OMP_NUM_THREADS=1 /usr/bin/time -v "${cmd[@]}" > "$log.out" 2> "$log.time")
      secs=$(awk '/TIMED_RUN_BEGIN/ {t=1} t && /^Loop time of/ {print $4; exit}' "$log.out")
      lt+=("$(awk -v s="$secs" -v n="$n" -v k="$steps" 'BEGIN {printf "%.3f", 1e9 * s / (n * k)}')")
      lm+=("$(peak_kib "$log.time")")
      lc=$(grep '^BENCH_STATE' "$log.out" | field contacts_per_particle)
      echo "  liggghts np=$th run $r: ${secs} s timed, ${lt[-1]} ns/particle-step, contacts/particle $lc"
    done
    NS[liggghts,$th]=$(echo "${lt[*]}" | median); RSS[liggghts,$th]=$(echo "${lm[*]}" | median)
    CONT[liggghts,$th]=$lc; REB[liggghts,$th]="-"; EVAL[liggghts,$th]=1

    for integ in verlet trapezoidal; do
      mt=(); mm=(); mc=""
      for r in $(seq 1 "$RUNS"); do
        log="$WORK/mpdem_${bed}_${integ}_t${th}_r$r"
        k=$steps; [ "$integ" = trapezoidal ] && k=${TRAP_STEPS:-$steps}
        /usr/bin/time -v "$MPDEM" bench "$data" --integrator "$integ" --phi 0.5 --threads "$th" --steps "$k" \
          --relax "$RELAX" > "$log.out" 2> "$log.time"
        line=$(grep '^BENCH_RESULT' "$log.out")
        mt+=("$(echo "$line" | field ns_per_pstep)")
        mm+=("$(peak_kib "$log.time")")
        mc=$(echo "$line" | field coordination)
        REB[$integ,$th]=$(echo "$line" | field rebuilds)
        EVAL[$integ,$th]=$(echo "$line" | field evals_per_step)
        echo "  mpdem $integ threads=$th run $r: ${mt[-1]} ns/particle-step, contacts/particle $mc, rebuilds ${REB[$integ,$th]}"
      done
      NS[$integ,$th]=$(echo "${mt[*]}" | median); RSS[$integ,$th]=$(echo "${mm[*]}" | median); CONT[$integ,$th]=$mc
    done
  done

  echo
  echo "Bed $bed ($n particles, $steps timed steps (trapezoidal ${TRAP_STEPS:-$steps}); medians of $RUNS runs; peak RSS per process, from /usr/bin/time -v)"
  printf '| %-22s | %7s | %9s | %12s | %6s | %8s | %9s | %8s | %14s |\n' code threads ns/p-step "p-steps/s" \
    evals rebuilds contacts/p "RSS MiB" "mpdem/LIGGGHTS"
  printf '|%s|\n' "------------------------|---------|-----------|--------------|--------|----------|-----------|----------|----------------"
  for th in $THREADS; do
    for code in liggghts verlet trapezoidal; do
      ns=${NS[$code,$th]}
      ratio=$(awk -v a="$ns" -v b="${NS[liggghts,$th]}" 'BEGIN {printf "%.2f", a / b}')
      [ "$code" = liggghts ] && ratio="1"
      label=$code; [ "$code" = liggghts ] && label="LIGGGHTS 3.8 (MPI)"; [ "$code" = verlet ] && label="mpdem verlet"
      [ "$code" = trapezoidal ] && label="mpdem trapezoidal 0.5"
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
  unset NS RSS CONT REB EVAL
done
exit $status
