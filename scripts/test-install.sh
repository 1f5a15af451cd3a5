#!/usr/bin/env bash
# Install test: installs the built tree into a temporary prefix, runs the installed `mpdem`
# (--version, check of the installed demo scene, validate --list and one validation case from the
# installed examples), checks the headers and the CMake package are there, then configures, builds and
# runs tests/install, an outside CMake project using find_package(mpdem) and mpdem::engine.
#
# Usage: scripts/test-install.sh
# Environment:
#   BUILD   the build folder to install (default: build/, brought up to date by scripts/build.sh,
#           which also configures and builds it from scratch when there is none; another folder:
#           configured as Release when new, then its target mpdem is built)
#   KEEP=1  keep the temporary prefix and the test project's build folder (their path is printed)
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"
cd "$ROOT"
BUILD="${BUILD:-build}"
BUILD="$(cd "$ROOT" && mkdir -p "$BUILD" && cd "$BUILD" && pwd)"
bash scripts/install-deps.sh >/dev/null

# Bring the build up to date first (a no-op when it is): the headers are installed from src/, the
# library from the build, and a stale build would not match them. build/ goes through
# scripts/build.sh (it configures build/ when it has not been configured yet).
if [ "$BUILD" = "$ROOT/build" ]; then
  bash scripts/build.sh
else
  gen=()
  command -v ninja >/dev/null 2>&1 && gen=(-G Ninja)
  [ -f "$BUILD/CMakeCache.txt" ] || cmake -S "$ROOT" -B "$BUILD" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release
  cmake --build "$BUILD" -j "$(nproc)" --target mpdem
fi
[ -x "$BUILD/mpdem" ] || { echo "test-install: no $BUILD/mpdem after the build" >&2; exit 1; }

work="$(mktemp -d "${TMPDIR:-/tmp}/mpdem-install-test.XXXXXX")"
prefix="$work/prefix"
if [ "${KEEP:-0}" = 1 ]; then
  echo "install test folder (kept): $work"
else
  trap 'rm -rf "$work"' EXIT
fi
fail() { echo "test-install: FAILED: $*" >&2; exit 1; }

cmake --install "$BUILD" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log" >&2; fail "cmake --install"; }
echo "installed $BUILD into $prefix ($(wc -l < "$work/install.log") files)"

# Everything from the prefix, run from a folder outside the sources.
cd "$work"
mpdem="$prefix/bin/mpdem"
[ -x "$mpdem" ] || fail "no $mpdem"
version="$(sed -n 's/^project(mpdem VERSION \([0-9][0-9.]*\).*/\1/p' "$ROOT/CMakeLists.txt")"
[ -n "$version" ] || fail "no project(mpdem VERSION ...) in CMakeLists.txt"
got="$("$mpdem" --version)" || fail "$mpdem --version exits $?"
[ "$got" = "mpdem $version" ] || fail "$mpdem --version printed '$got', expected 'mpdem $version'"
echo "ok: mpdem --version: $got"

scene="$prefix/share/mpdem/examples/demo/scene.toml"
[ -f "$scene" ] || fail "no installed demo scene $scene"
"$mpdem" check "$scene" > "$work/check.log" || { cat "$work/check.log" >&2; fail "mpdem check $scene"; }
particles="$(sed -n 's/^particles: \([0-9]*\) .*/\1/p' "$work/check.log")"
echo "ok: mpdem check of the installed demo scene ($particles particles)"
"$mpdem" validate --list > /dev/null || fail "mpdem validate --list"
echo "ok: mpdem validate --list"

# The validation cases from the prefix: found with --cases-dir (the default search looks from the
# working directory and from bin/ upwards for examples/validation, i.e. it finds them when run in
# share/mpdem/); the plots need scripts/plot_validation.py installed beside examples/.
"$mpdem" validate hole --cases-dir "$prefix/share/mpdem/examples/validation" --output "$work/validation" \
  > "$work/validate.log" 2>&1 || { cat "$work/validate.log" >&2; fail "mpdem validate hole --cases-dir <prefix>/share/mpdem/examples/validation"; }
echo "ok: mpdem validate hole with the installed cases"

for f in include/mpdem/model/scene.hpp include/mpdem/core/vec3.hpp share/doc/mpdem/README.md \
  share/doc/mpdem/LICENSE share/doc/mpdem/CHANGELOG.md; do
  [ -e "$prefix/$f" ] || fail "no $f in the prefix"
done
for f in mpdemConfig.cmake mpdemConfigVersion.cmake mpdemTargets.cmake; do
  compgen -G "$prefix/lib*/cmake/mpdem/$f" > /dev/null || fail "no lib/cmake/mpdem/$f in the prefix"
done

# The Python package from the prefix (docs/python.md, "Install"), when the build has it.
if grep -q '^MPDEM_PYTHON:BOOL=ON' "$BUILD/CMakeCache.txt"; then
  python="$(sed -n 's/^MPDEM_PYTHON_EXECUTABLE:INTERNAL=//p' "$BUILD/CMakeCache.txt")"
  site="$prefix/lib/python3/dist-packages"
  [ -f "$site/mpdem/__init__.py" ] || fail "no mpdem Python package in $site"
  got="$(PYTHONPATH="$site" "$python" -c '
import sys, mpdem
sim = mpdem.Simulation(mpdem.Scene.from_toml(sys.argv[1]), threads=1, write_output=False)
sim.step(10)
print(mpdem.__version__, len(sim.particles), sim.steps, mpdem.__file__)
' "$scene")" || fail "import mpdem from $site"
  case "$got" in
    "$version $particles 10 $site/mpdem/__init__.py") ;;
    *) fail "the installed Python package printed '$got', expected '$version $particles 10 $site/mpdem/__init__.py'" ;;
  esac
  echo "ok: import mpdem from the prefix, 10 steps of the installed demo scene"
fi

# The outside project: find_package(mpdem), mpdem::engine, load_scene.
gen=()
command -v ninja >/dev/null 2>&1 && gen=(-G Ninja)
cmake -S "$ROOT/tests/install" -B "$work/consumer" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" > "$work/consumer.log" 2>&1 || { cat "$work/consumer.log" >&2; fail "configure tests/install"; }
cmake --build "$work/consumer" >> "$work/consumer.log" 2>&1 || { cat "$work/consumer.log" >&2; fail "build tests/install"; }
out="$("$work/consumer/install_test" "$scene")" || fail "tests/install program exits $?"
echo "$out"
case "$out" in
  "mpdem $version: $particles particles, "*) ;;
  *) fail "tests/install printed '$out', expected 'mpdem $version: $particles particles, ...'" ;;
esac
echo "ok: tests/install built against the prefix (find_package(mpdem), mpdem::engine) and ran"
echo "test-install: all checks passed"
