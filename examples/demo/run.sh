#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The default example that `make demo` runs (examples/demo/README.md describes the scene).
# The DIRSIG4 simulation examples/demo/sim/demo.sim (a glint YAML scene, a parametric
# atmosphere, an aircraft carrying an RGB frame camera and a multispectral pushbroom, a .ppd
# flight line, a .tasks window) is converted to a DIRSIG5 .jsim and checked, its platform
# dumped as normalized JSON and its capture schedule written; glint-render renders every
# capture into ENVI files, and the RGB camera's processing tasks turn each frame into a PNG
# and encode the frames into a video through ffmpeg; glint-envi reports on the files and
# converts a false-colour composite of the pushbroom image to PNG; the Bayer camera's
# digital counts (detected in the render) are demosaiced to colour. Takes about half a minute on two cores once the tools are built.
# Usage: examples/demo/run.sh BIN_DIR OUT_DIR
set -euo pipefail

bin=$(cd "${1:?usage: run.sh BIN_DIR OUT_DIR}" && pwd)
out=${2:?usage: run.sh BIN_DIR OUT_DIR}
envi="$bin/glint-envi"
p2j="$bin/glint-platform2jsim"
here=$(cd "$(dirname "$0")" && pwd)
# Samples per pixel: at least 8, at most 64, stop when the pixel's mean radiance at the
# bandpass centre moved by less than 1e-5 W/(cm2 sr um) (about 0.3% of the grass) with the
# last sample.
convergence=8,64,1e-5
fps=6  # the RGB camera's clock rate, the video's frame rate (demo.platform): real time

step() { printf '\n== %s\n' "$*" >&2; }
run() { printf '$ %s\n' "$*" >&2; "$@"; }

rm -rf "$out"
mkdir -p "$out/render"

step "1. the DIRSIG4 simulation examples/demo/sim/demo.sim becomes a DIRSIG5 .jsim"
run "$p2j" "$here/sim/demo.sim" -o "$out/demo.jsim"
run "$p2j" --check "$out/demo.jsim" >&2
run "$p2j" --dump-platform "$here/sim/demo.platform" -o "$out/demo.platform.json"
# F# and G# of the camera, then of the pushbroom
mapfile -t optics < <(grep -e '"f_number"' -e '"g_number_per_sr"' "$out/demo.platform.json" |
                          tr -dc '0-9.\n')
printf 'Camera: F# %s, G# %s 1/sr; Pushbroom: F# %s, G# %s 1/sr (from demo.platform.json)\n' \
    "${optics[@]}" >&2

step "2. the capture schedule: 25 RGB frames (6 Hz), 2 Bayer frames and 241 pushbroom lines (60 Hz) in 4 s"
run "$bin/glint-schedule" --summary "$out/demo.jsim" >&2
run "$bin/glint-schedule" "$out/demo.jsim" -o "$out/demo.schedule.json"
run "$bin/glint-schedule" --format text --captures 0:4 "$out/demo.jsim" >&2

step "3. glint-render: every capture into ENVI files (the log of the first capture below)"
printf '$ %s -v %s --output-folder %s --convergence %s > %s 2> %s\n' "$bin/glint-render" \
    "$out/demo.jsim" "$out/render" "$convergence" "$out/render/files.txt" \
    "$out/render/render.log" >&2
SECONDS=0
"$bin/glint-render" -v "$out/demo.jsim" --output-folder "$out/render" \
    --convergence "$convergence" > "$out/render/files.txt" 2> "$out/render/render.log" || {
    cat "$out/render/render.log" >&2
    exit 1
}
grep -m1 -A5 'Starting capture' "$out/render/render.log" >&2
printf '... %d captures in %d s, %d files written (list in render/files.txt)\n' \
    "$(grep -c 'Starting capture' "$out/render/render.log")" "$SECONDS" \
    "$(wc -l < "$out/render/files.txt")" >&2

step "4. what the files are and hold (glint-envi info and stats)"
frame0="$out/render/rgb-t0000-c0000.img"
run "$envi" info "$frame0" >&2
run "$envi" stats "$frame0" >&2
"$envi" stats --format json "$frame0" > "$out/render/rgb-t0000-c0000.stats.json"
# The pushbroom's header lists its 241 capture ids, windows and times: kept in a file.
run "$envi" info "$out/render/msi.img" > "$out/render/msi.info.txt"
run "$envi" stats "$out/render/msi.img" | tee "$out/render/msi.stats.txt" >&2

step "5. PNG previews: the RGB frames (made during the render), the pushbroom as false colour"
# The RGB focal plane's processing tasks (examples/demo/sim/demo.platform, docs/processing.md)
# converted each frame to PNG as it was written, on one stretch for all frames, and encoded
# them into demo.mp4 when the collection completed: the render's log shows their messages.
grep -m1 -e 'Converting radiance image to PNG' "$out/render/render.log" >&2
grep -m1 -e 'Encoding frames into video' "$out/render/render.log" >&2
printf '%d frames converted to PNG (render/rgb-t0000-cNNNN.png), video render/demo.mp4\n' \
    "$(ls "$out"/render/rgb-t0000-c*.png | wc -l)" >&2
# NIR, red, green as red, green, blue: vegetation shows red. The first line (south) is at
# the top: a pushbroom image is stacked in acquisition order.
run "$envi" convert --bands 4,2,1 --per-band --percent 1 --gamma 2.2 \
    "$out/render/msi.img" "$out/render/msi-false-colour.png"

step "6. the video: encoded by ffmpeg, the RGB focal plane's collection_completed task"
run ls -l "$out/render/demo.mp4" >&2

step "7. the Bayer camera: digital counts from in-render detection, demosaiced to colour"
# glint-render applied the focal plane's detector model (QE, shot/dark/read noise, 12-bit
# ADC) and its RGGB mosaic; glint-demosaic restores three colours per pixel (raw sensor
# colour, not white-balanced).
run "$envi" stats "$out/render/bayer-t0000-c0000.img" >&2
for img in "$out"/render/bayer-t0000-c*.img; do
    run "$bin/glint-demosaic" --method mhc --percent 0.5 --gamma 2.2 "$img" "${img%.img}.png"
done

step "8. truth: the RGB camera's material map (glint-envi convert, index colour map)"
# The RGB focal plane's truth collection writes a cube per frame beside the radiance: the
# material index, the car abundance, the sample count and each channel's standard error
# (docs/truth.md). An index band converts to PNG with one colour per material.
run "$envi" info "$out/render/rgb_truth-t0000-c0010.img" | sed -n '/band list:/,/glint provenance:/p' >&2
run "$envi" convert --bands 0 "$out/render/rgb_truth-t0000-c0010.img" \
    "$out/render/rgb_truth-t0000-c0010-material.png"

cat >&2 <<MSG

glint demo finished. Outputs in $out/:
  demo.jsim                          examples/demo/sim/demo.sim as a DIRSIG5 .jsim
  demo.platform.json                 the platform as glint understood it (SI units, F#, G#)
  demo.schedule.json                 268 captures: time windows, poses, sun angles, file names
  render/rgb-t0000-cNNNN.img (.hdr)  25 RGB frames, 160 x 120 x 3, Joules/(cm2 um)
  render/rgb-t0000-cNNNN.png         the same frames as PNG
  render/msi.img (.hdr)              the pushbroom image, 256 x 241 x 5 (blue to NIR)
  render/msi-false-colour.png        NIR, red, green composite (first line, south, on top)
  render/bayer-t0000-cNNNN.img (.hdr) 2 Bayer mosaics, 160 x 120, 12-bit counts (uint16, DN)
  render/bayer-t0000-cNNNN.png       the same, demosaiced (Malvar-He-Cutler) to colour
  render/rgb_truth-t0000-cNNNN.img   25 truth cubes: material index, car abundance, sample
                                     count, standard error per channel (docs/truth.md)
  render/rgb_truth-t0000-c0010-material.png  frame 10's material map
  render/render.log, files.txt       glint-render's log (-v) and the files it wrote
  render/*.stats.*, msi.info.txt     glint-envi stats and info reports
  render/demo.mp4                    the RGB frames as a ${fps} fps video
MSG
