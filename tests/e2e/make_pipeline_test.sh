#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# examples/make/Makefile end to end (label cli): copies the demo simulation and the Makefile
# into WORK_DIR and runs `make -j2` there (3 shards, low convergence, quarter resolution), then
# checks
#   1. the products exist: .jsim, schedules, parts, the merged render, detected counts and
#      their demosaiced PNGs, frame PNGs, the video (when ffmpeg is installed), false colour;
#   2. the merged render equals one glint-render process of the same simulation with the same
#      options: the same files, data byte-identical, headers identical but for
#      `glint command line`; the detected counts equal glint-render's in-render detection;
#   3. a second `make` has nothing to do (`make -q` exits 0, `make` runs no command);
#   4. after an edit, make redoes exactly what depends on the edited file, by the commands it
#      runs and the files it rewrites: the atmosphere (renders onwards, no schedule, no .jsim),
#      the .tasks file (schedules onwards, no .jsim), SHARDS=2 (shards onwards, not the full
#      schedule), SHARD_BY=rows (row bands: shards onwards), each time ending with a merged
#      render equal to the single run again.
# Usage: tests/e2e/make_pipeline_test.sh BIN_DIR WORK_DIR
set -euo pipefail

bin=$(cd "${1:?usage: make_pipeline_test.sh BIN_DIR WORK_DIR}" && pwd)
work=${2:?usage: make_pipeline_test.sh BIN_DIR WORK_DIR}
repo=$(cd "$(dirname "$0")/../.." && pwd)

convergence=2,4,1e-3
scale=0.25
shards=3

fail() { printf 'make_pipeline_test: FAIL: %s\n' "$*" >&2; exit 1; }
note() { printf 'make_pipeline_test: %s\n' "$*" >&2; }

envi_help=$("$bin/glint-envi" --help)
if ! grep -Eq '^[[:space:]]+merge([[:space:]]|$)' <<<"$envi_help"; then
    fail "$bin/glint-envi has no merge subcommand (the Makefile's step 4 needs it)"
fi
command -v make >/dev/null || fail "make is not installed"
# Run from `make test` (ctest under make), the environment carries the outer make's flags
# and level (jobserver, "make[1]:" messages): the makes here are top-level ones.
unset MAKEFLAGS MFLAGS GNUMAKEFLAGS MAKELEVEL MAKEFILES MAKEOVERRIDES

rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
cp -r "$repo/examples/demo/sim" "$work/sim"
cp "$repo/examples/make/Makefile" "$work/Makefile"
cd "$work"

make_vars=(GLINT_BIN="$bin" SIM=sim/demo.sim OUT=out SHARDS="$shards"
           CONVERGENCE="$convergence" SCALE="$scale" THREADS=1)
if ! command -v ffmpeg >/dev/null; then
    note "ffmpeg is not installed: the video is left out (VIDEO=)"
    make_vars+=(VIDEO=)
fi
step=0
# run_make NAME [VAR=value...]: make -j2 with the test's variables, its output in logs/NAME.txt
run_make() {
    local name=$1
    shift
    mkdir -p logs
    note "make -j2 $* ($name)"
    if ! make --no-print-directory -j2 "${make_vars[@]}" "$@" > "logs/$name.txt" 2>&1; then
        cat "logs/$name.txt" >&2
        fail "make ($name) failed"
    fi
}
# count NAME TOOL: how many commands of glint-TOOL make ran, by the recipe lines it echoed
# (those that start with 'BIN/glint-TOOL'; commands inside a recipe's loop are echoed once,
# indented, and not counted: their files are checked instead). TOOL may hold a subcommand.
count() { awk -v p="'$bin/glint-$2" 'index($0, p) == 1 { n++ } END { print n + 0 }' "logs/$1.txt"; }
expect_count() {  # NAME TOOL N
    local n
    n=$(count "$1" "$2")
    [[ "$n" == "$3" ]] || { cat "logs/$1.txt" >&2; fail "$1: make ran glint-$2 $n times, expected $3"; }
}
# newer / older than the marker made before the edit
mark() { step=$((step + 1)); touch "mark-$step"; sleep 1; }
redone() { for f in "$@"; do [[ "$f" -nt "mark-$step" ]] || fail "step $step: $f was not remade"; done; }
kept() { for f in "$@"; do [[ ! "$f" -nt "mark-$step" ]] || fail "step $step: $f was remade"; done; }

# compare_render REF DIR: the same files; data equal, headers equal but for the command line
compare_render() {
    local ref=$1 dir=$2 f
    diff <(cd "$ref" && find . -type f | sort) <(cd "$dir" && find . -type f | sort) >&2 ||
        fail "$dir does not hold the files of the single run $ref"
    while IFS= read -r f; do
        if [[ "$f" == *.hdr ]]; then
            diff <(grep -v '^glint command line' "$ref/$f") <(grep -v '^glint command line' "$dir/$f") >&2 ||
                fail "$dir/$f: header differs from the single run's beyond 'glint command line'"
        else
            cmp "$ref/$f" "$dir/$f" >&2 || fail "$dir/$f: data differs from the single run's"
        fi
    done < <(cd "$ref" && find . -type f | sort)
}

# ---- 1. the pipeline --------------------------------------------------------------------
run_make first
for f in out/demo.jsim out/schedule/full.json out/render.done out/detect.done out/frames.done \
         out/msi-false-colour.png; do
    [[ -s "$f" || ( "$f" == *.done && -f "$f" ) ]] || fail "$f missing after make"
done
for k in $(seq 1 "$shards"); do
    [[ -s "out/schedule/shard-$k.json" && -f "out/parts/$k.done" && -d "out/parts/$k" ]] ||
        fail "shard $k: schedule, stamp or folder missing"
done
[[ ! -e out/parts/1.tmp && ! -e out/detect.tmp && ! -e out/frames.tmp ]] || fail "a .tmp folder is left"
frames=$(find out/frames -name 'rgb-t0000-c*.png' | wc -l)
[[ "$frames" == 25 ]] || fail "out/frames holds $frames frame PNGs, expected 25"
for c in 0000 0001; do
    [[ -s "out/detect/bayer-t0000-c$c.img" && -s "out/detect/bayer-t0000-c$c.png" ]] ||
        fail "out/detect/bayer-t0000-c$c.img or .png missing"
done
if command -v ffmpeg >/dev/null; then
    [[ -s out/demo.mp4 ]] || fail "out/demo.mp4 missing"
fi
expect_count first platform2jsim 1
expect_count first schedule $((shards + 1))
expect_count first render "$shards"
expect_count first "envi' merge" 1

# ---- 2. the same bytes as one glint-render, and as in-render detection ------------------
note "reference: one glint-render of the whole simulation"
"$bin/glint-render" out/demo.jsim --output-folder ref --no-processing --radiance-only \
    --convergence "$convergence" --scale-resolution "$scale" --seed 1 -q > ref.files
compare_render ref out/render
"$bin/glint-schedule" out/demo.jsim --focal-plane Bayer -o bayer.json
"$bin/glint-render" out/demo.jsim --schedule bayer.json --output-folder ref-counts \
    --no-processing --convergence "$convergence" --scale-resolution "$scale" --seed 1 -q > /dev/null
for c in 0000 0001; do
    cmp "ref-counts/bayer-t0000-c$c.img" "out/detect/bayer-t0000-c$c.img" >&2 ||
        fail "out/detect/bayer-t0000-c$c.img differs from glint-render's in-render detection"
done

# ---- 3. nothing to do the second time ---------------------------------------------------
make -q "${make_vars[@]}" || fail "make -q: the targets are not up to date after make"
run_make second
[[ "$(cat logs/second.txt)" == "make: Nothing to be done for 'all'." ]] ||
    { cat logs/second.txt >&2; fail "a second make ran commands"; }

# ---- 4. edits redo what depends on them -------------------------------------------------
products=(out/render.done out/detect.done out/frames.done out/msi-false-colour.png)
command -v ffmpeg >/dev/null && products+=(out/demo.mp4)
shard_jsons=() part_stamps=()
for k in $(seq 1 "$shards"); do
    shard_jsons+=("out/schedule/shard-$k.json")
    part_stamps+=("out/parts/$k.done")
done

# The atmosphere is read by glint-render only: renders onwards, no schedule, no .jsim.
mark
touch sim/demo_atmosphere.yaml
if make -q "${make_vars[@]}"; then fail "make -q: up to date after the atmosphere changed"; fi
run_make atmosphere
expect_count atmosphere platform2jsim 0
expect_count atmosphere schedule 0
expect_count atmosphere render "$shards"
expect_count atmosphere "envi' merge" 1
kept out/demo.jsim out/schedule/full.json "${shard_jsons[@]}"
redone "${part_stamps[@]}" "${products[@]}"
compare_render ref out/render

# The tasks file changes the schedule: schedules onwards, but not the .jsim (it names the
# file, it does not hold it).
mark
touch sim/demo.tasks
run_make tasks
expect_count tasks platform2jsim 0
expect_count tasks schedule $((shards + 1))
expect_count tasks render "$shards"
kept out/demo.jsim
redone out/schedule/full.json "${shard_jsons[@]}" "${part_stamps[@]}" "${products[@]}"
compare_render ref out/render

# Another shard count: new shard schedules and renders, a new merge; the full schedule
# (what the merge is checked against) and the .jsim stay. The merged bytes do not change.
mark
run_make shards2 SHARDS=2
expect_count shards2 platform2jsim 0
expect_count shards2 schedule 2
expect_count shards2 render 2
kept out/demo.jsim out/schedule/full.json out/parts/3.done
redone out/schedule/shard-1.json out/schedule/shard-2.json out/parts/1.done out/parts/2.done \
    "${products[@]}"
grep -q "^'$bin/glint-envi' merge '[^ ]*out/parts/1' '[^ ]*out/parts/2' -o" logs/shards2.txt ||
    fail "make SHARDS=2 did not merge parts 1 and 2 alone"
compare_render ref out/render
make -q "${make_vars[@]}" SHARDS=2 || fail "make -q SHARDS=2: not up to date after make SHARDS=2"

# Row bands instead of whole captures: new shard schedules, renders and merge, the same bytes.
mark
run_make rows SHARDS=2 SHARD_BY=rows
expect_count rows platform2jsim 0
expect_count rows schedule 2
expect_count rows render 2
kept out/demo.jsim out/schedule/full.json
redone out/schedule/shard-1.json out/schedule/shard-2.json "${products[@]}"
grep -q '"by": *"rows"' out/schedule/shard-1.json || fail "SHARD_BY=rows: shard-1.json is not split by rows"
compare_render ref out/render

note "PASS"
