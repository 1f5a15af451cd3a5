#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ (clang, ASan + UBSan) and runs one or all of them.
#   scripts/fuzz.sh [scene|particle_csv|barrier_csv|stl|checkpoint|all] [seconds per target, default 600]
# Targets run one after the other (-fork=0). New corpus entries go to $BUILD/corpus/<target>
# (the seeds in fuzz/corpus/<target> are read, never written); crashes, leaks, timeouts and
# out-of-memory inputs go to $BUILD/artifacts/<target>/; each run's log is $BUILD/logs/<target>.log.
# The checkpoint seeds are written by the engine: after a checkpoint format change, regenerate them
# with MPDEM_FUZZ_WRITE_SEEDS=fuzz/corpus/checkpoint $BUILD/fuzz_checkpoint (docs/fuzzing.md).
# Environment: MPDEM_FUZZ_BUILD (build folder, default build-fuzz), MPDEM_FUZZ_JOBS (default 2).
# See docs/fuzzing.md. Not part of the default build (scripts/build.sh stays g++-only).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
target=${1:-all}
seconds=${2:-600}
build=${MPDEM_FUZZ_BUILD:-$root/build-fuzz}
jobs=${MPDEM_FUZZ_JOBS:-2}

# clang with the libFuzzer/sanitizer runtimes (Debian 12: clang-14 + libclang-rt-14-dev, or the
# `clang` metapackage, which pulls both in).
have_toolchain() {
  command -v clang++ >/dev/null 2>&1 || return 1
  local probe
  probe=$(mktemp -d)
  printf 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }\n' >"$probe/t.cpp"
  clang++ -fsanitize=fuzzer,address,undefined "$probe/t.cpp" -o "$probe/t" >/dev/null 2>&1
  local ok=$?
  rm -rf "$probe"
  return $ok
}
if ! have_toolchain; then
  echo "fuzz.sh: installing clang and its runtime libraries" >&2
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq clang >/dev/null || $sudo apt-get install -y -qq clang-14 libclang-rt-14-dev >/dev/null
  if ! command -v clang++ >/dev/null 2>&1 && command -v clang++-14 >/dev/null 2>&1; then
    export CXX=clang++-14
  fi
  have_toolchain || [ -n "${CXX:-}" ] || { echo "fuzz.sh: no working clang++ -fsanitize=fuzzer" >&2; exit 1; }
fi

gen=()
command -v ninja >/dev/null 2>&1 && gen=(-G Ninja)
if [ ! -f "$build/CMakeCache.txt" ]; then
  CXX=${CXX:-clang++} cmake -S fuzz -B "$build" "${gen[@]}" >/dev/null
fi
cmake --build "$build" -j "$jobs"

case "$target" in
  all) targets=(scene particle_csv barrier_csv stl checkpoint) ;;
  scene | particle_csv | barrier_csv | stl | checkpoint) targets=("$target") ;;
  *) echo "usage: scripts/fuzz.sh [scene|particle_csv|barrier_csv|stl|checkpoint|all] [seconds]" >&2; exit 2 ;;
esac

status=0
for t in "${targets[@]}"; do
  exe="$build/fuzz_$t"
  if [ ! -x "$exe" ]; then echo "fuzz.sh: $exe was not built (see the cmake output)" >&2; status=1; continue; fi
  mkdir -p "$build/corpus/$t" "$build/artifacts/$t" "$build/logs"
  max_len=4096
  extra=()
  [ "$t" = stl ] && max_len=100000
  [ "$t" = checkpoint ] && max_len=16384  # the seeds (fixed scene, 4 particles) are ~3.3 KB
  [ "$t" = scene ] && extra=(-dict=fuzz/toml.dict)
  echo "fuzz.sh: fuzzing $t for $seconds s (log: $build/logs/$t.log)"
  if ! "$exe" -fork=0 -timeout=10 -rss_limit_mb=2048 -max_len=$max_len -max_total_time="$seconds" \
      -print_final_stats=1 -artifact_prefix="$build/artifacts/$t/" "${extra[@]}" \
      "$build/corpus/$t" "fuzz/corpus/$t" >"$build/logs/$t.log" 2>&1; then
    echo "fuzz.sh: $t FOUND A PROBLEM - see $build/logs/$t.log and $build/artifacts/$t/" >&2
    status=1
  fi
  grep -E '^stat::(number_of_executed_units|average_exec_per_sec)' "$build/logs/$t.log" || true
  echo "corpus entries: $(ls "$build/corpus/$t" | wc -l)"
done
exit $status
