#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The lidar example (README.md): a flash lidar 300 m above the demo site fires one 905 nm
# pulse; glint-render writes its DIRSIG BIN file, glint-envi reports it and turns the pulse
# into a range image (the range of each pixel's strongest return, and its photons), shown
# side by side as lidar.png. About 10 s on two cores.
# Usage: examples/lidar/run.sh BIN_DIR OUT_DIR
set -euo pipefail

bin=$(cd "${1:?usage: run.sh BIN_DIR OUT_DIR}" && pwd)
out=${2:?usage: run.sh BIN_DIR OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)

run() { printf '$ %s\n' "$*" >&2; "$@"; }

rm -rf "$out"
mkdir -p "$out"
run "$bin/glint-platform2jsim" --check "$here/lidar.jsim" >&2
run "$bin/glint-render" "$here/lidar.jsim" --output-folder "$out" >&2
run "$bin/glint-envi" info "$out/flash.bin" >&2
run "$bin/glint-envi" convert --range --pulse 0 "$out/flash.bin" "$out/range.img"
# Range 288-306 m on a grey ramp (nearer is darker: roofs and trees), the peak photons on a
# 2 % stretch.
run "$bin/glint-envi" convert --band 0 --min 288 --max 306 "$out/range.img" "$out/range.png"
run "$bin/glint-envi" convert --band 1 --percent 2 "$out/range.img" "$out/photons.png"
run ffmpeg -v error -y -i "$out/range.png" -i "$out/photons.png" -filter_complex \
    "[0]scale=384:384:flags=neighbor[a];[1]scale=384:384:flags=neighbor[b];[a][b]hstack=inputs=2" \
    "$out/lidar.png"
printf 'lidar example finished: %s/lidar.png (range | photons of the strongest return)\n' \
    "$out" >&2
