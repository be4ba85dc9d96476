#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The thermal example (examples/thermal/README.md): the demo site seen by an 8-12 um camera
# at 13:00 and at 01:00. glint-render solves every THERM material of the demo scene under the
# demo atmosphere's weather (../demo/sim/june.wth), then renders both captures with their
# Temperature and Material truth; glint-envi writes each radiance image as a PNG (a 1 %
# stretch of its own). About 10 s on two cores once the tools are built.
# Usage: examples/thermal/run.sh BIN_DIR OUT_DIR
set -euo pipefail

bin=$(cd "${1:?usage: run.sh BIN_DIR OUT_DIR}" && pwd)
out=${2:?usage: run.sh BIN_DIR OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
run() { printf '$ %s\n' "$*" >&2; "$@"; }

rm -rf "$out"
mkdir -p "$out/render"
run "$bin/glint-platform2jsim" "$here/thermal.sim" -o "$out/thermal.jsim"
run "$bin/glint-render" -v "$out/thermal.jsim" --output-folder "$out/render" \
    --convergence 16,16,0 --seed 1 > "$out/render/files.txt" 2> "$out/render.log" || {
    cat "$out/render.log" >&2
    exit 1
}
grep 'THERM' "$out/render.log" >&2
for capture in 0000:noon 0001:night; do
    run "$bin/glint-envi" convert --percent 1 "$out/render/lwir-t${capture%%:*}.img" \
        "$out/lwir_${capture##*:}.png"
done
printf '%s\n' "$out/lwir_noon.png" "$out/lwir_night.png"
