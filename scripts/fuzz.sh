#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fuzzes glint's input readers: configures and builds the `fuzz` preset (clang, libFuzzer,
# ASan + UBSan) and runs each target (all by default) for SECONDS on a writable copy of its
# corpus (build/fuzz/corpus-work/<target>, seeded from fuzz/corpus/<target>; the crash inputs
# of fuzz/crashes/<target> run first). New crash, timeout, out-of-memory and leak inputs are
# copied to fuzz/crashes/<target>/. Prints per target the runs executed, the coverage and the
# crashes; exits 1 when any target crashed, 2 on a usage error. docs/testing.md, "Fuzzing".
set -euo pipefail

usage() {
    echo "usage: scripts/fuzz.sh SECONDS [TARGET...]" >&2
    echo "targets: $(all_targets | tr '\n' ' ')" >&2
    exit 2
}

cd "$(dirname "$0")/.."
build=build/fuzz

all_targets() {
    for source in fuzz/*_fuzz.cpp; do
        basename "$source" _fuzz.cpp
    done
}

[ $# -ge 1 ] || usage
seconds=$1
shift
[[ $seconds =~ ^[1-9][0-9]*$ ]] || usage
if [ $# -gt 0 ]; then
    targets=("$@")
    for target in "${targets[@]}"; do
        [ -f "fuzz/${target}_fuzz.cpp" ] || { echo "fuzz.sh: unknown target $target" >&2; usage; }
    done
else
    mapfile -t targets < <(all_targets)
fi

mkdir -p build
cmake --preset fuzz >"$build.configure.log" 2>&1 ||
    { cat "$build.configure.log" >&2; echo "fuzz.sh: configure failed" >&2; exit 1; }
cmake --build "$build" --target "${targets[@]/%/_fuzz}" >&2

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
mkdir -p "$build/logs"
printf '%-18s %12s %8s %8s %8s %8s\n' target runs cov ft corpus crashes
found=0
for target in "${targets[@]}"; do
    work="$build/corpus-work/$target"
    artifacts="$build/artifacts/$target"
    log="$build/logs/$target.log"
    mkdir -p "$work"
    rm -rf "$artifacts"
    mkdir -p "$artifacts"
    cp -n "fuzz/corpus/$target"/* "$work"/ 2>/dev/null || true
    seeds=("$work")
    [ -d "fuzz/crashes/$target" ] && seeds+=("fuzz/crashes/$target")
    status=0
    "$build/fuzz/${target}_fuzz" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
        -print_final_stats=1 -artifact_prefix="$artifacts/" "${seeds[@]}" >"$log" 2>&1 ||
        status=$?
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    [ -n "$runs" ] || runs=$(grep -o '^#[0-9]*' "$log" | tail -1 | tr -d '#')
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
    ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
    crashes=0
    for input in "$artifacts"/*; do
        [ -f "$input" ] || continue
        mkdir -p "fuzz/crashes/$target"
        cp "$input" "fuzz/crashes/$target/"
        crashes=$((crashes + 1))
    done
    if [ "$status" -ne 0 ] && [ "$crashes" -eq 0 ]; then
        crashes="exit $status"  # libFuzzer failed without an artifact: see the log
    fi
    printf '%-18s %12s %8s %8s %8s %8s\n' "$target" "${runs:-?}" "${cov:-?}" "${ft:-?}" \
        "$(find "$work" -type f | wc -l)" "$crashes"
    if [ "$crashes" != 0 ]; then
        found=1
        echo "  $target: see $log; inputs copied to fuzz/crashes/$target/" >&2
    fi
done
exit "$found"
