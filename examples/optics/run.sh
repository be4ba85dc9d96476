#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The optics example (README.md): one glint-render run of three copies of a camera — a
# pinhole, the same with a Gaussian PSF (<psf><width>) and the same lens focused at 3 m
# (<focusdistance>) — looking at bar charts 1.5 m, 3 m and 6 m away; the three images are
# converted to PNG on one stretch and put side by side (sharp | PSF | depth of field) with
# ffmpeg. About 10 s on two cores.
# Usage: examples/optics/run.sh BIN_DIR OUT_DIR
set -euo pipefail

bin=$(cd "${1:?usage: run.sh BIN_DIR OUT_DIR}" && pwd)
out=${2:?usage: run.sh BIN_DIR OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
# 64 paths per pixel: the depth-of-field discs are sampled smoothly enough to see.
convergence=64,64,0
# One stretch for the three images: 0 to the white bars' value in the sharp image (float32,
# W/(cm2 um) at the focal plane: the 10 mm aperture's G# applied), display gamma 2.2.
white=0.00055

run() { printf '$ %s\n' "$*" >&2; "$@"; }

rm -rf "$out"
mkdir -p "$out"
run "$bin/glint-platform2jsim" --check "$here/optics.jsim" >&2
run "$bin/glint-render" "$here/optics.jsim" --output-folder "$out" --convergence "$convergence" >&2
for name in sharp psf focus; do
    run "$bin/glint-envi" convert --min 0 --max "$white" --gamma 2.2 "$out/$name.img" \
        "$out/$name.png"
done
run ffmpeg -v error -y -i "$out/sharp.png" -i "$out/psf.png" -i "$out/focus.png" \
    -filter_complex "[0][1][2]hstack=inputs=3" "$out/optics.png"
printf 'optics example finished: %s/optics.png (sharp | PSF sigma 2 px | focused at 3 m)\n' \
    "$out" >&2
