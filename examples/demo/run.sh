#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The default example that `make demo` runs. Until glint-render exists it exercises the
# richest pipeline that works: the DIRSIG4 simulation in examples/demo/sim/ is converted to
# a DIRSIG5 .jsim, checked, its camera dumped as normalized JSON and its capture schedule
# written; a generated three-band scene becomes an ENVI cube that is
# inspected, measured and previewed; then a short "capture per file" sequence of a moving
# scene is written as ENVI frames named as DIRSIG's capture schedule names them, each frame
# is converted to PNG with the image_tool spellings of the BasicPlatform manual's
# processing-task example, and the frames are encoded into a video through ffmpeg.
# Usage: examples/demo/run.sh BIN_DIR OUT_DIR
set -euo pipefail

bin=$(cd "${1:?usage: run.sh BIN_DIR OUT_DIR}" && pwd)
out=${2:?usage: run.sh BIN_DIR OUT_DIR}
envi="$bin/glint-envi"
p2j="$bin/glint-platform2jsim"
here=$(cd "$(dirname "$0")" && pwd)
frames=24

step() { printf '\n== %s\n' "$*" >&2; }
run() { printf '$ %s\n' "$*" >&2; "$@"; }

rm -rf "$out"
mkdir -p "$out/frames"

# A 160x120 scene: a smooth colour gradient under a checkerboard, as linear float data.
scene_pattern() {  # $1: checker offset in pixels; $2: output
    oiiotool --pattern "fill:topleft=0.05,0.10,0.20:topright=0.60,0.50,0.30:bottomleft=0.10,0.40,0.10:bottomright=0.90,0.80,0.70" 160x120 3 \
             --pattern "checker:width=20:height=20:color1=0,0,0:color2=0.15,0.15,0.15:xoffset=$1" 160x120 3 \
             --add -d float -o "$2"
}

step "0. the DIRSIG4 simulation examples/demo/sim/demo.sim becomes a DIRSIG5 .jsim"
run "$p2j" "$here/sim/demo.sim" -o "$out/demo.jsim"
run "$p2j" --check "$out/demo.jsim"
run "$p2j" --dump-platform "$here/sim/demo.platform" -o "$out/demo.platform.json"
printf 'camera: F# %s, G# %s 1/sr, bandpass samples %s (from demo.platform.json)\n' \
    "$(grep -m1 '"f_number"' "$out/demo.platform.json" | tr -dc '0-9.')" \
    "$(grep -m1 '"g_number_per_sr"' "$out/demo.platform.json" | tr -dc '0-9.')" \
    "$(grep -m1 '"count"' "$out/demo.platform.json" | tr -dc '0-9')" >&2

step "0b. the capture schedule: 12 Hz frames over the 2 s task, with poses, sun and file names"
run "$bin/glint-schedule" --summary "$out/demo.jsim" >&2
run "$bin/glint-schedule" "$out/demo.jsim" -o "$out/demo.schedule.json"
run "$bin/glint-schedule" --format text --captures 0:4 "$out/demo.jsim" >&2

step "1. a generated scene becomes an ENVI cube (BIP float32, band names R, G, B)"
scene_pattern 0 "$out/scene.exr"
run "$envi" convert "$out/scene.exr" "$out/scene.img"

step "2. what the cube is (glint-envi info) and what it holds (glint-envi stats)"
run "$envi" info "$out/scene.img" | tee "$out/scene.info.txt" >&2
run "$envi" info --format json "$out/scene.img" > "$out/scene.info.json"
run "$envi" stats --format json "$out/scene.img" > "$out/scene.stats.json"
run "$envi" stats "$out/scene.img" >&2

step "3. PNG previews: 2% percentile stretch, and band 1 alone with gamma 2.2"
run "$envi" convert --percent 2 "$out/scene.img" "$out/scene.png"
run "$envi" convert --band 1 --gamma 2.2 "$out/scene.img" "$out/scene-band1.png"

step "4. $frames captures written one file per capture (schedule 'capture'), each converted to PNG"
for ((c = 0; c < frames; c++)); do
    name=$(printf 'demo-t0000-c%04d' "$c")
    scene_pattern $((2 * c)) "$out/frames/$name.exr"
    "$envi" convert "$out/frames/$name.exr" "$out/frames/$name.img"
    rm "$out/frames/$name.exr"
    # The processing task of the manual's video example, with glint-envi for image_tool:
    "$envi" convert --gamma=1 --format=png --output_filename="$out/frames/$name.png" \
        "$out/frames/$name.img"
done
printf '%d ENVI frames and PNGs in %s\n' "$frames" "$out/frames" >&2

step "5. the PNG frames encoded into a video (ffmpeg through glint-envi encode)"
run "$envi" encode --framerate 12 --output "$out/demo.mp4" "$out/frames/demo-t0000-c%04d.png"

cat >&2 <<MSG

glint demo finished. Outputs in $out/:
  demo.jsim                    examples/demo/sim/demo.sim as a DIRSIG5 .jsim
  demo.platform.json           the camera as glint understood it (SI units, F#, G#, IFOV)
  demo.schedule.json           25 captures: time windows, camera poses, sun angles, file names
  scene.img, scene.img.hdr     ENVI cube (160 x 120 x 3, float32, BIP)
  scene.info.txt/.json         glint-envi info
  scene.stats.json             per-band min/max/mean/std
  scene.png, scene-band1.png   previews
  frames/demo-t0000-cNNNN.img  $frames per-capture ENVI frames (+ .png)
  demo.mp4                     the frames as a 12 fps video
MSG
