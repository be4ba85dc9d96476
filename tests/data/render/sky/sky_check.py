"""Checks the directional-sky case (tests/cli/render/directional-sky.toml): a 41 × 41 camera on
the ground looking straight up (±54° across) under a rural haze of 5 km visibility. With the
isotropic sky every pixel reads E_d/π exactly (the camera's rays meet nothing: no sampling
noise), so the image is flat to 1e-12. With the directional sky (the default) it is not: the
pixel brightest is the one nearest the sun (its aureole), more than 5 times the pixel opposite
it through the image's centre (measured 12.1), and the sky's mean over the frame lies
within a factor of 2 of E_d/π."""
import sys

import numpy as np

work = sys.argv[1]
shaped = np.fromfile(f"{work}/shaped/sky.img", dtype=np.float64).reshape(41, 41)
flat = np.fromfile(f"{work}/flat/sky.img", dtype=np.float64).reshape(41, 41)
assert flat.min() > 0.0 and flat.max() / flat.min() - 1.0 < 1e-12, "the isotropic sky is flat"
row, column = np.unravel_index(shaped.argmax(), shaped.shape)
assert (row, column) != (20, 20), "the sun is not overhead at this date"
opposite = shaped[40 - row, 40 - column]
ratio = shaped[row, column] / opposite
mean = shaped.mean() / flat[0, 0]
print(f"brightest pixel ({row}, {column}): {ratio:.2f} x the opposite one; frame mean "
      f"{mean:.3f} x the isotropic sky")
assert ratio > 5.0, "the aureole"
assert 0.5 < mean < 2.0, "the scale"
print("directional sky ok")
