"""Checks the refraction case (tests/cli/render/refraction-split-channels.toml): a camera 20 km
up looks north at a 70° view zenith across an edge (black ground south of y = 0, a white field
north of it), its two channels (0.45 and 0.90 µm) split into spectral states.

In each channel the edge's position along the column is the count of bright-equivalent
pixels, Σ (v − dark)/(bright − dark) over the rows (dark and bright: the means of the ten rows
at each end). With refraction each channel's rays are bent at its own wavelength: the blue
ones land farther towards the sensor (south) than the near-infrared ones, by the refraction
tracer's 0.90 m at this geometry (tests/unit/radiometry/view_refraction_test.cpp tests the
tracer's table; here it is the renderer that must apply it per channel), so the blue column
holds that much less of the bright field: the difference is −0.90 m over the pixels' ground
spacing (from the Intersection truth, about 1.0 m), within 0.1 pixel (the edge pixels'
sampling noise at 1,000 samples is about 0.02 pixel). With refraction off the two agree within
0.1 pixel. Both runs: the edge lies inside the frame, the header says whether it refracted."""
import sys

import numpy as np

ROWS, COLUMNS = 101, 3


def read(folder, name):
    header = open(f"{folder}/{name}.img.hdr").read()
    bands = int(header.split("bands = ")[1].split("\n")[0])
    values = np.fromfile(f"{folder}/{name}.img", dtype=np.float64).reshape(ROWS, COLUMNS, bands)
    return values, header


def edge_rows(frame, channel):
    column = frame[:, :, channel].mean(axis=1)
    bright = column[:10].mean()
    dark = column[-10:].mean()
    assert bright > 2.0 * dark + 1e-12, f"channel {channel}: no edge in view ({bright}, {dark})"
    return float(((column - dark) / (bright - dark)).sum())


work = sys.argv[1]
bent, bent_header = read(f"{work}/bent", "frame")
straight, straight_header = read(f"{work}/straight", "frame")
assert "glint refraction = on\n" in bent_header, "the refracting run's header"
assert "glint refraction = off\n" in straight_header, "the straight run's header"
truth, header = read(f"{work}/bent", "truth")
names = header.split("band names = {")[1].split("}")[0].split(", ")
y = truth[:, :, names.index("Scene Y")].mean(axis=1)
spacing_m = float(-(y[-1] - y[0]) / (ROWS - 1))
expected = -0.90 / spacing_m
shift = edge_rows(bent, 0) - edge_rows(bent, 1)
none = edge_rows(straight, 0) - edge_rows(straight, 1)
print(f"ground spacing {spacing_m:.3f} m; blue - near-infrared edge: refracted {shift:+.3f} px "
      f"(expected {expected:+.3f}), straight {none:+.3f} px")
assert abs(shift - expected) < 0.1, "the channels' displacement"
assert abs(none) < 0.1, "straight rays: the channels agree"
print("refraction edge ok")
