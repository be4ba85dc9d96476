# SPDX-License-Identifier: Apache-2.0
"""Checks a render of maps.jsim: the west half's Material truth is the classification image
texel for texel, the east half's Abundance truth is the mixture's weights, and the radiance
is proportional to each texel's reflectance (pure) or its weighted mean (mixed, within 5 σ
of the draw's noise). Usage: check.py OUTPUT_FOLDER SAMPLES_PER_PIXEL

With `texture` as the first argument, checks a render of texture.jsim instead: each texel
shows the texture class a z-score match of its brightness selects (computed here from the
image and the .ems curves), the Material truth is the textured material everywhere, and the
mean reflectance over the image is the material's mean over its classes.
Usage: check.py texture OUTPUT_FOLDER

With `thermal`, checks a render of thermal.jsim (a temperature map): check.py thermal
OUTPUT_FOLDER SAMPLES_PER_PIXEL. With `uv`, a render of uv.jsim (a uv projector on a textured
OBJ): check.py uv OUTPUT_FOLDER. With `bump`, a render of bump.jsim (bump maps of constant
slope): check.py bump OUTPUT_FOLDER"""
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RHO = {10: 0.1, 50: 0.5, 30: 0.3}  # DC → the reflectance of its material
ID = {10: "11", 50: "12", 30: "13"}


def header(path):
    keys = {}
    for line in path.read_text().splitlines():
        if "=" in line:
            key, value = line.split("=", 1)
            keys[key.strip()] = value.strip()
    return keys


def texture(out):
    pgm = (HERE / "maps" / "texture.pgm").read_bytes()
    dc = np.frombuffer(pgm[-48:], dtype=np.uint8).reshape(6, 8).astype(float)
    curves = (HERE / "materials" / "textured.ems").read_text().split("CURVE_BEGIN")[1:]
    rho = np.array([1 - float(c.split()[1]) for c in curves])  # flat emissivity curves
    z_texel = (dc - dc.mean()) / dc.std()
    z_class = (rho - rho.mean()) / rho.std()
    selected = rho[np.abs(z_texel[..., None] - z_class).argmin(axis=-1)]
    radiance = np.fromfile(out / "frame.img", dtype="<f8").reshape(6, 8)
    k = radiance / selected
    assert k.std() / k.mean() < 1e-3, radiance / radiance.max()
    truth = np.fromfile(out / "truth.img", dtype="<f8").reshape(6, 8, 3)
    ids = [s.strip() for s in header(out / "truth.img.hdr")["glint material ids"].strip("{}").split(",")]
    assert {ids[int(i)] for i in truth[..., 0].ravel()} == {"2"}, truth[..., 0]
    # Four brightness levels of 12 texels each: every class a quarter of the image.
    assert abs(selected.mean() - rho.mean()) < 1e-12, (selected.mean(), rho.mean())
    classes = ", ".join(f"{c:.1f}" for c in sorted(set(selected.ravel())))
    print(f"texture ok: classes {classes}, mean {selected.mean():.3f}")


def planck_w_per_cm2_sr_um(wavelength_um, temperature_k):
    h, c, k = 6.62607015e-34, 2.99792458e8, 1.380649e-23
    w = wavelength_um * 1e-6
    return 2 * h * c**2 / w**5 / np.expm1(h * c / (w * k * temperature_k)) * 1e-10


def thermal(out, samples):
    """thermal.jsim: a black plate under a temperature map of 10 + 0.5 column + 0.8 line °C,
    texel (column, line) under pixel (column − 1, line − 1). The Temperature truth is each
    pixel's mean over its samples of a plane: its texel's value within 5 σ of the samples'
    spread; the radiance is the band's Planck radiance at it (one scale for all pixels, the
    tophat's mean, within 1 % of 1)."""
    truth = np.fromfile(out / "truth.img", dtype="<f8").reshape(6, 8)
    expected_c = 10 + 0.5 * (np.arange(8) + 1)[None, :] + 0.8 * (np.arange(6) + 1)[:, None]
    sigma = np.sqrt((0.5**2 + 0.8**2) / 12 / samples)
    error = np.abs(truth - 273.15 - expected_c).max()
    assert error < 5 * sigma, (error, sigma)
    radiance = np.fromfile(out / "frame.img", dtype="<f8").reshape(6, 8)
    band = np.linspace(10.0, 11.0, 101)
    expected = np.array([planck_w_per_cm2_sr_um(band, t).mean() for t in (expected_c + 273.15).ravel()])
    k = radiance.ravel() / expected
    assert k.std() / k.mean() < 1e-3 and abs(k.mean() - 1) < 0.01, k
    print(f"thermal ok: temperature within {error:.3f} K (sigma {sigma:.3f} K), radiance scale {k.mean():.4f}")


def uv(out):
    """uv.jsim: pixel (column c, line l) sees texel (column l // 2, line 3 − c // 2) of
    maps/uv_classes.pgm (u runs south, v east; the projector flips its lines)."""
    pgm = (HERE / "maps" / "uv_classes.pgm").read_bytes()
    image = np.frombuffer(pgm[-12:], dtype=np.uint8).reshape(4, 3)
    truth = np.fromfile(out / "truth.img", dtype="<f8").reshape(6, 8, 3)
    ids = [s.strip() for s in header(out / "truth.img.hdr")["glint material ids"].strip("{}").split(",")]
    material = np.array(ids)[truth[..., 0].astype(int)]
    lines, cols = np.meshgrid(np.arange(6), np.arange(8), indexing="ij")
    expected = np.vectorize(lambda dc: ID[dc])(image[3 - cols // 2, lines // 2])
    assert (material == expected).all(), (material, expected)
    print("uv ok")


def bump(out):
    """bump.jsim: eight grey Lambertian quads lit by the sun alone (black sky), six tilted by a
    bump map of constant slope (sx, sy): L ∝ n'·s with n' ∝ (−sx, −sy, 1). The flat quads A
    and H agree; B (0.3, 0) and C (0, 0.3) against A give the sun's s_x/s_z and s_y/s_z,
    which predict D (0.3, 0.3) and E (−0.3, 0); of F (50, 0) and G (−50, 0), nearly upright,
    the one whose normal faces away from the sun gets no sunlight (its geometry is lit)."""
    f = np.fromfile(out / "frame.img", dtype="<f8").reshape(6, 8)
    a, b, c, d = (f[:3, 2 * i:2 * i + 2].mean() for i in range(4))
    e, f_, g, h = (f[3:, 2 * i:2 * i + 2].mean() for i in range(4))
    k = 0.3
    r = lambda quad, tilt: quad / a * np.sqrt(1 + tilt)
    rb, rc, rd, re_ = r(b, k * k), r(c, k * k), r(d, 2 * k * k), r(e, k * k)
    # Sun-disc sampling spreads a pixel by ~10^-4: 10^-3 relative.
    assert abs(h / a - 1) < 1e-3, h / a
    assert abs(rd - (rb + rc - 1)) < 1e-3, (rd, rb + rc - 1)
    assert abs(re_ - (2 - rb)) < 1e-3, (re_, 2 - rb)
    dark, lit = sorted((f_ / a, g / a))
    assert dark < 1e-20 and lit > 0.05, (f_ / a, g / a)  # thermal emission only: ~1e-29
    print(f"bump ok: D {rd:.5f} (predicted {rb + rc - 1:.5f}), E {re_:.5f} "
          f"(predicted {2 - rb:.5f}), the steep quad facing away {dark:.1e}")


def main():
    if sys.argv[1] == "bump":
        bump(Path(sys.argv[2]))
        return
    if sys.argv[1] == "uv":
        uv(Path(sys.argv[2]))
        return
    if sys.argv[1] == "thermal":
        thermal(Path(sys.argv[2]), int(sys.argv[3]))
        return
    if sys.argv[1] == "texture":
        texture(Path(sys.argv[2]))
        return
    out = Path(sys.argv[1])
    samples = int(sys.argv[2])
    pgm = (HERE / "maps" / "classes.pgm").read_bytes()
    classes = np.frombuffer(pgm[-24:], dtype=np.uint8).reshape(6, 4)
    cube = np.fromfile(HERE / "maps" / "fractions.img", dtype="<f4").reshape(6, 4, 2)
    dark = cube[..., 0] / cube.sum(axis=-1)  # the weight of material 11 (ρ 0.1)

    truth = np.fromfile(out / "truth.img", dtype="<f8").reshape(6, 8, 3)
    ids = [s.strip() for s in header(out / "truth.img.hdr")["glint material ids"].strip("{}").split(",")]
    material = np.vectorize(lambda i: ids[int(i)])(truth[..., 0])
    expected = np.vectorize(lambda dc: ID[dc])(classes)
    assert (material[:, :4] == expected).all(), (material, expected)
    assert (truth[:, :4, 1] == (classes == 10)).all() and (truth[:, :4, 2] == (classes == 50)).all()
    # Abundance of a mixed texel: its weights (float32 weights, summed in double).
    assert np.abs(truth[:, 4:, 1] - dark).max() < 1e-6, truth[:, 4:, 1] - dark
    assert np.abs(truth[:, 4:, 2] - (1 - dark)).max() < 1e-6

    radiance = np.fromfile(out / "frame.img", dtype="<f8").reshape(6, 8)
    rho_pure = np.vectorize(RHO.get)(classes)
    k = radiance[:, :4] / rho_pure  # radiance per unit reflectance: the same everywhere
    # Pure pixels: only the sun's direction within its disc varies, 1e-3 relative.
    assert k.std() / k.mean() < 1e-3, k
    k = k.mean()
    mean = dark * 0.1 + (1 - dark) * 0.5
    pure = (dark == 0) | (dark == 1)
    variance = np.clip(dark * 0.01 + (1 - dark) * 0.25 - mean**2, 1e-12, None)
    z = (radiance[:, 4:] / k - mean) / np.sqrt(variance / samples)
    assert (np.abs(z[~pure]) < 5).all(), z
    assert np.allclose(radiance[:, 4:][pure] / k, mean[pure], rtol=1e-3)
    print(f"maps ok: max |z| {np.abs(z[~pure]).max():.2f} over {(~pure).sum()} mixed pixels")


if __name__ == "__main__":
    main()
