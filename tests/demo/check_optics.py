#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks the optics example's images (examples/optics/run.sh) against the blurs' transfer
functions. For each bar chart, the amplitude of the bars' fundamental (period 20 pixels: 0.05
cycles per pixel) in the column profile over the bars (four periods, the chart's middle
rows) of the PSF and depth-of-field images, divided by the sharp image's, is the blur's MTF
at 0.05 cycles per pixel (the pixel's own aperture and the scene, shadows included, divide
out):
- PSF, a Gaussian of sigma 2 pixels: exp(-2 pi^2 sigma^2 f^2) = 0.821 on every chart;
- focused at 3 m (a uniform disc of diameter B = D |1/d - 1/f| / IFOV pixels, D = 10 mm,
  IFOV 0.2 mrad): 2 J1(pi B f) / (pi B f): B = 16.7 at 1.5 m -> 0.356; B = 0 at 3 m -> 1;
  B = 8.33 at 6 m -> 0.801.
Tolerance 0.04 on each ratio: the Monte Carlo noise of 64 paths per pixel over 20 x 80
pixels is below 0.005; the rest allows for the profile window's leakage.
Exit 77 when numpy is missing (the test is then skipped)."""
import argparse
import math
import sys

try:
    import numpy as np
except ImportError:
    sys.exit(77)

COLUMNS, ROWS = 320, 240
# Chart centres: -21, 0 and +21 mrad at 0.2 mrad per pixel from the middle column.
CENTRES = {"near": 160 - 105, "focus": 160, "far": 160 + 105}


def fundamental(image, centre):
    profile = image[110:130, centre - 40:centre + 40].mean(axis=0)
    phase = np.exp(-2j * np.pi * np.arange(80) / 20.0)
    return abs(np.sum(profile * phase))


def disc_mtf(diameter_px, f=0.05):
    x = np.pi * diameter_px * f
    # J1 by its series (x < 3 here): sum (-1)^k (x/2)^(2k+1) / (k! (k+1)!)
    j1 = sum((-1) ** k * (x / 2) ** (2 * k + 1) / (math.factorial(k) * math.factorial(k + 1))
             for k in range(20))
    return 2 * j1 / x


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    out = parser.parse_args().out
    images = {name: np.fromfile(f"{out}/{name}.img", dtype="<f4").reshape(ROWS, COLUMNS)
              for name in ("sharp", "psf", "focus")}
    sharp = {chart: fundamental(images["sharp"], c) for chart, c in CENTRES.items()}
    ratio = {name: {chart: fundamental(images[name], c) / sharp[chart]
                    for chart, c in CENTRES.items()} for name in ("psf", "focus")}
    expected = {"psf": {chart: np.exp(-2 * np.pi ** 2 * 4 * 0.05 ** 2) for chart in CENTRES},
                "focus": {"near": disc_mtf(0.01 * (1 / 1.5 - 1 / 3) / 0.0002), "focus": 1.0,
                          "far": disc_mtf(0.01 * (1 / 3 - 1 / 6) / 0.0002)}}
    problems = []
    for name in ratio:
        for chart in CENTRES:
            got, want = ratio[name][chart], expected[name][chart]
            print(f"{name} {chart}: MTF at 0.05 cycles/pixel {got:.3f}, expected {want:.3f}")
            if abs(got - want) > 0.04:
                problems.append(f"{name} image, {chart} chart: {got:.3f} instead of {want:.3f}")
    for p in problems:
        print("check_optics:", p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
