#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The install test (label install, docs/install.md): installs the already-built tree with
# `cmake --install`, then uses only the install: the installed glint-render must find its data
# in <prefix>/share/glint (not the source tree), the installed demo must run, the man pages
# must be there, and examples/plugin must build against the installed CMake package and print
# plausible radiance. Exit 77 (skipped) only when a required program is missing.
# Usage: install_test.sh --build BUILD_DIR --work WORK_DIR [--man ON|OFF]
set -euo pipefail

build='' work='' man=ON
while [ $# -gt 0 ]; do
    case "$1" in
        --build) build=$2; shift 2 ;;
        --work) work=$2; shift 2 ;;
        --man) man=$2; shift 2 ;;
        *) echo "install_test: unknown argument $1" >&2; exit 2 ;;
    esac
done
[ -n "$build" ] && [ -n "$work" ] || { echo "usage: $0 --build DIR --work DIR [--man ON|OFF]" >&2; exit 2; }

fail() { echo "install_test: FAIL: $*" >&2; exit 1; }
step() { printf '\n== install_test: %s\n' "$*" >&2; }

for program in cmake c++ ffmpeg; do
    command -v "$program" >/dev/null || { echo "install_test: skipped: $program is not installed" >&2; exit 77; }
done

build=$(cd "$build" && pwd)
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
prefix="$work/prefix"
# Nothing below may depend on the source tree: run from the work folder, no GLINT_DATA_DIR.
cd "$work"
unset GLINT_DATA_DIR
tools=(glint-render glint-schedule glint-detect glint-envi glint-demosaic glint-platform2jsim)

step "1. cmake --install $build --prefix $prefix"
cmake --install "$build" --prefix "$prefix" > "$work/install.log" 2>&1 ||
    { cat "$work/install.log" >&2; fail "cmake --install failed"; }
for f in "${tools[@]/#/bin/}" share/glint/solar/astm_g173.csv \
         share/glint/examples/demo/run.sh share/glint/examples/plugin/CMakeLists.txt \
         share/glint/examples/plugin/main.cpp share/doc/glint/README.md \
         share/doc/glint/docs/install.md include/glint/core/install_paths.h \
         include/glint/radiometry/problem.h; do
    [ -e "$prefix/$f" ] || fail "not installed: $prefix/$f"
done
config=$(find "$prefix" -path '*/cmake/glint/glintConfig.cmake' | head -1)
[ -n "$config" ] || fail "glintConfig.cmake not installed under $prefix"
[ -e "$(dirname "$config")/glintConfigVersion.cmake" ] || fail "glintConfigVersion.cmake not installed"
find "$prefix" -path '*/glint/glint-image-oiio.so' | grep -q . ||
    fail "the image module lib/glint/glint-image-oiio.so not installed under $prefix"
for c in core model motion scene radiometry atmosphere inputs; do
    find "$prefix" -name "libglint_$c.a" | grep -q . || fail "libglint_$c.a not installed"
done
for t in "${tools[@]}"; do
    [ -x "$prefix/bin/$t" ] || fail "$prefix/bin/$t is not executable"
    "$prefix/bin/$t" --version > /dev/null || fail "$t --version failed"
done

step "2. the installed glint-render uses $prefix/share/glint"
demo="$prefix/share/glint/examples/demo"
"$prefix/bin/glint-render" -v --dry-run "$demo/sim/demo.sim" --output-folder "$work/dry" \
    > "$work/dry-run.out" 2> "$work/dry-run.log" ||
    { cat "$work/dry-run.log" >&2; fail "glint-render --dry-run from the install failed"; }
grep -qxF "Data folder: $prefix/share/glint" <(sed 's/^.*Data folder: /Data folder: /' "$work/dry-run.log") ||
    { grep -i 'data folder' "$work/dry-run.log" >&2 || true; fail "glint-render did not use $prefix/share/glint"; }
# Relocatable: a copy of the install elsewhere finds its own share/glint (/proc/self/exe).
# Only glint-render is copied, so the demo's image_tool task (glint-envi stands in) has no
# program there: --no-processing, as the dry run would otherwise fail as the run would.
mkdir -p "$work/moved/bin" "$work/moved/share"
cp "$prefix/bin/glint-render" "$work/moved/bin/"
cp -r "$prefix/share/glint" "$work/moved/share/"
"$work/moved/bin/glint-render" -v --dry-run --no-processing "$demo/sim/demo.sim" --output-folder "$work/dry" \
    > /dev/null 2> "$work/dry-run-moved.log" ||
    { cat "$work/dry-run-moved.log" >&2; fail "a moved copy of the install failed"; }
grep -q "Data folder: $work/moved/share/glint" "$work/dry-run-moved.log" ||
    fail "a moved copy of glint-render did not use its own share/glint"
GLINT_DATA_DIR="$work/elsewhere" "$prefix/bin/glint-render" -v --dry-run "$demo/sim/demo.sim" \
    --output-folder "$work/dry" > /dev/null 2> "$work/dry-run-env.log" || true
grep -q "Data folder: $work/elsewhere" "$work/dry-run-env.log" ||
    fail "\$GLINT_DATA_DIR does not take precedence over the installed data folder"

step "3. the installed demo: $demo/run.sh $prefix/bin $work/demo-out"
"$demo/run.sh" "$prefix/bin" "$work/demo-out" > "$work/demo.log" 2>&1 ||
    { tail -40 "$work/demo.log" >&2; fail "the installed demo failed (log: $work/demo.log)"; }
for f in demo.jsim demo.platform.json demo.schedule.json render/demo.mp4 render/msi.img render/msi.img.hdr \
         render/rgb-t0000-c0000.img render/rgb-t0000-c0000.png render/msi-false-colour.png \
         render/bayer-t0000-c0000.png; do
    [ -s "$work/demo-out/$f" ] || fail "the installed demo did not write $f"
done
grep -q "Data folder: $prefix/share/glint" "$work/demo-out/render/render.log" ||
    fail "the demo's glint-render did not read $prefix/share/glint"

step "4. man pages"
if [ "$man" = ON ]; then
    for t in "${tools[@]}"; do
        page="$prefix/share/man/man1/$t.1"
        [ -s "$page" ] || fail "man page not installed: $page"
        if command -v man >/dev/null; then
            MANWIDTH=80 man -l -P cat "$page" 2>/dev/null | grep -q -- '--help' ||
                fail "man -l $page does not render the options"
        fi
    done
else
    echo "help2man was missing at configure time: man pages not checked" >&2
fi

step "5. examples/plugin against the installed package"
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
cmake -S "$prefix/share/glint/examples/plugin" -B "$work/plugin-build" "${generator[@]}" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" > "$work/plugin-configure.log" 2>&1 ||
    { cat "$work/plugin-configure.log" >&2; fail "configuring examples/plugin with find_package(glint) failed"; }
cmake --build "$work/plugin-build" > "$work/plugin-build.log" 2>&1 ||
    { tail -60 "$work/plugin-build.log" >&2; fail "building examples/plugin failed"; }
# The default sweep: 29 positions 1 m apart across the demo's five calibration panels.
"$work/plugin-build/glint-radiometer" "$demo/sim/demo.sim" > "$work/radiometer.csv" \
    2> "$work/radiometer.log" ||
    { cat "$work/radiometer.log" >&2; fail "glint-radiometer failed"; }
cat "$work/radiometer.csv" >&2
awk -F, 'NR == 1 { next }
         { rows++; for (i = 5; i <= 8; i++) if (!($i + 0 > 0) || $i + 0 > 1 || $i ~ /nan|inf/) bad++ }
         END { exit !(rows == 29 && bad == 0) }' "$work/radiometer.csv" ||
    fail "glint-radiometer did not print 29 rows of positive, finite radiance (< 1 W/(cm2 sr))"
# Panel centres x = -10, -5, 0, 5, 10 m: reflectance 3, 12, 25, 50, 80 %, radiance increasing.
awk -F, 'NR > 1 && ($2 + 0 == -10 || $2 + 0 == -5 || $2 + 0 == 0 || $2 + 0 == 5 || $2 + 0 == 10) {
             n++; if (n > 1 && !($5 + 0 > last)) bad++; last = $5 + 0 }
         END { exit !(n == 5 && bad == 0) }' "$work/radiometer.csv" ||
    fail "glint-radiometer: radiance over the calibration panels is not increasing with reflectance"

echo "install_test: OK ($prefix)" >&2
