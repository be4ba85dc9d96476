#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The memory table of docs/performance.md ("Memory"): glint-render's peak resident memory and
# time for one capture of SIZE x SIZE pixels at 1 sample per pixel over the render fixtures'
# plate (bench/hyper/make_hyper.py) with a bandpass of 3, 32 or 2,101 samples (as many
# gaussian channels, 224 for 2,101 — 0.4-2.5 µm at 1 nm: an AVIRIS-like imager), for each SIZE given. The output
# files go to a temporary folder (a 4096² x 224-channel float64 image is 30 GB) and are removed.
# Usage: bench/hyper/memory.sh BIN_DIR [SIZE...]   (default sizes: 1024 4096)
set -euo pipefail

bin=$(cd "${1:?usage: memory.sh BIN_DIR [SIZE...]}" && pwd)
shift
sizes=("$@")
[[ ${#sizes[@]} -gt 0 ]] || sizes=(1024 4096)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/glint-memory.XXXXXX")
trap 'rm -rf "$work"' EXIT

printf '| pixels | bandpass samples | channels | peak RSS MiB | wall s | output MiB |\n'
printf '|---:|---:|---:|---:|---:|---:|\n'
for size in "${sizes[@]}"; do
    for samples in 3 32 2101; do
        channels=$samples
        [[ $samples -le 224 ]] || channels=224
        sim="$work/sim-$size-$samples"
        /usr/bin/python3 "$here/make_hyper.py" "$sim" --size "$size" --samples "$samples" \
            --channels "$channels"
        /usr/bin/time -f '%M %e' -o "$work/time.txt" "$bin/glint-render" "$sim/hyper.jsim" \
            --output-folder "$sim/out" --convergence 1,1,0 -q > /dev/null
        read -r rss_kib wall_s < "$work/time.txt"
        out_mib=$(du -sm "$sim/out" | cut -f1)
        printf '| %d² | %d | %d | %d | %s | %d |\n' "$size" "$samples" "$channels" \
            $((rss_kib / 1024)) "$wall_s" "$out_mib"
        rm -rf "$sim"
    done
done
