"""Checks the false-shadow renders: the plate with a far box (with/) against the plate alone
(without/). Radiance: every pixel within 1e-6 relative (no atmosphere, a Lambertian plate:
the only randomness is the sun-disk draw and the pixel position, which the seed makes the
same in both; a false shadow darkens a pixel by up to 90 %). Truth: no shadow anywhere, every
hit on the plate (z = 0 within 1e-6 m) and at the same place in both renders (1e-6 m)."""
import sys

import numpy as np


def read(folder, name):
    header = open(f"{folder}/{name}.img.hdr").read()
    bands = int(header.split("bands = ")[1].split("\n")[0])
    names = header.split("band names = {")[1].split("}")[0].split(", ")
    data = np.fromfile(f"{folder}/{name}.img", dtype=np.float64).reshape(200, 200, bands)
    return data, names


work = sys.argv[1]
with_box, _ = read(f"{work}/with", "frame")
without, _ = read(f"{work}/without", "frame")
assert np.isfinite(with_box).all() and (without > 0).all(), "radiance not positive"
relative = np.abs(with_box / without - 1.0)
darker = int((with_box < 0.9 * without).sum())
assert relative.max() < 1e-6, f"{darker} pixels >10 % darker; largest difference {relative.max():.3g}"

truth, names = read(f"{work}/with", "truth")
reference, _ = read(f"{work}/without", "truth")
band = {n: i for i, n in enumerate(names)}
shadow = truth[:, :, band["Shadow Fraction"]]
assert (shadow == 0).all(), f"{int((shadow > 0).sum())} pixels in false shadow"
z = truth[:, :, band["Scene Z"]]
assert np.abs(z).max() < 1e-6, f"hits off the plate by {np.abs(z).max():.3g} m"
for axis in ("Scene X", "Scene Y", "Distance"):
    gap = np.abs(truth[:, :, band[axis]] - reference[:, :, band[axis]]).max()
    assert gap < 1e-6, f"{axis} differs by {gap:.3g} m from the box-free render"
print(f"far box ok: 40000 pixels, largest radiance difference {relative.max():.2g}")
