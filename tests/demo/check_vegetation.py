#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks the vegetation example's images (examples/vegetation/run.sh): 240 x 240 pixels of
1/3 m from 400 m straight down, north up, east right, so scene (x, y) lies at column
120 + 3x and row 120 - 3y. Reflectance factors are each band over the white panel's
(rho = 0.99), as ndvi.py computes them.
- canopy: 15-45 % of the pixels have NDVI > 0.5, and their median NIR reflectance factor lies
  between 0.3 and 0.7 (leaves reflect 0.47 and transmit 0.45; crowns over soil);
- the seedlings under the cold frame's clear glass (x 24..32, y -4..4): NIR reflectance
  factor 0.24-0.36 (0.44 x 0.9^4 = 0.29: the glass is a thin box, its top and bottom faces two
  sheets of 0.9 each, passed down and up; a pane that blocked the sun would leave them in
  shadow, under 0.1), NDVI above 0.5;
- the Ward metal roof (x -32..-24, y -4..4): NDVI between -0.2 and 0.05: the roof is
  spectrally flat, but it is dark off its specular peak and the atmosphere's path radiance,
  larger in the red than in the NIR, lowers its NDVI (an empirical line through zero does
  not remove it);
- the pond (x -6..6, y -32..-26): every band's reflectance factor under 0.05.
Exit 77 when numpy is missing (the test is then skipped)."""
import argparse
import re
import sys

try:
    import numpy as np
except ImportError:
    sys.exit(77)


def read_envi(path):
    header = open(path + ".hdr").read()
    field = lambda k: int(re.search(k + r"\s*=\s*(\d+)", header).group(1))
    shape = (field("lines"), field("samples"), field("bands"))
    return np.fromfile(path, "<f4").reshape(shape)


def region(image, x0, x1, y0, y1):
    return image[int(120 - 3 * y1):int(120 - 3 * y0), int(120 + 3 * x0):int(120 + 3 * x1)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    msi = read_envi(args.out + "/render/msi-t0000-c0000.img").astype(np.float64)
    ndvi = read_envi(args.out + "/ndvi.img")[..., 0]
    panel = msi[..., 1] > 0.9 * msi[..., 1].max()
    rho = 0.99 * msi / msi[panel].mean(axis=0)
    failures = []

    def check(name, value, low, high):
        ok = low <= value <= high
        print("%-40s %8.4f in [%g, %g] %s" % (name, value, low, high, "ok" if ok else "FAIL"))
        if not ok:
            failures.append(name)

    canopy = ndvi > 0.5
    check("canopy fraction (NDVI > 0.5)", canopy.mean(), 0.15, 0.45)
    check("canopy median NIR reflectance", np.median(rho[..., 2][canopy]), 0.3, 0.7)
    seedlings = region(rho, 24, 32, -4, 4)
    check("seedlings under glass: NIR reflectance", seedlings[..., 2].mean(), 0.24, 0.36)
    check("seedlings under glass: NDVI", region(ndvi, 24, 32, -4, 4).mean(), 0.5, 1.0)
    check("Ward metal roof: NDVI", region(ndvi, -32, -24, -4, 4).mean(), -0.2, 0.05)
    check("pond: largest band reflectance", region(rho, -6, 6, -32, -26).mean(axis=(0, 1)).max(),
          0.0, 0.05)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
