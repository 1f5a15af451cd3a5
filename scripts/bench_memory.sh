#!/usr/bin/env bash
# Peak memory per particle (issue 21 item 4; docs/benchmark.md, "Memory"): the settled 100k bed
# through `mpdem bench` (its protocol, Verlet, 1000 + 2000 steps) and boxes of generated spheres
# through `mpdem run` (bench/memory/box.toml.in: radius 1 mm, solid fraction 0.3, random
# velocities of 0.5 m/s, so that they collide and the list is rebuilt). Peak RSS from GNU time:
# the whole process, libraries included (about 8 MiB on Debian 12).
#
# Usage: scripts/bench_memory.sh
# Environment:
#   MPDEM       mpdem executable (default: build/mpdem)
#   MPDEM_OLD   a second (older) mpdem executable, run after MPDEM on every case
#   WORK        scratch folder (default: build/bench-memory)
#   COUNTS      sphere counts of the boxes (default "100000 1000000")
#   STEPS       steps of 1.5e-6 s of each box run (default 1000: several rebuilds)
#   INTEGRATORS integrators of the box runs (default "verlet trapezoidal")
#   THREADS     threads (default 2)
#   BOUND       bytes per particle the peaks must stay within (default 560; exit 1 when one does not)
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
. "$ROOT/scripts/bench_lib.sh"
MPDEM="${MPDEM:-$ROOT/build/mpdem}"
WORK="${WORK:-$ROOT/build/bench-memory}"
COUNTS="${COUNTS:-100000 1000000}"
STEPS="${STEPS:-1000}"
INTEGRATORS="${INTEGRATORS:-verlet trapezoidal}"
THREADS="${THREADS:-2}"
BOUND="${BOUND:-560}"
[ -x /usr/bin/time ] || { echo "GNU time (/usr/bin/time) is needed: apt-get install time" >&2; exit 2; }
mkdir -p "$WORK"
codes=(new)
[ -n "${MPDEM_OLD:-}" ] && codes+=(old)
exe() { if [ "$1" = new ]; then echo "$MPDEM"; else echo "$MPDEM_OLD"; fi; }

rows=()
fail=0
row() {  # code case particles kib
  local bpp
  bpp=$(awk -v k="$4" -v n="$3" 'BEGIN {printf "%.0f", k * 1024 / n}')
  rows+=("$(printf '%-4s %-32s %9s %9.1f %6s' "$1" "$2" "$3" "$(awk -v k="$4" 'BEGIN {print k / 1024}')" "$bpp")")
  [ "$1" = new ] && [ "$bpp" -gt "$BOUND" ] && fail=1
  return 0
}

bed=$(bed_file 100k "$WORK" "$ROOT/../shared/bench")
for code in "${codes[@]}"; do
  out=$("$(exe "$code")" bench "$bed" --threads "$THREADS" --steps 2000 --relax 1000 2>&1 | grep BENCH_RESULT)
  row "$code" "bed 100k, verlet (bench)" 100000 "$(echo "$out" | field peak_rss_kib)"
done

for n in $COUNTS; do
  side=$(awk -v n="$n" 'BEGIN {printf "%.4f", (n * 4.18879e-9 / 0.3) ^ (1 / 3)}')  # m
  for integ in $INTEGRATORS; do
    for code in "${codes[@]}"; do
      dir="$WORK/box_${n}_${integ}_$code"
      rm -rf "$dir" && mkdir -p "$dir"
      fill_template "$ROOT/bench/memory/box.toml.in" "$dir/scene.toml" COUNT "$n" SIDE "$side" \
        OUTER "$(awk -v s="$side" 'BEGIN {print s + 0.1}')" DURATION "$(awk -v k="$STEPS" 'BEGIN {print k * 1.5e-6}')" \
        INTEGRATOR "$integ"
      (cd "$dir" && /usr/bin/time -v "$(exe "$code")" run scene.toml --threads "$THREADS" > run.log 2> time.log) ||
        { echo "run failed: $dir" >&2; tail -5 "$dir/time.log" >&2; exit 1; }
      row "$code" "box $n, $integ (run)" "$n" "$(peak_kib "$dir/time.log")"
    done
  done
done

echo "Peak RSS per particle, $THREADS threads (bound $BOUND B)"
printf '%-4s %-32s %9s %9s %6s\n' code case particles "RSS MiB" "B/p"
printf '%s\n' "${rows[@]}"
exit $fail
