"""Checks the UTM-coordinates renders: the plate and 8 m box at the origin (origin/) and the
same 500,000 m east and 4,000,000 m north (utm/), each seen from 6 km straight above it.
Radiance: every pixel within 1e-6 relative (the same scene in Embree's frame, which is
centred on the scene: the bytes agree). Truth: the same shadow map, with the box's shadow
in view, and the same hits shifted by exactly the offset (1e-6 m)."""
import sys

import numpy as np

work = sys.argv[1]
origin = np.fromfile(f"{work}/origin/frame.img", dtype=np.float64)
utm = np.fromfile(f"{work}/utm/frame.img", dtype=np.float64)
assert origin.size == utm.size == 40000, (origin.size, utm.size)
lit = origin > 1e-6
gap = np.abs(utm[lit] / origin[lit] - 1.0).max()
assert gap < 1e-6, f"radiance differs by {gap:.3g} relative"
assert np.abs(utm[~lit] - origin[~lit]).max() < 1e-12, "shadowed pixels differ"

a = np.fromfile(f"{work}/origin/truth.img", dtype=np.float64).reshape(200, 200, 11)
b = np.fromfile(f"{work}/utm/truth.img", dtype=np.float64).reshape(200, 200, 11)
shadow_a, shadow_b = a[:, :, 0], b[:, :, 0]
assert (shadow_a == shadow_b).all(), f"{int((shadow_a != shadow_b).sum())} shadow pixels differ"
assert (shadow_a > 0).sum() > 1000, "the box's shadow is not in view"
for band, shift in ((1, 500000.0), (2, 4000000.0), (3, 0.0), (10, 0.0)):
    moved = np.abs(b[:, :, band] - a[:, :, band] - shift).max()
    assert moved < 1e-6, f"truth band {band} off by {moved:.3g} m"
print(f"utm ok: {int((shadow_a > 0).sum())} shadowed pixels, largest radiance difference {gap:.2g}")
