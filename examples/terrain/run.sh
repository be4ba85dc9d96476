#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The terrain example (examples/terrain/README.md): make_terrain.py writes a DIRSIG scene of
# a height field whose materials come from a draped land-cover map and whose grass varies
# through a texture map; glint-render images it with a green/red/NIR camera and Material
# truth; glint-envi writes the false-colour PNG (NIR, red, green as R, G, B) and the Material
# truth PNG (one colour per material). Needs /usr/bin/python3 with NumPy
# (scripts/install-deps.sh installs it). About 15 s on two cores once the tools are built.
# Usage: examples/terrain/run.sh BIN_DIR OUT_DIR
set -euo pipefail

bin=$(cd "${1:?usage: run.sh BIN_DIR OUT_DIR}" && pwd)
out=${2:?usage: run.sh BIN_DIR OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
run() { printf '$ %s\n' "$*" >&2; "$@"; }

rm -rf "$out"
mkdir -p "$out/render"
cp "$here/terrain.sim" "$here/terrain.platform" "$here/terrain.ppd" "$here/terrain.tasks" \
    "$here/../demo/sim/demo_atmosphere.yaml" "$here/../demo/sim/june.wth" "$out/"
run /usr/bin/python3 "$here/make_terrain.py" "$out" >&2
run "$bin/glint-platform2jsim" "$out/terrain.sim" -o "$out/terrain.jsim"
run "$bin/glint-render" "$out/terrain.jsim" --output-folder "$out/render" \
    --convergence 16,16,0 --seed 1 > "$out/render/files.txt" 2> "$out/render.log" || {
    cat "$out/render.log" >&2
    exit 1
}
msi="$out/render/msi-t0000-c0000.img"
truth="$out/render/truth-t0000-c0000.img"
run "$bin/glint-envi" convert --bands 2,1,0 --per-band --percent 1 --gamma 2.2 \
    "$msi" "$out/terrain_false_colour.png"
run "$bin/glint-envi" convert --band 0 "$truth" "$out/terrain_materials.png"
printf '%s\n' "$out/terrain_false_colour.png" "$out/terrain_materials.png"
