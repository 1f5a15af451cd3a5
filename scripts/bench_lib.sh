# Shared by scripts/bench_vs_liggghts.sh, bench_silo_vs_liggghts.sh, bench_size_ratio.sh and scaling.sh
# (sourced): the tools they need, the beds, LIGGGHTS's timed run, scene templates, and the parsing
# of results. Expects ROOT (the repository).

# Installs LIGGGHTS, Open MPI and GNU time when missing (NO_INSTALL=1: fail instead).
bench_tools() {
  local need=()
  command -v liggghts >/dev/null 2>&1 || need+=(liggghts)
  command -v mpirun >/dev/null 2>&1 || need+=(openmpi-bin)
  [ -x /usr/bin/time ] || need+=(time)
  [ ${#need[@]} -eq 0 ] && return 0
  if [ "${NO_INSTALL:-0}" = 1 ]; then echo "missing: ${need[*]}" >&2; exit 2; fi
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q >/dev/null
  $sudo apt-get install -y -q --no-install-recommends "${need[@]}" >/dev/null
}

# The environment every mpdem run of the scripts gets: threads bound to cores, and mpdem's own
# default spin (src/cli/openmp_environment.hpp) given explicitly, since mpdem leaves the OpenMP
# environment alone under a binding.
MPDEM_OMP_ENV=(GOMP_SPINCOUNT=1000 OMP_PROC_BIND=close)

# fill_template SRC DST KEY VALUE [KEY VALUE ...]: DST is SRC with every @KEY@ replaced by VALUE
# (values may span lines and hold any character).
fill_template() {
  /usr/bin/python3 - "$@" <<'PYEOF'
import sys
src, dst, pairs = sys.argv[1], sys.argv[2], sys.argv[3:]
t = open(src).read()
for k, v in zip(pairs[::2], pairs[1::2]):
    t = t.replace("@" + k + "@", v)
open(dst, "w").write(t)
PYEOF
}
# run_seconds FILE...: the time loop's wall time (s) from `mpdem run`'s "done: ... steps in X s" line
run_seconds() { sed -n 's/^done: .* steps in \([0-9.e+-]*\) s .*/\1/p' "$@" | head -1; }

# median of the numbers on stdin (blank-separated)
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR]=$1} END {if (NR%2) print a[(NR+1)/2]; else print (a[NR/2]+a[NR/2+1])/2}'; }
# value of key=... in a BENCH_RESULT / BENCH_STATE line on stdin
field() { tr ' ' '\n' | sed -n "s/^$1=//p" | head -1; }
# peak RSS (KiB) from a GNU time -v report
peak_kib() { sed -n 's/.*Maximum resident set size (kbytes): *//p' "$1" | tail -1; }

# bed_file NAME WORK SHARED: the path of bed NAME (20k, 100k: the shared beds; 50k: the 100k bed's
# spheres with x + r <= 90 mm, in a box half as long; 2x50k: the 50k bed and its mirror image in
# the plane x = 90 mm, ids + 100000, in the 100k bed's box: two identical halves for weak
# scaling), decompressed or cut into WORK once.
bed_file() {
  local name=$1 work=$2 shared=$3 data="$2/bed$1.data"
  if [ ! -s "$data" ]; then
    case "$name" in
      20k | 100k) gzip -dc "$shared/bed$name.data.gz" > "$data" ;;
      50k)
        gzip -dc "$shared/bed100k.data.gz" > "$data.full"
        # Pass 1 counts the kept spheres (columns: id type diameter density x y z), pass 2 writes.
        awk 'NR == FNR { if (atoms && NF == 7 && $5 + $3 / 2 <= 0.09) n++; if ($1 == "Atoms") atoms = 1; next }
             $2 == "atoms" && NF == 2 { print n " atoms"; next }
             $3 == "xlo" { print "0 0.09 xlo xhi"; next }
             $1 == "Atoms" { atoms2 = 1; print; next }
             atoms2 && NF == 7 { if ($5 + $3 / 2 <= 0.09) print; next }
             { print }' "$data.full" "$data.full" > "$data.tmp"
        rm -f "$data.full"
        mv "$data.tmp" "$data" ;;
      2x50k)
        local half
        half=$(bed_file 50k "$work" "$shared")
        awk 'NR == FNR { if (atoms && NF == 7) n++; if ($1 == "Atoms") atoms = 1; next }
             $2 == "atoms" && NF == 2 { print 2 * n " atoms"; next }
             $3 == "xlo" { print "0 0.18 xlo xhi"; next }
             $1 == "Atoms" { atoms2 = 1; print; next }
             atoms2 && NF == 7 { print; $1 += 100000; $5 = sprintf("%.10g", 0.18 - $5); mirror[++m] = $0; next }
             { print }
             END { for (i = 1; i <= m; i++) print mirror[i] }' "$half" "$half" > "$data.tmp"
        mv "$data.tmp" "$data" ;;
      *) echo "unknown bed '$name'" >&2; exit 2 ;;
    esac
  fi
  echo "$data"
}

# liggghts_job LOG RANKS INPUT [-var NAME VALUE ...]: runs LIGGGHTS on INPUT in LOG's folder (one
# thread per rank); its screen output goes to LOG.out, its log to LOG.log, and the peak RSS of
# every rank (GNU time around each rank, KiB) to LOG.rank*.
liggghts_job() {
  local log=$1 ranks=$2 input=$3
  shift 3
  rm -f "$log".rank*
  local cmd=(liggghts -in "$input" -log "$log.log" "$@")
  local wrap=(sh -c '/usr/bin/time -f "%M" -o "$0.rank${OMPI_COMM_WORLD_RANK:-0}" "$@"' "$log")
  if [ "$ranks" -gt 1 ]; then
    (cd "$(dirname "$log")" && OMP_NUM_THREADS=1 mpirun -np "$ranks" --allow-run-as-root --oversubscribe "${wrap[@]}" "${cmd[@]}" > "$log.out" 2>&1)
  else
    (cd "$(dirname "$log")" && OMP_NUM_THREADS=1 "${wrap[@]}" "${cmd[@]}" > "$log.out" 2>&1)
  fi
}

# liggghts_ns DATA STEPS RELAX RANKS LOG: runs LIGGGHTS's timed bench (liggghts_job) and prints its
# ns per particle-step; its state line (BENCH_STATE) stays in LOG.out.
liggghts_ns() {
  local data=$1 steps=$2 relax=$3 ranks=$4 log=$5 n secs
  liggghts_job "$log" "$ranks" "$SHARED/liggghts_bench.in" -var data "$data" -var nrelax "$relax" \
    -var nsteps "$steps" -var dt 4e-6
  n=$(awk '$2 == "atoms" {print $1; exit}' "$data")
  secs=$(awk '/TIMED_RUN_BEGIN/ {t=1} t && /^Loop time of/ {print $4; exit}' "$log.out")
  awk -v s="$secs" -v n="$n" -v k="$steps" 'BEGIN {printf "%.3f\n", 1e9 * s / (n * k)}'
}
