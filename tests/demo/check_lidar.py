#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks the lidar example's range image (examples/lidar/run.sh) against the receiver's
geometry: a pixel (column i, row j) of the 128 x 128 array (20 um pitch, 11 mm focal length,
looking straight down from 300 m) sees the ground along (x/f, y/f, -1) with
x = (i + 0.5 - 64) 20 um and y = -(j + 0.5 - 64) 20 um, so its range to a surface at height z is
(300 - z) sqrt(1 + (x/f)^2 + (y/f)^2). Checked at the centre (the road, z = 0.02 m) and the four
corners (grass, z = 0), within 0.05 m: half a 0.5 ns bin is 0.0375 m, and a pixel's samples
spread its range by under 1 mm. Every pixel must see a return; the warehouse roof (the
nearest flat surface) must be nearer than the ground by its height.
Exit 77 when numpy is missing (the test is then skipped)."""
import argparse
import math
import sys

try:
    import numpy as np
except ImportError:
    sys.exit(77)

SIZE, PITCH_M, FOCAL_M, HEIGHT_M = 128, 20e-6, 0.011, 300.0


def expected_range(row, column, z_m):
    x = (column + 0.5 - SIZE / 2) * PITCH_M / FOCAL_M
    y = -(row + 0.5 - SIZE / 2) * PITCH_M / FOCAL_M
    return (HEIGHT_M - z_m) * math.sqrt(1 + x * x + y * y)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    image = np.fromfile(f"{args.out}/range.img", dtype="<f8").reshape(SIZE, SIZE, 2)
    ranges, photons = image[:, :, 0], image[:, :, 1]
    problems = []
    for row, column, z in ((64, 64, 0.02), (0, 0, 0.0), (0, 127, 0.0), (127, 0, 0.0),
                           (127, 127, 0.0)):
        want = expected_range(row, column, z)
        got = ranges[row, column]
        print(f"pixel ({column}, {row}): range {got:.4f} m, expected {want:.4f} m")
        if abs(got - want) > 0.05:
            problems.append(f"pixel ({column}, {row}): range {got} m, expected {want} m")
    if not (photons > 0).all():
        problems.append(f"{int((photons <= 0).sum())} pixels without a return")
    nearest = ranges.min()
    print(f"nearest return {nearest:.3f} m")
    if not nearest < HEIGHT_M - 5:
        problems.append(f"no roof nearer than 295 m (nearest {nearest} m)")
    for p in problems:
        print("check_lidar:", p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
