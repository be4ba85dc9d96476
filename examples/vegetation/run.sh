#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The vegetation example (examples/vegetation/README.md): make_forest.py writes a forest of
# instanced trees whose leaves reflect and transmit (beside a Ward metal roof, a glass-roofed
# cold frame, a pond and a white panel); glint-render images it with a green/red/NIR camera;
# glint-envi writes the false-colour PNG (NIR, red, green as R, G, B); ndvi.py turns the
# image into reflectance with the white panel and writes NDVI, which glint-envi makes a PNG.
# Needs /usr/bin/python3 with NumPy (scripts/install-deps.sh installs it). About 20 s on two
# cores once the tools are built.
# Usage: examples/vegetation/run.sh BIN_DIR OUT_DIR [TREES]
set -euo pipefail

bin=$(cd "${1:?usage: run.sh BIN_DIR OUT_DIR [TREES]}" && pwd)
out=${2:?usage: run.sh BIN_DIR OUT_DIR [TREES]}
trees=${3:-150}
here=$(cd "$(dirname "$0")" && pwd)
run() { printf '$ %s\n' "$*" >&2; "$@"; }

rm -rf "$out"
mkdir -p "$out/render"
cp "$here/vegetation.sim" "$here/vegetation.platform" "$here/vegetation.ppd" \
    "$here/vegetation.tasks" "$here/../demo/sim/demo_atmosphere.yaml" "$here/../demo/sim/june.wth" "$out/"
run python3 "$here/make_forest.py" "$out" --trees "$trees" >&2
run "$bin/glint-platform2jsim" "$out/vegetation.sim" -o "$out/vegetation.jsim"
run "$bin/glint-render" "$out/vegetation.jsim" --output-folder "$out/render" \
    --convergence 64,64,0 --seed 1 > "$out/render/files.txt" 2> "$out/render.log" || {
    cat "$out/render.log" >&2
    exit 1
}
msi="$out/render/msi-t0000-c0000.img"
run "$bin/glint-envi" convert --bands 2,1,0 --per-band --percent 1 --gamma 2.2 \
    "$msi" "$out/vegetation_false_colour.png"
run /usr/bin/python3 "$here/ndvi.py" "$msi" "$out/ndvi.img" >&2
run "$bin/glint-envi" convert --min -0.2 --max 0.9 "$out/ndvi.img" "$out/vegetation_ndvi.png"
printf '%s\n' "$out/vegetation_false_colour.png" "$out/vegetation_ndvi.png"
