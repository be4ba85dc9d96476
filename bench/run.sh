#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The bench driver: times glint's tools on generated inputs and prints a table of
# wall-clock seconds and throughput. Not run by ctest (speed is measured here, never
# asserted in a test). Grows as tools land.
# Usage: bench/run.sh BIN_DIR [SIZE]   (SIZE: square image side in pixels, default 4096)
# GLINT_BENCH_ARGS: extra arguments for glint-bench (e.g. "--quick", "--threads 1").
#
#        bench/run.sh --peer [--quick] [BIN_DIR [WORK_DIR]]
# The peer benchmark (bench/peer/README.md): glint-render against Blender Cycles on the same
# 1,008,200-triangle terrain, interleaved, other load recorded; prints a table of render and
# wall time ratios per spp and band count, and a JSON line. BIN_DIR defaults to
# build/release/bin, WORK_DIR (scene, cached OBJ, logs, peer.json) to out/peer. Installs
# Debian's blender package (apt-get, as root) when `blender` is missing, and python3-numpy
# when /usr/bin/python3 has no numpy. --quick: 256 x 256, spp 1 and 4, one repeat (checks the
# script in a minute). GLINT_PEER_ARGS: extra arguments for bench/peer/run_peer.py (e.g.
# "--repeats 5", "--spp 1,4", "--max-interference 0.10").
set -euo pipefail

if [[ "${1:-}" == "--peer" ]]; then
    shift
    quick=()
    if [[ "${1:-}" == "--quick" ]]; then
        quick=(--quick)
        shift
    fi
    here=$(cd "$(dirname "$0")" && pwd)
    bin=$(cd "${1:-$here/../build/release/bin}" && pwd)
    work=${2:-$here/../out/peer}
    as_root() { if [[ $(id -u) -eq 0 ]]; then "$@"; else sudo "$@"; fi; }
    apt_install() {  # installs Debian packages, refreshing the package lists once if needed
        as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "$@" ||
            { as_root apt-get update && as_root env DEBIAN_FRONTEND=noninteractive \
                apt-get install -y --no-install-recommends "$@"; }
    }
    if ! command -v blender >/dev/null; then
        echo "bench/run.sh --peer: installing Debian's blender package (with blender-data about 190 MB installed)" >&2
        apt_install blender
    fi
    py=/usr/bin/python3
    [[ -x $py ]] || py=python3
    if ! "$py" -c "import numpy" 2>/dev/null; then
        apt_install python3-numpy
    fi
    read -r -a peer_args <<<"${GLINT_PEER_ARGS:-}"
    mkdir -p "$work"
    work=$(cd "$work" && pwd)
    exec "$py" "$here/peer/run_peer.py" --bin "$bin" --work "$work" --out "$work/results" \
        "${quick[@]}" "${peer_args[@]}"
fi

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
