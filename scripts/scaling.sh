#!/usr/bin/env bash
# Scaling of mpdem over MPI ranks and OpenMP threads on the settled-bed protocol of
# scripts/bench_vs_liggghts.sh (docs/parallel.md, "Scaling"; a measurement, not a test).
#
#  1. weak scaling, 49470 spheres per rank: the 100k bed's half (x <= 90 mm) on 1 rank against
#     that half and its mirror image (the two halves side by side in the 100k bed's box) on 2
#     ranks, each rank then holding one half; efficiency = the wall time of a step on 1 rank / on
#     2 ranks (>= 0.9 wanted); beside it LIGGGHTS on the same two beds (1 and 2 ranks), and two
#     independent one-rank runs of the half at once, one per core (no communication at all: what
#     this machine allows two processes that share it);
#  2. strong scaling of the 100k bed: 1 rank x 1 thread, 1 rank x 2 threads, 2 ranks x 1 thread,
#     beside LIGGGHTS on 1 and 2 ranks (hybrid 1x2 and 2x1 within 15 % of each other and mpdem on
#     2 ranks >= 2x LIGGGHTS on 2 ranks wanted);
#  3. correctness beyond the cores: the 20k bed on CHECK_RANKS ranks (oversubscribed): the same
#     contacts, kinetic energy and bed top on every rank count.
#
# Usage: scripts/scaling.sh
# Environment: MPDEM (build/mpdem), WORK (build/bench-bed), RUNS (3: medians of interleaved runs),
#   STEPS (2000) and RELAX (1000) for tables 1-2, CHECK_RANKS ("1 2 4 8"), SHARED (../shared/bench),
#   NO_INSTALL=1 (do not apt-get LIGGGHTS / Open MPI / GNU time).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
MPDEM="${MPDEM:-$ROOT/build/mpdem}"
WORK="${WORK:-$ROOT/build/bench-bed}"
RUNS="${RUNS:-3}"
STEPS="${STEPS:-2000}"
RELAX="${RELAX:-1000}"
CHECK_RANKS="${CHECK_RANKS:-1 2 4 8}"
SHARED="${SHARED:-$ROOT/../shared/bench}"
[ -d "$SHARED" ] || SHARED=/work/shared/bench
# shellcheck source=bench_lib.sh
. "$ROOT/scripts/bench_lib.sh"
bench_tools
[ -x "$MPDEM" ] || { echo "no mpdem executable at $MPDEM (build it, or set MPDEM)" >&2; exit 2; }
mkdir -p "$WORK"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# mpdem RANKS THREADS DATA STEPS RELAX LOG: the BENCH_RESULT line of one mpdem bench run.
mpdem_bench() {
  local ranks=$1 threads=$2 data=$3 steps=$4 relax=$5 log=$6
  local cmd=("$MPDEM" bench "$data" --integrator verlet --threads "$threads" --steps "$steps" --relax "$relax")
  if [ "$ranks" -gt 1 ]; then
    # One core per rank when they fit (oversubscribed runs are for correctness only).
    local bind=(--bind-to core)
    [ "$ranks" -gt "$(nproc)" ] && bind=(--oversubscribe --bind-to none)
    OMP_NUM_THREADS=$threads mpirun -np "$ranks" "${bind[@]}" "${cmd[@]}" > "$log" 2>&1
  else
    env "${MPDEM_OMP_ENV[@]}" "${cmd[@]}" > "$log" 2>&1
  fi
  grep '^BENCH_RESULT' "$log"
}

# on_core CORE COMMAND...: COMMAND (a shell function too) in a subshell bound to one core.
on_core() { (taskset -pc "$1" "$BASHPID" > /dev/null && shift && "$@"); }

half=$(bed_file 50k "$WORK" "$SHARED")
twin=$(bed_file 2x50k "$WORK" "$SHARED")
full=$(bed_file 100k "$WORK" "$SHARED")
small=$(bed_file 20k "$WORK" "$SHARED")
n_half=$(awk '$2 == "atoms" {print $1; exit}' "$half")
n_full=$(awk '$2 == "atoms" {print $1; exit}' "$full")
n_twin=$(awk '$2 == "atoms" {print $1; exit}' "$twin")

declare -A S=() C=()
echo "== $RUNS interleaved runs of: 50k x 1 rank, 2 x 50k x 2 ranks; 100k x (1x1, 1x2, 2x1); LIGGGHTS 50k x 1, 2 x 50k x 2, 100k x 1, 2 ranks; $RELAX + $STEPS steps =="
for r in $(seq 1 "$RUNS"); do
  for cfg in half_1x1 twin_2x1 half_pair lig_half_1 lig_twin_2 full_1x1 full_1x2 full_2x1 lig_1 lig_2; do
    log="$WORK/scaling_${cfg}_r$r"
    case "$cfg" in
      half_1x1) line=$(mpdem_bench 1 1 "$half" "$STEPS" "$RELAX" "$log.out") ;;
      twin_2x1) line=$(mpdem_bench 2 1 "$twin" "$STEPS" "$RELAX" "$log.out") ;;
      half_pair)  # the slower of two concurrent one-rank runs, each on its own core
        on_core 0 mpdem_bench 1 1 "$half" "$STEPS" "$RELAX" "$log.a.out" > /dev/null &
        on_core 1 mpdem_bench 1 1 "$half" "$STEPS" "$RELAX" "$log.b.out" > /dev/null
        wait
        line="ns_per_pstep=$(grep -ho 'ns_per_pstep=[^ ]*' "$log.a.out" "$log.b.out" | cut -d= -f2 | sort -g | tail -1)" ;;
      full_1x1) line=$(mpdem_bench 1 1 "$full" "$STEPS" "$RELAX" "$log.out") ;;
      full_1x2) line=$(mpdem_bench 1 2 "$full" "$STEPS" "$RELAX" "$log.out") ;;
      full_2x1) line=$(mpdem_bench 2 1 "$full" "$STEPS" "$RELAX" "$log.out") ;;
      lig_half_1) line="ns_per_pstep=$(liggghts_ns "$half" "$STEPS" "$RELAX" 1 "$log")" ;;
      lig_twin_2) line="ns_per_pstep=$(liggghts_ns "$twin" "$STEPS" "$RELAX" 2 "$log")" ;;
      lig_1) line="ns_per_pstep=$(liggghts_ns "$full" "$STEPS" "$RELAX" 1 "$log")" ;;
      lig_2) line="ns_per_pstep=$(liggghts_ns "$full" "$STEPS" "$RELAX" 2 "$log")" ;;
    esac
    ns=$(echo "$line" | field ns_per_pstep)
    S[$cfg]+=" $ns"
    C[$cfg]=$(echo "$line" | field coordination)
    echo "  run $r $cfg: $ns ns/particle-step"
  done
done
declare -A M=()
for cfg in "${!S[@]}"; do M[$cfg]=$(echo "${S[$cfg]}" | median); done

echo
echo "Weak scaling (settled bed, $n_half spheres per rank; medians of $RUNS runs)"
echo "| code | ranks x threads | spheres | ns/particle-step | wall ms per step | efficiency |"
echo "|---|---|---|---|---|---|"
weak_rows() {  # weak_rows CODE ONE_RANK_NS TWO_RANKS_NS
  awk -v c="$1" -v a="$2" -v b="$3" -v n1="$n_half" -v n2="$n_twin" 'BEGIN {
    printf "| %s | 1 x 1 | %d | %.1f | %.3f | 1 |\n", c, n1, a, a * n1 * 1e-6
    printf "| %s | 2 x 1 | %d | %.1f | %.3f | %.3f |\n", c, n2, b, b * n2 * 1e-6, (a * n1) / (b * n2) }'
}
weak_rows mpdem "${M[half_1x1]}" "${M[twin_2x1]}"
awk -v a="${M[half_1x1]}" -v b="${M[half_pair]}" -v n1="$n_half" 'BEGIN {
  printf "| mpdem, two independent runs at once | 2 x (1 x 1) | 2 x %d | %.1f (the slower) | %.3f | %.3f |\n", n1, b, b * n1 * 1e-6, a / b }'
weak_rows "LIGGGHTS 3.8" "${M[lig_half_1]}" "${M[lig_twin_2]}"
echo
echo "Strong scaling, 100k bed ($n_full spheres; medians of $RUNS runs)"
echo "| code | ranks x threads | ns/particle-step | particle-steps/s | speed-up | vs LIGGGHTS at the same cores |"
echo "|---|---|---|---|---|---|"
for cfg in full_1x1 full_1x2 full_2x1 lig_1 lig_2; do
  case "$cfg" in
    full_1x1) code=mpdem; shape="1 x 1"; base=${M[full_1x1]}; lig=${M[lig_1]} ;;
    full_1x2) code=mpdem; shape="1 x 2"; base=${M[full_1x1]}; lig=${M[lig_2]} ;;
    full_2x1) code=mpdem; shape="2 x 1"; base=${M[full_1x1]}; lig=${M[lig_2]} ;;
    lig_1) code="LIGGGHTS 3.8"; shape="1 x 1"; base=${M[lig_1]}; lig=${M[lig_1]} ;;
    lig_2) code="LIGGGHTS 3.8"; shape="2 x 1"; base=${M[lig_1]}; lig=${M[lig_2]} ;;
  esac
  awk -v c="$code" -v s="$shape" -v x="${M[$cfg]}" -v b="$base" -v l="$lig" 'BEGIN {
    printf "| %s | %s | %.1f | %.3g | %.2f | %.2fx |\n", c, s, x, 1e9 / x, b / x, l / x }'
done
echo
awk -v a="${M[half_1x1]}" -v t="${M[twin_2x1]}" -v n1="$n_half" -v n2="$n_twin" -v b="${M[full_2x1]}" \
  -v h="${M[full_1x2]}" -v l="${M[lig_2]}" -v la="${M[lig_half_1]}" -v lt="${M[lig_twin_2]}" 'BEGIN {
  e = (a * n1) / (t * n2); d = h / b - 1; s = l / b
  printf "weak-scaling efficiency 1 -> 2 ranks: %.3f (>= 0.9 wanted: %s); LIGGGHTS on the same beds: %.3f\n", e,
         (e >= 0.9 ? "met" : "NOT met"), (la * n1) / (lt * n2)
  printf "hybrid 1x2 vs 2x1: %.1f vs %.1f ns/particle-step, %+.1f%% (within 15%% wanted: %s)\n", h, b, 100 * d,
         (d <= 0.15 && d >= -0.15 ? "met" : "NOT met")
  printf "2 ranks: mpdem %.2fx LIGGGHTS (>= 2 wanted: %s)\n", s, (s >= 2 ? "met" : "NOT met") }'
echo "contacts per particle (coordination): 50k 1x1 ${C[half_1x1]}, 2 x 50k 2x1 ${C[twin_2x1]}, 100k 1x1 ${C[full_1x1]}, 1x2 ${C[full_1x2]}, 2x1 ${C[full_2x1]}"

echo
echo "Correctness on more ranks than cores (20k bed, 100 + 300 steps; the physics, not the speed)"
echo "| ranks | contacts per particle | kinetic energy (J) | top of bed z (m) |"
echo "|---|---|---|---|"
status=0
ref=""
for np in $CHECK_RANKS; do
  line=$(mpdem_bench "$np" 1 "$small" 300 100 "$WORK/scaling_check_np$np.out")
  c=$(echo "$line" | field coordination) ke=$(echo "$line" | field ke) z=$(echo "$line" | field zmax)
  echo "| $np | $c | $ke | $z |"
  [ -z "$ref" ] && ref="$c $ke $z"
  # Contact counts equal; energy and top within round-off's reach over 400 steps of a static bed.
  awk -v r="$ref" -v c="$c" -v ke="$ke" -v z="$z" 'BEGIN { split(r, a, " ");
    bad = (c != a[1]) || (ke - a[2] > 1e-6 * a[2] || a[2] - ke > 1e-6 * a[2]) || (z - a[3] > 1e-12 || a[3] - z > 1e-12)
    exit bad }' || { echo "  $np ranks differ from the first rank count" >&2; status=1; }
done
exit $status
