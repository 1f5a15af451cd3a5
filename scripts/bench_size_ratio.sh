#!/usr/bin/env bash
# Wide size ratios (issue 21 item 5; docs/benchmark.md, "Wide size ratios"): the cost per contact
# of beds with radius ratio 1:20 against beds of one size, velocity Verlet, mpdem only.
#
# Usage: scripts/bench_size_ratio.sh
# Environment:
#   MPDEM      mpdem executable (default: build/mpdem)
#   MPDEM_OLD  a second (older) mpdem executable, run interleaved with MPDEM and reported beside it
#   WORK       scratch folder (default: build/bench-size-ratio); the settled beds are made there
#              once (by MPDEM) and reused
#   RUNS       repetitions of every timed run, median reported (default 3)
#   THREADS    thread counts (default "1")
#   N          spheres of the bimodal bed (default 8000: 1 % of them large)
#   NU         spheres of the uniform bed (default 2000)
#   STEPS      timed steps from the settled beds (default 10000)
#   POUR       simulated time of the pours, s (default 0.1)
#
# The beds, each generated in an open box (`mpdem mesh box`) at solid fraction 0.25, the largest
# spheres at the bottom, and settled under gravity (untimed; the box is sized so the generated
# column is 1.5 times as tall as wide):
#   bimodal  N spheres, 99 % of radius R0 = 1 mm and 1 % of radius 20 R0 (by number)
#   small    the settled bimodal bed without its large spheres: its small spheres alone, in the
#            same box, settled again
#   uniform  NU spheres, radius uniform in [R0, 20 R0] (by number; generated in four bands)
#   mono     spheres of radius R0, as many as give the uniform bed's contact count (from the
#            contacts per sphere of a first mono bed of NU spheres)
# The timed run starts from the settled spheres at rest and takes STEPS steps of 4e-6 s. Cost per
# contact = wall time of the run's time loop / (STEPS x mean contacts), contacts = particle-particle
# + particle-wall, the mean of the log rows (every 500 steps). The issue's bounds: bimodal / small
# <= 1.3, uniform / mono <= 1.5; the script exits 1 when a bound fails. The pours (spheres falling
# into the box, lists rebuilt often; per particle-step, few contacts yet): pour_bimodal is the first
# POUR s of the bimodal bed's settling run, pour_small the same without its large spheres.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
MPDEM="${MPDEM:-$ROOT/build/mpdem}"
WORK="${WORK:-$ROOT/build/bench-size-ratio}"
RUNS="${RUNS:-3}"
THREADS="${THREADS:-1}"
N="${N:-8000}"
NU="${NU:-2000}"
STEPS="${STEPS:-10000}"
POUR="${POUR:-0.1}"
TEMPLATE="$ROOT/bench/size_ratio/mixture.toml.in"

# shellcheck source=bench_lib.sh
. "$ROOT/scripts/bench_lib.sh"
[ -x "$MPDEM" ] || { echo "no mpdem executable at $MPDEM (build it, or set MPDEM)" >&2; exit 2; }
mkdir -p "$WORK"
WORK="$(cd "$WORK" && pwd)"

# scene FILE SOURCE DURATION CSV_EVERY: an mpdem scene from the template.
scene() { fill_template "$TEMPLATE" "$1" SOURCE "$2" DURATION "$3" CSV_EVERY "$4"; }

# settle NAME CLASS...: generates the classes "COUNT|RADIUS_TABLE|MEAN_R3|R_MAX" (radius table in
# TOML, mean r^3 in m^3, largest radius in m), the first at the bottom, each in a layer of the
# column holding it at solid fraction 0.25 (and at least 8 R_MAX tall), and lets them settle; writes
# WORK/NAME/particles.csv (at rest). Largest first: a large sphere landing on small ones at the
# same density would crush them.
settle() {
  local name=$1 dir="$WORK/$1"
  shift
  [ -s "$dir/particles.csv" ] && return 0
  rm -rf "$dir" && mkdir -p "$dir/settle"
  local total=0 cls count radius r3 rmax
  for cls in "$@"; do
    IFS='|' read -r count radius r3 rmax <<< "$cls"
    total=$(awk -v t="$total" -v n="$count" -v r3="$r3" 'BEGIN {printf "%.10g", t + n * 4.18879 * r3}')
  done
  # Box side L: solid volume / 0.25 = L x L x 1.5 L.
  local side half
  side=$(awk -v v="$total" 'BEGIN {printf "%.5f", (v / 0.25 / 1.5) ^ (1 / 3)}')
  half=$(awk -v l="$side" 'BEGIN {printf "%.6f", l / 2}')
  local z0=0 z1 src="" seed=7
  for cls in "$@"; do
    IFS='|' read -r count radius r3 rmax <<< "$cls"
    z1=$(awk -v z="$z0" -v l="$side" -v n="$count" -v r3="$r3" -v rm="$rmax" \
      'BEGIN {h = n * 4.18879 * r3 / 0.25 / (l * l); if (h < 8 * rm) h = 8 * rm; printf "%.6f", z + h}')
    [ -n "$src" ] && src="$src
[[particles]]
material = \"beads\"
"
    src="${src}generate = { region = \"box\", min = [-$half, -$half, $z0], max = [$half, $half, $z1], count = $count, radius = $radius, seed = $seed }"
    z0=$z1
    seed=$((seed + 1))
  done
  # Settling time: the fall from the top + 0.8 s (the small spheres rattle down through the pores).
  local settle_s
  settle_s=$(awk -v h="$z0" 'BEGIN {printf "%.3f", sqrt(2 * h / 9.81) + 0.8}')
  "$MPDEM" mesh box --size "$side" "$side" "$(awk -v h="$z0" 'BEGIN {print 1.2 * h}')" -o "$dir/settle/box.csv" \
    --group walls > /dev/null
  cp "$dir/settle/box.csv" "$dir/"
  scene "$dir/settle/scene.toml" "$src" "$settle_s" "$settle_s"
  echo "settling $name: $* in a ${side} m box for $settle_s s (untimed) ..." >&2
  settle_run "$dir"
}

# settle_run DIR: runs DIR/settle/scene.toml and writes its last snapshot, at rest, to
# DIR/particles.csv (id, position, radius).
settle_run() {
  "$MPDEM" run "$1/settle/scene.toml" --overwrite > "$1/settle/run.out" 2>&1
  awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; print "id,x,y,z,radius"; next}
           {print $c["id"] "," $c["x"] "," $c["y"] "," $c["z"] "," $c["radius"]}' \
    "$(ls "$1"/settle/out/particles_csv/*.csv | tail -1)" > "$1/particles.csv"
}

# timed EXE NAME THREADS TAG: one timed run; prints "seconds contacts ns_per_contact_step
# ns_per_particle_step" (contacts: the mean of the log rows after the first; particles: the first row's).
timed() {
  local exe=$1 name=$2 th=$3 tag=$4 dir="$WORK/$2/run_$4" steps=$STEPS
  rm -rf "$dir" && mkdir -p "$dir"
  if [ -s "$WORK/$name/scene.toml" ]; then  # a pour: its own scene
    cp "$WORK/$name/scene.toml" "$WORK/$name/box.csv" "$dir/"
    steps=$(awk -v t="$POUR" 'BEGIN {printf "%d", t / 4e-6 + 0.5}')
  else
    cp "$WORK/$name/particles.csv" "$WORK/$name/box.csv" "$dir/"
    scene "$dir/scene.toml" 'file = "particles.csv"' "$(awk -v s="$STEPS" 'BEGIN {printf "%.10g", s * 4e-6}')" 0
  fi
  env "${MPDEM_OMP_ENV[@]}" "$exe" run "$dir/scene.toml" --threads "$th" --overwrite > "$dir/run.out" 2> "$dir/run.err"
  local secs contacts
  secs=$(run_seconds "$dir/run.out" "$dir/run.err")
  contacts=$(awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next}
                      NR > 2 {s += $c["contacts_pp"] + $c["contacts_pb"]; k++} END {printf "%.1f", s / k}' "$dir/out/log.csv")
  local parts
  parts=$(awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) c[$i] = i; next} {print $c["particles"]; exit}' "$dir/out/log.csv")
  echo "$secs $contacts $(awk -v s="$secs" -v c="$contacts" -v n="$steps" 'BEGIN {printf "%.3f", 1e9 * s / (c * n)}') $(
    awk -v s="$secs" -v p="$parts" -v n="$steps" 'BEGIN {printf "%.3f", 1e9 * s / (p * n)}')"
}

R0=0.001
# uniform CLASS_COUNT LO HI: a class of radii uniform in [LO, HI] m.
uniform() { echo "$1|{ distribution = \"uniform\", min = $2, max = $3 }|$(awk -v a="$2" -v b="$3" 'BEGIN {print (b ^ 4 - a ^ 4) / (4 * (b - a))}')|$3"; }
settle bimodal "$((N / 100))|0.02|8e-6|0.02" "$((N * 99 / 100))|$R0|1e-9|$R0"
# small: the settled bimodal bed without its large spheres (same box), settled again (0.5 s).
if [ ! -s "$WORK/small/particles.csv" ]; then
  rm -rf "$WORK/small" && mkdir -p "$WORK/small/settle"
  cp "$WORK/bimodal/box.csv" "$WORK/small/"
  cp "$WORK/bimodal/box.csv" "$WORK/small/settle/"
  awk -F, -v r0="$R0" 'NR == 1 || $5 + 0 < 1.5 * r0' "$WORK/bimodal/particles.csv" > "$WORK/small/settle/start.csv"
  scene "$WORK/small/settle/scene.toml" 'file = "start.csv"' 0.5 0.5
  echo "settling small: the bimodal bed's small spheres alone for 0.5 s (untimed) ..." >&2
  settle_run "$WORK/small"
fi
# Uniform in [R0, 20 R0] by number, generated in four bands (each uniform, counts by band width).
n1=$((NU * 10 / 19)); n2=$((NU * 5 / 19)); n3=$((NU * 25 / 190))
settle uniform "$(uniform "$n1" 0.01 0.02)" "$(uniform "$n2" 0.005 0.01)" "$(uniform "$n3" 0.0025 0.005)" \
  "$(uniform $((NU - n1 - n2 - n3)) $R0 0.0025)"
# mono: spheres of radius R0, as many as give the uniform bed's contacts at the contacts per sphere of
# a first mono bed of NU spheres (untimed probe runs).
if [ ! -s "$WORK/mono/particles.csv" ]; then
  settle mono_probe "$NU|$R0|1e-9|$R0"
  read -r _ c_probe _ < <(timed "$MPDEM" mono_probe 1 probe)
  read -r _ c_uni _ < <(timed "$MPDEM" uniform 1 probe)
  n_mono=$(awk -v cu="$c_uni" -v cp="$c_probe" -v n="$NU" 'BEGIN {printf "%d", cu / (cp / n) + 0.5}')
  settle mono "$n_mono|$R0|1e-9|$R0"
fi

# Pours: the first POUR s of the bimodal bed's settling run, and of the same run without the large
# spheres (the small ones generated in the same layer): spheres falling, lists rebuilt often.
for bed in bimodal small; do
  dir="$WORK/pour_$bed"
  [ -s "$dir/scene.toml" ] && continue
  mkdir -p "$dir"
  cp "$WORK/bimodal/box.csv" "$dir/"
  src=$(grep '^generate = ' "$WORK/bimodal/settle/scene.toml")
  [ "$bed" = small ] && src=$(echo "$src" | tail -1)
  src=$(echo "$src" | awk 'NR > 1 {print "[[particles]]"; print "material = \"beads\""} {print}')
  scene "$dir/scene.toml" "$src" "$POUR" 0
done

BEDS="small bimodal uniform mono"
declare -A SAMPLES=() PSAMPLES=() CONTACTS=() PARTS=() NSC=() NSP=()
for th in $THREADS; do
  for r in $(seq 1 "$RUNS"); do
    order="new old"; [ $((r % 2)) -eq 0 ] && order="old new"
    for which in $order; do
      exe=$MPDEM
      if [ "$which" = old ]; then [ -n "${MPDEM_OLD:-}" ] || continue; exe=$MPDEM_OLD; fi
      for bed in $BEDS pour_small pour_bimodal; do
        read -r secs contacts ns nsp < <(timed "$exe" "$bed" "$th" "${which}_t${th}_r$r")
        SAMPLES[$which,$bed,$th]+=" $ns"
        PSAMPLES[$which,$bed,$th]+=" $nsp"
        CONTACTS[$bed]=$contacts
        echo "  $which $bed threads=$th run $r: $secs s, $contacts contacts, $ns ns/contact-step, $nsp ns/particle-step"
      done
    done
  done
done

WHICH="new"; [ -n "${MPDEM_OLD:-}" ] && WHICH="new old"
echo
echo "Wide size ratios (Verlet, steps of 4e-6 s: $STEPS from the settled beds at rest, the pours' first $POUR s; medians of $RUNS interleaved runs)"
printf '| %-8s | %-7s | %-12s | %9s | %8s | %10s | %10s | %s |\n' code threads bed particles contacts ns/c-step ns/p-step "ratio (bound)"
printf '|%s|\n' "----------|---------|--------------|-----------|----------|------------|------------|--------------"
status=0
for which in $WHICH; do
  for th in $THREADS; do
    for bed in $BEDS pour_small pour_bimodal; do
      NSC[$bed]=$(echo "${SAMPLES[$which,$bed,$th]}" | median)
      NSP[$bed]=$(echo "${PSAMPLES[$which,$bed,$th]}" | median)
    done
    for bed in $BEDS pour_small pour_bimodal; do
      if [ -s "$WORK/$bed/particles.csv" ]; then PARTS[$bed]=$(($(wc -l < "$WORK/$bed/particles.csv") - 1)); fi
      [ "$bed" = pour_small ] && PARTS[$bed]=${PARTS[small]}
      [ "$bed" = pour_bimodal ] && PARTS[$bed]=${PARTS[bimodal]}
      ratio="" label=""
      case $bed in
        bimodal) ratio=$(awk -v a="${NSC[bimodal]}" -v b="${NSC[small]}" 'BEGIN {printf "%.2f", a / b}'); bound=1.3 ;;
        uniform) ratio=$(awk -v a="${NSC[uniform]}" -v b="${NSC[mono]}" 'BEGIN {printf "%.2f", a / b}'); bound=1.5 ;;
        pour_bimodal) label="$(awk -v a="${NSP[pour_bimodal]}" -v b="${NSP[pour_small]}" 'BEGIN {printf "%.2f", a / b}') per particle-step" ;;
      esac
      if [ -n "$ratio" ]; then
        label="$ratio (<= $bound)"
        [ "$which" = new ] && awk -v r="$ratio" -v b="$bound" 'BEGIN {exit !(r > b)}' && status=1
      fi
      printf '| %-8s | %7s | %12s | %9s | %8.0f | %10.1f | %10.1f | %s |\n' "$which" "$th" "$bed" "${PARTS[$bed]}" \
        "${CONTACTS[$bed]}" "${NSC[$bed]}" "${NSP[$bed]}" "$label"
    done
  done
done
exit $status
