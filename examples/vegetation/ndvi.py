#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""NDVI of the vegetation example's image: each band's radiance divided by the white
reference panel's (ρ = 0.99, an empirical line through zero) is a reflectance factor; NDVI =
(ρ_NIR − ρ_red)/(ρ_NIR + ρ_red) per pixel, written as a one-band float32 ENVI image (BSQ,
little endian) for glint-envi convert. Prints the panel's radiances and the NDVI of the
canopy, the soil, the seedlings under glass, the roof and the pond.

Usage: ndvi.py MSI.img OUT.img   (MSI.img: glint's 3-band BIP float32 image, Green Red NIR)
"""
import re
import sys

import numpy as np


def read_envi(path):
    header = open(path + ".hdr").read()
    field = lambda k: int(re.search(k + r"\s*=\s*(\d+)", header).group(1))
    lines, samples, bands = field("lines"), field("samples"), field("bands")
    assert "bip" in header and re.search(r"data type\s*=\s*4", header), "expected float32 BIP"
    return np.fromfile(path, "<f4").reshape(lines, samples, bands)


def main():
    image = read_envi(sys.argv[1])
    green, red, nir = (image[..., b].astype(np.float64) for b in range(3))
    # The panel: the brightest red pixels (nothing else in the scene is near 99 % in the red),
    # its 4 m square's inner pixels.
    panel = red > 0.9 * red.max()
    reflectance = [0.99 * band / band[panel].mean() for band in (green, red, nir)]
    _, rho_red, rho_nir = reflectance
    ndvi = (rho_nir - rho_red) / np.maximum(rho_nir + rho_red, 1e-12)
    ndvi.astype("<f4").tofile(sys.argv[2])
    lines, samples = ndvi.shape
    with open(sys.argv[2] + ".hdr", "w") as f:
        f.write("ENVI\ndescription = {NDVI from %s (examples/vegetation/ndvi.py)}\n"
                "samples = %d\nlines = %d\nbands = 1\nheader offset = 0\nfile type = ENVI Standard\n"
                "data type = 4\ninterleave = bsq\nbyte order = 0\nband names = {NDVI}\n"
                % (sys.argv[1], samples, lines))
    print("panel: %d pixels, radiance G R NIR = %.4g %.4g %.4g"
          % (panel.sum(), green[panel].mean(), red[panel].mean(), nir[panel].mean()))
    print("NDVI percentiles 5/50/95: %.3f %.3f %.3f" % tuple(np.percentile(ndvi, [5, 50, 95])))
    print("pixels with NDVI > 0.5 (canopy): %.1f %%" % (100.0 * (ndvi > 0.5).mean()))


if __name__ == "__main__":
    main()
