#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The bench driver: times glint's tools on generated inputs and prints a table of
# wall-clock seconds and throughput. Not run by ctest (speed is measured here, never
# asserted in a test). Grows as tools land.
# Usage: bench/run.sh BIN_DIR [SIZE]   (SIZE: square image side in pixels, default 4096)
set -euo pipefail

bin=$(cd "${1:?usage: run.sh BIN_DIR [SIZE]}" && pwd)
size=${2:-4096}
work=$(mktemp -d "${TMPDIR:-/tmp}/glint-bench.XXXXXX")
trap 'rm -rf "$work"' EXIT

seconds() {  # runs "$@" quietly and prints its wall-clock seconds
    local start end
    start=$(date +%s.%N)
    "$@" >/dev/null
    end=$(date +%s.%N)
    awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }'
}
row() {  # name, seconds, megabytes
    awk -v n="$1" -v s="$2" -v mb="$3" 'BEGIN { printf "%-44s %8.3f s %10.1f MB/s\n", n, s, mb / s }'
}

oiiotool --pattern noise:type=uniform:min=0:max=1 "${size}x${size}" 3 -d float -o "$work/in.exr"
mb=$(awk -v n="$size" 'BEGIN { printf "%.1f", n * n * 3 * 4 / 1e6 }')
echo "glint bench: ${size}x${size}x3 float32 ($(printf '%.0f' "$mb") MB), $(nproc) cores"
row "glint-envi convert exr -> envi" "$(seconds "$bin/glint-envi" convert "$work/in.exr" "$work/cube.img")" "$mb"
row "glint-envi stats" "$(seconds "$bin/glint-envi" stats "$work/cube.img")" "$mb"
row "glint-envi convert envi -> png (2% stretch)" "$(seconds "$bin/glint-envi" convert --percent 2 "$work/cube.img" "$work/out.png")" "$mb"
