#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The bench driver: times glint's tools on generated inputs and prints a table of
# wall-clock seconds and throughput. Not run by ctest (speed is measured here, never
# asserted in a test). Grows as tools land.
# Usage: bench/run.sh BIN_DIR [SIZE]   (SIZE: square image side in pixels, default 4096)
# GLINT_BENCH_ARGS: extra arguments for glint-bench (e.g. "--quick", "--threads 1").
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

# glint-detect: a SIZE x SIZE single-band Photons/cm2 frame (about 4000-8000 electrons per
# pixel) through bench/detect.platform with every noise on, 2 threads; pixel-channels per second.
here=$(cd "$(dirname "$0")" && pwd)
python3 - "$work/photons.img" "$size" <<'PY'
import array, sys
path, n = sys.argv[1], int(sys.argv[2])
line = array.array("d", [6.25e9 * (1 + (x % 97) / 97.0) for x in range(n)])
with open(path, "wb") as f:
    for _ in range(n):
        line.tofile(f)
with open(path + ".hdr", "w") as f:
    f.write("ENVI\nsamples = %d\nlines = %d\nbands = 1\nheader offset = 0\n"
            "file type = ENVI Standard\ndata type = 5\ninterleave = bip\nbyte order = %d\n"
            "data units = Photons/cm2\n" % (n, n, 0 if sys.byteorder == "little" else 1))
PY
detect_s=$(seconds "$bin/glint-detect" "$work/photons.img" -o "$work/dc.img" \
    --platform "$here/detect.platform" --focal-plane Frame --threads 2 -q)
awk -v s="$detect_s" -v n="$size" 'BEGIN { printf "%-44s %8.3f s %10.1f M pixel-channels/s (target >= 50)\n", "glint-detect, all noise, 2 threads", s, n * n / s / 1e6 }'
rm -f "$work/photons.img" "$work/dc.img"

# The Embree scene and the path tracer against bare Embree (docs/performance.md): JSON.
read -r -a bench_args <<<"${GLINT_BENCH_ARGS:-}"
echo "glint-bench: Embree scene and path tracer vs bare rtcIntersect1 (docs/performance.md)"
"$bin/glint-bench" "${bench_args[@]}"
