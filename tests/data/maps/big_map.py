# SPDX-License-Identifier: Apache-2.0
"""Renders maps.jsim's camera over a 16384 x 16384 class map (256 MiB, a binary PGM of 1 cm
texels) and checks the memory it takes: glint maps the PGM as it is and reads only the pages
rays touch, so the render's peak resident memory must stay well below the image's size
(under 128 MiB, where decoding it would take 256 MiB at one byte a texel and 2 GiB as
doubles). The Material truth must still follow the map: the map's classes are 20 x 20
texel squares of DC 10/50/30 (materials 11/12/13), and the camera's 0.2 m pixels each see one
square.

Usage: big_map.py BIN_DIR WORK_DIR SOURCE_FIXTURE_DIR"""
import resource
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np

SIDE = 16384
LIMIT_MIB = 128


def main():
    bin_dir, work, fixture = Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
    scene_dir = work / "big"
    shutil.copytree(fixture, scene_dir)
    shutil.copytree(fixture.parent / "render", work / "render")
    # Squares of 20 texels (0.2 m at 1 cm): DC by (row + column) of the square, mod 3.
    squares = np.array([10, 50, 30], dtype=np.uint8)
    index = (np.arange(SIDE) // 20).astype(np.int32)
    with open(scene_dir / "maps" / "big.pgm", "wb") as f:
        f.write(b"P5\n%d %d\n255\n" % (SIDE, SIDE))
        # In blocks of 64 lines: this process stays small, and so does the render's peak
        # resident memory, which counts what the forked child held before it ran the tool.
        for y in range(0, SIDE, 64):
            block = squares[(index[y:y + 64, None] + index[None, :]) % 3]
            f.write(block.tobytes())
    scene = (scene_dir / "maps.scene").read_text()
    # The classes map from (-80.8, 80.6), so that the footprint's north-west corner
    # (-0.8, 0.6) lies on texel (8000, 8000), the corner of square (400, 400).
    scene = scene.replace("<x>-0.8</x><y>0.6</y></insertpoint><gsd>0.2</gsd>",
                          "<x>-80.8</x><y>80.6</y></insertpoint><gsd>0.01</gsd>")
    scene = scene.replace("classes.pgm", "big.pgm")
    (scene_dir / "maps.scene").write_text(scene)
    out = work / "out"
    result = subprocess.run([str(bin_dir / "glint-render"), str(scene_dir / "maps.jsim"),
                             "--output-folder", str(out), "--convergence", "16,16,0"],
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"glint-render failed ({result.returncode}):\n{result.stderr}")
    peak_mib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    assert peak_mib < LIMIT_MIB, f"peak resident memory {peak_mib:.0f} MiB"
    truth = np.fromfile(out / "truth.img", dtype="<f8").reshape(6, 8, 3)
    header = (out / "truth.img.hdr").read_text()
    ids = header.split("glint material ids = {")[1].split("}")[0].split(", ")
    material = np.array(ids)[truth[:, :4, 0].astype(int)]
    # Pixel (column c, line l) of the west half is square (400 + c, 400 + l).
    rows = (400 + np.arange(6))[:, None]
    cols = (400 + np.arange(4))[None, :]
    expected = np.array(["11", "12", "13"])[(rows + cols) % 3]
    assert (material == expected).all(), (material, expected)
    print(f"big map ok: {SIDE} x {SIDE} texels ({SIDE * SIDE / 2**20:.0f} MiB), "
          f"peak resident memory {peak_mib:.0f} MiB")


if __name__ == "__main__":
    main()
