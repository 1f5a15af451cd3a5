#!/usr/bin/env bash
# Flowing benchmark, mpdem against LIGGGHTS 3.8 on the same machine (docs/benchmark.md, "Flowing
# silo"): a hopper of 20 000 spheres discharging through its outlet, the spheres removed below it.
#
# Usage: scripts/bench_silo_vs_liggghts.sh
# Environment:
#   MPDEM      mpdem executable (default: build/mpdem)
#   MPDEM_OLD  a second (older) mpdem executable, run interleaved with MPDEM and reported beside it
#   WORK       scratch folder (default: build/bench-silo); the settled bed is made there once per
#              PARTICLES and reused
#   RUNS       repetitions of every configuration, median reported (default 3)
#   THREADS    thread / rank counts to run (default "1 2")
#   PARTICLES  spheres (default 20000)
#   DURATION   simulated discharge time, s (default 0.1: 25 000 steps of 4e-6 s)
#   RATE_FROM  the discharge rate is the slope of the particle count from this time on, s (default 0.03)
#   NO_INSTALL=1  do not apt-get install missing LIGGGHTS / Open MPI / GNU time
#   NO_LEDGER=1   also run MPDEM with [checks] energy_ledger = false, interleaved like the others,
#                 as the row "mpdem verlet, no ledger"
#
# 1. Once: `mpdem mesh funnel` writes the hopper's STL (both codes read it), bench/silo/make_silo.py
#    a jittered lattice of spheres, and mpdem lets it settle on a closed outlet (a lid, 0.15 s,
#    untimed); make_silo.py writes the settled spheres, at rest, for both codes.
# 2. Timed, interleaved: LIGGGHTS (bench/silo/liggghts_silo.in, one rank per thread) and mpdem
#    (velocity Verlet, bench/silo/silo.toml.in) run the same discharge from the settled bed for
#    DURATION, the outlet open from t = 0. Wall time: LIGGGHTS's "Loop time", mpdem's "done: ... in
#    X s" (both the time loop only). Particle-steps: the particle count of every log row (each 2500
#    steps), trapezoidal sum, from each code's own rows.
# 3. The table: wall time, ns per particle-step, discharge rate, peak RSS; the discharge rates must
#    agree within 10 % (exit status 1 if not: then speeds are not comparable).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
MPDEM="${MPDEM:-$ROOT/build/mpdem}"
WORK="${WORK:-$ROOT/build/bench-silo}"
RUNS="${RUNS:-3}"
THREADS="${THREADS:-1 2}"
PARTICLES="${PARTICLES:-20000}"
DURATION="${DURATION:-0.1}"
RATE_FROM="${RATE_FROM:-0.03}"
SETTLE=0.15                    # s, settling of the lattice on the closed outlet (untimed)
DT=4e-6                        # s, both codes
PY=/usr/bin/python3
SILO="$ROOT/bench/silo"

# shellcheck source=bench_lib.sh
. "$ROOT/scripts/bench_lib.sh"
bench_tools
[ -x "$MPDEM" ] || { echo "no mpdem executable at $MPDEM (build it, or set MPDEM)" >&2; exit 2; }
mkdir -p "$WORK"
WORK="$(cd "$WORK" && pwd)"

# scene FILE PARTICLES LID DURATION OUTDIR CSV_EVERY: an mpdem scene from silo.toml.in.
scene() {
  fill_template "$SILO/silo.toml.in" "$1" PARTICLES "$2" LID "$3" DURATION "$4" INTEGRATOR verlet OUTDIR "$5" \
    CSV_EVERY "$6"
}

# 1. The hopper and the settled bed (once per PARTICLES).
BED="$WORK/bed$PARTICLES"
if [ ! -s "$BED/particles.data" ]; then
  rm -rf "$BED" && mkdir -p "$BED/settle"
  "$MPDEM" mesh funnel --top-radius 0.025 --outlet-radius 0.01 --height 0.03 --wall-height 0.2 \
    --segments 48 -o "$BED/silo.stl" > /dev/null
  "$MPDEM" mesh rect --size 0.024 0.024 -o "$BED/settle/lid.csv" --group lid --first-id 1000 > /dev/null
  cp "$BED/silo.stl" "$BED/settle/"
  "$PY" "$SILO/make_silo.py" "$BED/settle" --particles "$PARTICLES"
  scene "$BED/settle/scene.toml" particles.csv '[[barriers]]
file = "lid.csv"          # closes the outlet while the lattice settles
material = "beads"
' "$SETTLE" out "$SETTLE"
  echo "settling $PARTICLES spheres for $SETTLE s on the closed outlet (untimed) ..."
  "$MPDEM" run "$BED/settle/scene.toml" --overwrite > "$BED/settle/run.out" 2>&1
  "$PY" "$SILO/make_silo.py" "$BED" --from-snapshot "$(ls "$BED"/settle/out/particles_csv/*.csv | tail -1)"
fi
n=$(awk '$2 == "atoms" {print $1; exit}' "$BED/particles.data")
steps=$(awk -v t="$DURATION" -v dt="$DT" 'BEGIN {printf "%d", t / dt + 0.5}')
echo "== flowing silo: $n spheres, $steps steps ($DURATION s), $RUNS runs per configuration =="

# count_stats FILE: "particle_steps rate" from rows "step count" (rate: particles/s, the negated
# least-squares slope of the count against time from RATE_FROM on).
count_stats() {
  awk -v dt="$DT" -v from="$RATE_FROM" '
    NR > 1 { ps += (c0 + $2) / 2 * ($1 - s0) }
    { s0 = $1; c0 = $2; t = $1 * dt
      if (t >= from - 1e-12) { k++; st += t; sc += $2; stt += t * t; stc += t * $2 } }
    END { slope = (k * stc - st * sc) / (k * stt - st * st); printf "%.6g %.6g\n", ps, -slope }' "$1"
}

declare -A SAMPLES=() MEMS=() RATES=() NS=() RSS=() RATE=() WALL=() WALLS=()
for th in $THREADS; do
  for r in $(seq 1 "$RUNS"); do
    log="$WORK/liggghts_np${th}_r$r"
    liggghts_job "$log" "$th" "$SILO/liggghts_silo.in" -var data "$BED/particles.data" -var stl "$BED/silo.stl" \
      -var nsteps "$steps"
    secs=$(awk '/^Loop time of/ {print $4; exit}' "$log.out")
    awk '/Step +Atoms/ {on = 1; next} on && NF == 3 && $1 ~ /^[0-9]+$/ {print $1, $2} /^Loop time/ {on = 0}' \
      "$log.out" > "$log.counts"
    read -r ps rate < <(count_stats "$log.counts")
    SAMPLES[liggghts,$th]+=" $(awk -v s="$secs" -v p="$ps" 'BEGIN {printf "%.3f", 1e9 * s / p}')"
    WALLS[liggghts,$th]+=" $secs"
    RATES[liggghts,$th]+=" $rate"
    MEMS[liggghts,$th]+=" $(cat "$log".rank* | awk '{s += $1} END {print s}')"
    echo "  liggghts np=$th run $r: $secs s, $(echo "${SAMPLES[liggghts,$th]}" | awk '{print $NF}') ns/particle-step, discharge $rate /s"

    order="new noledger old"; [ $((r % 2)) -eq 0 ] && order="old noledger new"
    for which in $order; do
      exe=$MPDEM; code=verlet
      if [ "$which" = old ]; then [ -n "${MPDEM_OLD:-}" ] || continue; exe=$MPDEM_OLD; code=old_verlet; fi
      if [ "$which" = noledger ]; then [ "${NO_LEDGER:-0}" = 1 ] || continue; code=verlet_noledger; fi
      dir="$WORK/mpdem_${code}_t${th}_r$r"
      rm -rf "$dir" && mkdir -p "$dir"
      cp "$BED/particles.csv" "$BED/silo.stl" "$dir/"
      scene "$dir/scene.toml" particles.csv "" "$DURATION" out 0
      [ "$code" = verlet_noledger ] && sed -i 's/^\[checks\]$/[checks]\nenergy_ledger = false/' "$dir/scene.toml"
      env "${MPDEM_OMP_ENV[@]}" /usr/bin/time -v "$exe" run "$dir/scene.toml" --threads "$th" --overwrite \
        > "$dir/run.out" 2> "$dir/run.err"
      secs=$(run_seconds "$dir/run.out" "$dir/run.err")
      awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) if ($i == "particles") c = i; next} {print $1, $c}' \
        "$dir/out/log.csv" > "$dir/counts"
      read -r ps rate < <(count_stats "$dir/counts")
      SAMPLES[$code,$th]+=" $(awk -v s="$secs" -v p="$ps" 'BEGIN {printf "%.3f", 1e9 * s / p}')"
      WALLS[$code,$th]+=" $secs"
      RATES[$code,$th]+=" $rate"
      MEMS[$code,$th]+=" $(peak_kib "$dir/run.err")"
      echo "  mpdem $code threads=$th run $r: $secs s, $(echo "${SAMPLES[$code,$th]}" | awk '{print $NF}') ns/particle-step, discharge $rate /s"
    done
  done
  CODES="liggghts verlet"
  [ -n "${MPDEM_OLD:-}" ] && CODES="liggghts verlet old_verlet"
  [ "${NO_LEDGER:-0}" = 1 ] && CODES="${CODES/verlet/verlet verlet_noledger}"
  for code in $CODES; do
    NS[$code,$th]=$(echo "${SAMPLES[$code,$th]}" | median)
    WALL[$code,$th]=$(echo "${WALLS[$code,$th]}" | median)
    RATE[$code,$th]=$(echo "${RATES[$code,$th]}" | median)
    RSS[$code,$th]=$(echo "${MEMS[$code,$th]}" | median)
  done
done

echo
echo "Flowing silo ($n spheres, $steps steps of $DT s; discharge rate from t = $RATE_FROM s; medians of $RUNS interleaved runs; peak RSS of the job (LIGGGHTS: sum over its ranks))"
printf '| %-20s | %7s | %8s | %9s | %14s | %8s | %14s |\n' code threads "wall s" ns/p-step "discharge 1/s" "RSS MiB" "speed vs LIGGGHTS"
printf '|%s|\n' "----------------------|---------|----------|-----------|----------------|----------|-------------------"
status=0
for th in $THREADS; do
  for code in $CODES; do
    label=$code; [ "$code" = liggghts ] && label="LIGGGHTS 3.8 (MPI)"; [ "$code" = verlet ] && label="mpdem verlet"
    [ "$code" = old_verlet ] && label="old mpdem verlet"
    [ "$code" = verlet_noledger ] && label="mpdem verlet, no ledger"
    printf '| %-20s | %7s | %8.2f | %9.1f | %14.0f | %8.1f | %17.2fx |\n' "$label" "$th" "${WALL[$code,$th]}" "${NS[$code,$th]}" \
      "${RATE[$code,$th]}" "$(awk -v k="${RSS[$code,$th]}" 'BEGIN {print k / 1024}')" \
      "$(awk -v a="${NS[$code,$th]}" -v b="${NS[liggghts,$th]}" 'BEGIN {print b / a}')"
  done
done
echo
for th in $THREADS; do
  ok=$(awk -v a="${RATE[verlet,$th]}" -v b="${RATE[liggghts,$th]}" \
    'BEGIN {d = (a - b) / b; printf "%+.1f%% %s", 100 * d, (d <= 0.1 && d >= -0.1 ? "ok" : "FAIL")}')
  echo "discharge check, $th thread(s): mpdem ${RATE[verlet,$th]} vs LIGGGHTS ${RATE[liggghts,$th]} spheres/s: $ok (within 10 % wanted)"
  case "$ok" in *FAIL) status=1 ;; esac
  awk -v m="${NS[verlet,$th]}" -v l="${NS[liggghts,$th]}" -v th="$th" 'BEGIN {
    printf "target speed, %s thread(s): mpdem verlet %.2fx LIGGGHTS (>= 2.5 wanted): %s\n", th, l / m, (l / m >= 2.5 ? "met" : "NOT met") }'
  if [ -n "${MPDEM_OLD:-}" ]; then
    awk -v a="${NS[verlet,$th]}" -v b="${NS[old_verlet,$th]}" -v th="$th" 'BEGIN {
      printf "new vs old, %s thread(s): %.1f vs %.1f ns/particle-step, %+.1f%%\n", th, a, b, 100 * (a / b - 1) }'
  fi
done
exit $status
