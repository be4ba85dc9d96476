#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks the terrain example's images (examples/terrain/run.sh): 240 x 240 pixels of 10 um
behind 12 mm from 2000 m straight down, north up, east right.
- the Material truth is the land-cover map: each pixel's centre ray is followed down to the
  height field (the same heights make_terrain.py wrote), the class there looked up in
  maps/landcover.pgm (2 m texels draped from (-200, 200)), and at least 97 % of the pixels
  whose 3 x 3 texel neighbourhood holds one class agree (the rest sit on facet/texel edges);
- every land-cover class shows; texture classes are reported as the grass (12), never as
  their own ids;
- the texture varies the grass: its NIR radiance has a coefficient of variation above 3 %
  (the six classes span NIR reflectance 0.30-0.50), 1.4 times the forest's (one curve,
  varied only by slope and noise);
- water is the darkest class in the NIR.
Exit 77 when numpy is missing (the test is then skipped)."""
import argparse
import re
import sys
from pathlib import Path

try:
    import numpy as np
except ImportError:
    sys.exit(77)

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples" / "terrain"))
from make_terrain import height_m  # noqa: E402  (the heights the scene was written with)


def read_envi(path, dtype):
    header = Path(str(path) + ".hdr").read_text()
    field = lambda k: int(re.search(k + r"\s*=\s*(\d+)", header).group(1))
    shape = (field("lines"), field("samples"), field("bands"))
    ids = re.search(r"glint material ids\s*=\s*\{([^}]*)\}", header)
    return np.fromfile(path, dtype).reshape(shape), ids and [s.strip() for s in ids.group(1).split(",")]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    out = Path(parser.parse_args().out)
    truth, ids = read_envi(out / "render" / "truth-t0000-c0000.img", "<f8")
    msi, _ = read_envi(out / "render" / "msi-t0000-c0000.img", "<f4")
    material = np.array(ids)[truth[..., 0].astype(int)]
    pgm = (out / "maps" / "landcover.pgm").read_bytes()
    classes = np.frombuffer(pgm[-200 * 200:], dtype=np.uint8).reshape(200, 200)
    lut = {30: "11", 90: "12", 150: "13", 200: "14", 250: "15"}

    # Each pixel centre's ray from (0, 0, 2000) down to the height field.
    tan = (np.arange(240) + 0.5 - 120) * 10e-6 / 12e-3
    u, v = np.meshgrid(tan, -tan)  # row 0 looks north
    z = np.full(u.shape, 14.0)
    for _ in range(30):
        x, y = u * (2000 - z), v * (2000 - z)
        z = height_m(x, y)
    col = np.clip(((x + 200) / 2).astype(int), 0, 199)
    line = np.clip(((200 - y) / 2).astype(int), 0, 199)
    expected = np.vectorize(lut.get)(classes[line, col])
    padded = np.pad(classes, 1, mode="edge")
    uniform = np.ones(classes.shape, bool)
    for dy in (0, 1, 2):
        for dx in (0, 1, 2):
            uniform &= padded[dy:dy + 200, dx:dx + 200] == classes
    inside = uniform[line, col]
    agree = (material == expected)[inside].mean()
    assert agree >= 0.97, f"Material truth agrees with the land-cover map at {agree:.3f}"
    shown = set(material.ravel())
    assert shown == set(lut.values()), f"materials shown: {sorted(shown)}"

    nir = msi[..., 2]
    grass = nir[(material == "12") & inside]
    forest = nir[(material == "13") & inside]
    water = nir[(material == "11") & inside]
    cv_grass = grass.std() / grass.mean()
    cv_forest = forest.std() / forest.mean()
    assert cv_grass > 0.03 and cv_grass > 1.4 * cv_forest, (cv_grass, cv_forest)
    means = {c: nir[(material == c) & inside].mean() for c in lut.values()}
    assert min(means, key=means.get) == "11", means
    print(f"terrain ok: truth agrees at {agree:.3f} of {inside.sum()} pixels; grass NIR CV "
          f"{cv_grass:.3f} (forest {cv_forest:.3f}); water NIR {water.mean():.3g}")


if __name__ == "__main__":
    main()
