#!/usr/bin/env bash
# Lint: (1) the layers of src/ (scripts/check_layers.py: no #include from a folder to one of a
# higher layer or its own layer, no folder-level include cycle; docs/architecture.md "Layers"),
# (2) clang-format check of every tracked C++ file under src/ tests/ bench/ fuzz/ (style:
# .clang-format), (3) clang-tidy over src/ (checks: .clang-tidy), any warning is an error.
# Exit status 0 when every part is clean, 1 when one has findings (all always run).
#
# Usage: scripts/lint.sh [--fix] [layers|format|tidy]
#   --fix   rewrite the files in place with clang-format instead of checking them (clang-tidy
#           still only reports; it changes nothing)
#   layers, format, tidy  run only those parts (default: all three)
# Environment: CLANG_FORMAT, CLANG_TIDY (default clang-format, clang-tidy; Debian 12: version 14),
#   LINT_JOBS (parallel clang-tidy processes, default nproc).
# clang-tidy reads build-lint/compile_commands.json, from a configure-only build (nothing is
# compiled; scripts/install-deps.sh provides what the configure step needs).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
cd "$ROOT"
CLANG_FORMAT="${CLANG_FORMAT:-clang-format}"
CLANG_TIDY="${CLANG_TIDY:-clang-tidy}"
JOBS="${LINT_JOBS:-$(nproc)}"
LINT_BUILD="$ROOT/build-lint"

fix=0
parts=()
for arg in "$@"; do
  case "$arg" in
    --fix) fix=1 ;;
    layers | format | tidy) parts+=("$arg") ;;
    -h | --help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "lint.sh: unknown argument '$arg' (usage: scripts/lint.sh [--fix] [layers|format|tidy])" >&2; exit 2 ;;
  esac
done
[ ${#parts[@]} -gt 0 ] || parts=(layers format tidy)
bash "$ROOT/scripts/install-deps.sh" >/dev/null

need() {
  command -v "$1" >/dev/null 2>&1 || { echo "lint.sh: $1 not found (scripts/install-deps.sh installs it)" >&2; exit 2; }
}

# The C++ files of the repository: tracked ones (git), or all of them outside a git checkout.
cpp_files() {
  if git -C "$ROOT" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git -C "$ROOT" ls-files -- "$@"
  else
    local dirs=()
    for p in "$@"; do dirs+=("${p%%/*}"); done
    find $(printf '%s\n' "${dirs[@]}" | sort -u) -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' -o -name '*.cc' \) | sort
  fi
}

# Part 1: formatting of src/ tests/ bench/ fuzz/.
format_check() {
  need "$CLANG_FORMAT"
  # The style is tuned for, and checked with, clang-format 14; other versions break lines a little
  # differently.
  "$CLANG_FORMAT" --version | grep -q ' 14\.' ||
    echo "lint.sh: warning: $("$CLANG_FORMAT" --version) is not clang-format 14 (Debian 12), results may differ" >&2
  "$CLANG_FORMAT" --dump-config > /dev/null || { echo "clang-format: .clang-format is not valid" >&2; return 1; }
  local files=() bad=() f
  mapfile -t files < <(cpp_files 'src/*.cpp' 'src/*.hpp' 'tests/*.cpp' 'tests/*.hpp' 'bench/*.cpp' 'bench/*.hpp' \
    'fuzz/*.cpp' 'fuzz/*.hpp' 'src/*.h' 'tests/*.h' 'bench/*.h' 'fuzz/*.h' | while read -r f; do [ -f "$f" ] && echo "$f"; done)
  if [ "$fix" = 1 ]; then
    printf '%s\0' "${files[@]}" | xargs -0 -r -n 20 -P "$JOBS" "$CLANG_FORMAT" -i
    echo "clang-format: formatted ${#files[@]} files in place"
    return 0
  fi
  for f in "${files[@]}"; do
    "$CLANG_FORMAT" --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
  done
  if [ ${#bad[@]} -gt 0 ]; then
    printf '  %s\n' "${bad[@]}"
    echo "clang-format: ${#bad[@]} of ${#files[@]} files are not formatted (see one: $CLANG_FORMAT --dry-run FILE;" \
      "fix all: scripts/lint.sh --fix)"
    return 1
  fi
  echo "clang-format: ${#files[@]} files clean"
}

# Part 2: clang-tidy over the sources under src/ (headers under src/ through HeaderFilterRegex).
# Debian's run-clang-tidy-14 has no --warnings-as-errors, so clang-tidy runs through xargs, one
# file a process, each file's report printed in one piece.
tidy_check() {
  need "$CLANG_TIDY"
  need cmake
  # Configure only, every time (cheap): the compile database follows added and removed sources.
  local gen=()
  command -v ninja >/dev/null 2>&1 && gen=(-G Ninja)
  [ -f "$LINT_BUILD/CMakeCache.txt" ] && gen=()
  mkdir -p "$LINT_BUILD"
  if ! cmake -S "$ROOT" -B "$LINT_BUILD" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DMPDEM_BUILD_BENCH=OFF -DMPDEM_MPI=ON \
    > "$LINT_BUILD/lint-configure.log" 2>&1; then
    cat "$LINT_BUILD/lint-configure.log" >&2
    echo "clang-tidy: configuring $LINT_BUILD failed" >&2
    return 1
  fi
  local files=()
  mapfile -t files < <(python3 -c '
import json, sys
root = sys.argv[1] + "/src/"
print("\n".join(sorted({e["file"] for e in json.load(open(sys.argv[2])) if e["file"].startswith(root)})))
' "$ROOT" "$LINT_BUILD/compile_commands.json")
  [ ${#files[@]} -gt 0 ] || { echo "clang-tidy: no sources under src/ in $LINT_BUILD/compile_commands.json" >&2; return 1; }
  local log
  log="$(mktemp)"
  local status=0
  printf '%s\0' "${files[@]}" | xargs -0 -n 1 -P "$JOBS" sh -c '
    out=$("$0" -p "$1" --quiet --warnings-as-errors="*" "$2" 2>&1); rc=$?
    printf "%s\n" "$out" | grep -v -E "^[0-9]+ (warning|error)s? (generated|treated as errors?)\.?$|^Suppressed [0-9]+ warnings|^Use -header-filter|^$" || true
    exit $rc' "$CLANG_TIDY" "$LINT_BUILD" > "$log" || status=1
  cat "$log"
  # A header's finding is reported once per source including it: count each place once.
  local findings=()
  mapfile -t findings < <(sed -n -E 's#^'"$ROOT"'/(.*:[0-9]+):[0-9]+: (warning|error): .* \[([a-z0-9.-]+)(,-warnings-as-errors)?\]$#\1: \3#p' \
    "$log" | sort -u -V)
  rm -f "$log"
  if [ "$status" != 0 ]; then
    echo "clang-tidy findings (file:line: check):"
    printf '  %s\n' "${findings[@]}"
    echo "clang-tidy: ${#findings[@]} findings in ${#files[@]} sources under src/ and their headers"
    return 1
  fi
  echo "clang-tidy: ${#files[@]} sources under src/ clean"
}

status=0
for part in "${parts[@]}"; do
  case "$part" in
    layers) need python3; python3 "$ROOT/scripts/check_layers.py" "$ROOT" || status=1 ;;
    format) format_check || status=1 ;;
    tidy) tidy_check || status=1 ;;
  esac
done
exit "$status"
