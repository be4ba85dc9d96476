#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Regenerates docs/images/sky_fisheye.png: the directional sky the renderer reads, as an
# equidistant fisheye, for a rural haze of 23 and 5 km visibility (tests/tools/sky_fisheye.cpp;
# docs/physics.md, "The sky in the renderer"). Builds the program in the release preset's tree
# first; a few seconds.
# Usage: scripts/make-sky-fisheye.sh
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cmake --preset release >/dev/null
cmake --build --preset release --target sky_fisheye
build/release/tests/sky_fisheye data docs/images/sky_fisheye.png
