#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks the outputs of `make demo` (examples/demo/run.sh BIN OUT).

1. Every output run.sh announces exists and is not empty: the .jsim, the platform dump, the
   schedule, 25 RGB frames (ENVI + PNG), the pushbroom image (ENVI + PNG), the video (25
   frames of 160 x 120, counted by ffprobe when it is installed).
2. The images are not trivial: the first RGB frame and the pushbroom image, read with
   Spectral Python, have the shape the schedule promises, no NaN or infinity, and a
   standard deviation > 0 in every band; every PNG (read with GDAL) varies.
3. The calibration panels (five spectrally flat greys, 0.03 to 0.80, in
   examples/demo/sim/demo_scene.yaml) are found without any pixel coordinates written down:
   every pixel centre is projected onto the panels' top plane through the pinhole camera of
   docs/camera.md §2 (focal length, pitch, offsets from demo.platform.json) at the capture's
   instrument pose (demo.schedule.json), and the pixels that land inside a panel shrunk by
   0.5 m (two ground pixels, so edge pixels and adjacent light stay out) are that panel's.
   In the first RGB frame and in the pushbroom image (all lines, each at its own pose) the
   panels' mean signal must increase strictly with reflectance in every band, and be linear
   in it (r² of a straight-line fit ≥ 0.999): the at-sensor signal is a + b ρ for a
   Lambertian panel (path radiance plus reflected sun and sky).
4. Vegetation shows its red edge: in the pushbroom image, grass pixels west of the pad have
   NIR > 2 × red.
5. The Bayer camera's digital counts (in-render detection): two uint16 mosaics whose values
   are whole counts in [0, 4095] (`data units = DN`), and in each colour filter's pixels the
   panels' mean counts increase with reflectance and are linear in it (r² ≥ 0.999: counts are
   linear in electrons below full well; shot and read noise average out over a panel); the
   demosaiced PNGs are 160 x 120 RGB and vary.
6. Truth (docs/truth.md): 25 truth cubes beside the RGB frames with the bands the platform's
   collection asks for; in frame 0 every pixel well inside a calibration panel has that
   panel's material index (the header's `glint material ids`) and no car abundance; the
   parked cars' centres are fully car (abundance 1); sample counts are whole numbers within
   the convergence settings (8 to 64) and above the minimum somewhere (edges); the standard
   errors are finite and >= 0; the material map PNG of frame 10 varies.

Usage: check_demo.py --out OUT --scene examples/demo/sim/demo_scene.yaml
Exit status: 0 pass, 1 fail, 77 skipped (numpy, GDAL or Spectral Python missing).
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

SKIP = 77

try:
    import numpy as np
    from osgeo import gdal
    import spectral.io.envi as envi
except ImportError as error:  # the oracle is not installed: skip, do not fail
    print(f"skipped: cannot import {error.name} (install python3-numpy, python3-gdal and "
          "python3-spectral for this test)")
    sys.exit(SKIP)

FRAMES = 25                 # 4 s at 6 Hz, both ends included
BAYER_FRAMES = 2            # 0.5 Hz from 1 s
PANEL_MARGIN_M = 0.5        # panel shrunk by this on every side
MIN_PANEL_PIXELS = 16
MIN_R2 = 0.999
MIN_NIR_OVER_RED = 2.0
GRASS_BOX_M = (-30.0, -25.0, -16.0, -20.0)  # x0, y0, x1, y1: grass only (demo_scene.yaml)

TRUTH_BANDS = ["Material Index", "Tag Abundance 'car'", "Sample Count",
               "Standard Error 'Red'", "Standard Error 'Green'", "Standard Error 'Blue'"]
TRUTH_MAP_PNG = "rgb_truth-t0000-c0010-material.png"

failures = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)
    return condition


def read_panels(scene_file):
    """(reflectance, lower, upper) of every `panel_NN` box, NN = reflectance in percent."""
    pattern = re.compile(r"name: panel_(\d+), primitive: box, material: panel_\d+, "
                         r"lower: \[([^\]]+)\], upper: \[([^\]]+)\]")
    panels = []
    with open(scene_file, encoding="utf-8") as f:
        for line in f:
            m = pattern.search(line)
            if m:
                lower = [float(v) for v in m.group(2).split(",")]
                upper = [float(v) for v in m.group(3).split(",")]
                panels.append((int(m.group(1)) / 100.0, lower, upper))
    return sorted(panels)


def rotation(wxyz):
    w, x, y, z = wxyz
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def ground_points(instrument, pose, z_m, focal_plane=0):
    """Scene x, y where each pixel centre's ray meets the plane z = z_m: (lines, samples, 2)."""
    fp = instrument["focal_planes"][focal_plane]
    array = fp["detector_array"]
    props = instrument["properties"]
    assert not array["x_flip"] and not array["y_flip"], "flipped arrays are not handled here"
    assert not any(props["distortion"].values()), "lens distortion is not handled here"
    n, m = array["x_count"], array["y_count"]
    f = props["focal_length_m"]
    cols = (np.arange(n) + 0.5 - n / 2) * array["x_spacing_m"] + array["x_offset_m"]
    rows = -(np.arange(m) + 0.5 - m / 2) * array["y_spacing_m"] + array["y_offset_m"]
    x, y = np.meshgrid(cols, rows)
    d = np.stack([x, y, np.full_like(x, -f)], axis=-1) @ rotation(
        pose["orientation_wxyz"]).T
    boresight = rotation(pose["orientation_wxyz"]) @ np.array([0.0, 0.0, -1.0])
    assert np.allclose(boresight, pose["boresight_enu"], atol=1e-9), "orientation convention"
    origin = np.array(pose["position_enu_m"])
    t = (z_m - origin[2]) / d[..., 2]
    return origin[:2] + t[..., None] * d[..., :2]


def inside(points, x0, y0, x1, y1):
    return ((points[..., 0] > x0) & (points[..., 0] < x1) &
            (points[..., 1] > y0) & (points[..., 1] < y1))


def read_envi(path):
    return np.asarray(envi.open(path + ".hdr", path).load(), dtype=np.float64)


def check_image(name, data, lines, samples, bands):
    check(data.shape == (lines, samples, bands),
          f"{name}: shape {data.shape} is (lines, samples, bands) = {(lines, samples, bands)}")
    check(bool(np.all(np.isfinite(data))), f"{name}: no NaN or infinity")
    stds = data.reshape(-1, data.shape[-1]).std(axis=0)
    check(bool(np.all(stds > 0)),
          f"{name}: every band varies (std {', '.join(f'{s:.3g}' for s in stds)})")


def check_panels(name, data, points_per_line, panels):
    """points_per_line: ground points, same (lines, samples) as data."""
    means = []
    for reflectance, lower, upper in panels:
        mask = inside(points_per_line, lower[0] + PANEL_MARGIN_M, lower[1] + PANEL_MARGIN_M,
                      upper[0] - PANEL_MARGIN_M, upper[1] - PANEL_MARGIN_M)
        count = int(mask.sum())
        if not check(count >= MIN_PANEL_PIXELS,
                     f"{name}: panel {reflectance:.2f} covers {count} pixels "
                     f"(>= {MIN_PANEL_PIXELS})"):
            return
        means.append(data[mask].mean(axis=0))
    means = np.array(means)  # (panels, bands)
    rho = np.array([p[0] for p in panels])
    for b in range(means.shape[1]):
        column = means[:, b]
        check(bool(np.all(np.diff(column) > 0)),
              f"{name} band {b}: panel means increase with reflectance "
              f"({', '.join(f'{v:.4g}' for v in column)})")
        slope, intercept = np.polyfit(rho, column, 1)
        residual = column - (intercept + slope * rho)
        r2 = 1 - residual.var() / column.var()
        check(r2 >= MIN_R2 and slope > 0,
              f"{name} band {b}: linear in reflectance, r2 = {r2:.6f} (>= {MIN_R2}), "
              f"offset/slope = {intercept / slope:.4f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="the OUT_DIR given to run.sh")
    parser.add_argument("--scene", required=True, help="examples/demo/sim/demo_scene.yaml")
    args = parser.parse_args()
    out = args.out
    render = os.path.join(out, "render")

    # 1. the files
    frames = [os.path.join(render, f"rgb-t0000-c{c:04d}") for c in range(FRAMES)]
    expected = ["demo.jsim", "demo.platform.json", "demo.schedule.json", "render/demo.mp4",
                "render/msi.img", "render/msi.img.hdr", "render/msi-false-colour.png"]
    expected += [os.path.relpath(f + ext, out) for f in frames
                 for ext in (".img", ".img.hdr", ".png")]
    bayers = [os.path.join(render, f"bayer-t0000-c{c:04d}") for c in range(BAYER_FRAMES)]
    expected += [os.path.relpath(f + ext, out) for f in bayers
                 for ext in (".img", ".img.hdr", ".png")]
    truths = [os.path.join(render, f"rgb_truth-t0000-c{c:04d}") for c in range(FRAMES)]
    expected += [os.path.relpath(f + ext, out) for f in truths for ext in (".img", ".img.hdr")]
    expected += ["render/" + TRUTH_MAP_PNG]
    missing = [e for e in expected
               if not os.path.isfile(os.path.join(out, e)) or
               os.path.getsize(os.path.join(out, e)) == 0]
    check(not missing, f"{len(expected)} outputs exist and are not empty"
          + (f" (missing or empty: {', '.join(missing)})" if missing else ""))
    if missing:
        return 1
    video = os.path.join(render, "demo.mp4")
    if shutil.which("ffprobe"):
        probe = subprocess.run(
            ["ffprobe", "-v", "error", "-select_streams", "v:0", "-count_frames",
             "-show_entries", "stream=nb_read_frames,width,height", "-of", "json", video],
            capture_output=True, text=True, check=False)
        stream = (json.loads(probe.stdout or "{}").get("streams") or [{}])[0]
        check(stream.get("nb_read_frames") == str(FRAMES) and stream.get("width") == 160,
              f"demo.mp4 (ffprobe): {stream}, expected {FRAMES} frames of 160 x 120")
    else:
        print("note: no ffprobe, demo.mp4 only checked for existence")
    extra = sorted(set(os.listdir(render)) - {os.path.basename(e) for e in expected}
                   - {"render.log", "files.txt", "msi.info.txt", "msi.stats.txt",
                      "rgb-t0000-c0000.stats.json"})
    check(not extra, "no unexpected files in render/" + (f": {extra}" if extra else ""))

    with open(os.path.join(out, "demo.platform.json"), encoding="utf-8") as f:
        platform = json.load(f)
    with open(os.path.join(out, "demo.schedule.json"), encoding="utf-8") as f:
        schedule = json.load(f)
    instruments = {i["name"]: i for i in platform["instruments"]}
    captures = schedule["captures"]
    rgb = [c for c in captures if c["focal_plane"]["name"] == "RGB"]
    msi = sorted((c for c in captures if c["focal_plane"]["name"] == "MSI"),
                 key=lambda c: c["capture_index"])
    check(len(rgb) == FRAMES, f"the schedule has {len(rgb)} RGB captures ({FRAMES})")

    # 2. non-trivial images
    frame0 = read_envi(frames[0] + ".img")
    check_image("rgb frame 0", frame0, 120, 160, 3)
    pushbroom = read_envi(os.path.join(render, "msi.img"))
    check_image("msi", pushbroom, len(msi), 256, 5)
    pngs = ([f + ".png" for f in frames + bayers] +
            [os.path.join(render, "msi-false-colour.png")])
    flat = [os.path.relpath(png, out) for png in pngs
            if (pixels := gdal.Open(png).ReadAsArray()) is None or not pixels.std() > 0]
    check(not flat, f"{len(pngs)} PNGs read with GDAL vary" + (f" (flat: {flat})" if flat else ""))
    if failures:
        return 1

    # 3. the calibration panels
    panels = read_panels(args.scene)
    check([p[0] for p in panels] == [0.03, 0.12, 0.25, 0.5, 0.8],
          f"five panels read from {os.path.basename(args.scene)}: "
          f"{[p[0] for p in panels]}")
    top_m = panels[0][2][2]
    first = next(c for c in rgb if c["files"]["image"] == "rgb-t0000-c0000.img")
    points = ground_points(instruments["Camera"], first["pose"]["instrument"], top_m)
    check_panels("rgb frame 0", frame0, points, panels)
    lines = np.concatenate([ground_points(instruments["Pushbroom"], c["pose"]["instrument"],
                                          top_m) for c in msi])
    check_panels("msi", pushbroom, lines, panels)

    # 4. the red edge of grass
    grass = inside(ground_points_plane(instruments, msi), *GRASS_BOX_M)
    names = [b["name"] for b in platform["instruments"][1]["focal_planes"][0]
             ["spectral_response"]["channels"]]
    red, nir = pushbroom[grass][:, names.index("Red")], pushbroom[grass][:, names.index("NIR")]
    check(grass.sum() >= MIN_PANEL_PIXELS and nir.mean() > MIN_NIR_OVER_RED * red.mean(),
          f"msi grass ({int(grass.sum())} pixels): NIR/red = {nir.mean() / red.mean():.2f} "
          f"(> {MIN_NIR_OVER_RED})")

    # 5. the Bayer camera's digital counts
    check_bayer(out, render, instruments, captures, panels, top_m)

    # 6. truth
    check_truth(render, [t + ".img" for t in truths], points, panels, instruments["Camera"],
                rgb)

    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


def check_truth(render, paths, points, panels, camera, rgb):
    path = paths[0]
    header = envi.open(path + ".hdr", path).metadata
    check(header["band names"] == TRUTH_BANDS,
          f"truth band names {header['band names']} (expected {TRUTH_BANDS})")
    truth = read_envi(path)
    check(truth.shape == (120, 160, len(TRUTH_BANDS)), f"truth cube shape {truth.shape}")
    material, car, samples, errors = truth[..., 0], truth[..., 1], truth[..., 2], truth[..., 3:]
    ids = [i.strip() for i in header["glint material ids"]]
    for reflectance, lower, upper in panels:
        box = (lower[0] + PANEL_MARGIN_M, lower[1] + PANEL_MARGIN_M,
               upper[0] - PANEL_MARGIN_M, upper[1] - PANEL_MARGIN_M)
        mask = inside(points, *box)
        name = f"panel_{round(reflectance * 100):02d}"
        check(mask.sum() >= MIN_PANEL_PIXELS and bool(np.all(material[mask] == ids.index(name)))
              and bool(np.all(car[mask] == 0)),
              f"truth: {int(mask.sum())} pixels inside {name} have its material index "
              f"{ids.index(name)} and no car")
    # The first frame that sees parked_1 (centre -11, 16; roof about 1.4 m up).
    for path, capture in zip(paths, sorted(rgb, key=lambda c: c["capture_index"])):
        centres = inside(ground_points(camera, capture["pose"]["instrument"], 1.4),
                         -11.2, 15.8, -10.8, 16.2)
        if centres.any():
            cars = read_envi(path)[..., 1][centres]
            break
    check(centres.any() and bool(np.all(cars == 1.0)),
          f"truth: the pixels at parked_1's centre are fully car "
          f"({os.path.basename(path)}: {cars if centres.any() else 'not seen'})")
    check(bool(np.all(samples == np.round(samples))) and samples.min() >= 8 and
          samples.max() <= 64 and samples.max() > 8,
          f"truth: sample counts whole, within 8..64, above 8 somewhere "
          f"({samples.min():.0f}..{samples.max():.0f})")
    check(bool(np.all(np.isfinite(errors))) and errors.min() >= 0,
          "truth: standard errors finite and >= 0")
    png = gdal.Open(os.path.join(render, TRUTH_MAP_PNG)).ReadAsArray()
    check(png is not None and png.shape == (3, 120, 160) and png.std() > 0,
          f"{TRUTH_MAP_PNG}: a 160 x 120 colour map that varies")


def check_bayer(out, render, instruments, captures, panels, top_m):
    camera = instruments["Camera"]
    index = [fp["name"] for fp in camera["focal_planes"]].index("Bayer")
    first = next(c for c in captures if c["files"]["image"] == "bayer-t0000-c0000.img")
    path = os.path.join(render, "bayer-t0000-c0000.img")
    with open(path + ".hdr", encoding="utf-8") as f:
        header = f.read()
    check("data units = DN" in header and "data type = 12" in header and "bands = 1" in header,
          "bayer frame 0: one band of uint16 digital counts (data units = DN)")
    counts = read_envi(path)[..., 0]
    check(counts.shape == (120, 160) and bool(np.all(counts == np.round(counts))) and
          counts.min() >= 0 and counts.max() <= 4095,
          f"bayer frame 0: 160 x 120 whole counts in [0, 4095] "
          f"(min {counts.min():.0f}, max {counts.max():.0f})")
    points = ground_points(camera, first["pose"]["instrument"], top_m, index)
    rows, cols = np.indices(counts.shape)
    # RGGB (docs/detector.md): red at even line and sample, blue at odd ones, green elsewhere.
    filters = {"red": (rows % 2 == 0) & (cols % 2 == 0), "blue": (rows % 2 == 1) & (cols % 2 == 1)}
    filters["green"] = ~(filters["red"] | filters["blue"])
    for name, where in filters.items():
        means = []
        for reflectance, lower, upper in panels:
            mask = where & inside(points, lower[0] + PANEL_MARGIN_M, lower[1] + PANEL_MARGIN_M,
                                  upper[0] - PANEL_MARGIN_M, upper[1] - PANEL_MARGIN_M)
            means.append(counts[mask].mean() if mask.sum() >= 4 else np.nan)
        means = np.array(means)
        rho = np.array([p[0] for p in panels])
        ok = bool(np.all(np.isfinite(means)) and np.all(np.diff(means) > 0))
        r2 = 0.0
        if ok:
            slope, intercept = np.polyfit(rho, means, 1)
            r2 = 1 - (means - (intercept + slope * rho)).var() / means.var()
        check(ok and r2 >= MIN_R2,
              f"bayer frame 0, {name} pixels: panel counts increase and are linear in "
              f"reflectance ({', '.join(f'{v:.0f}' for v in means)} DN, r2 = {r2:.6f})")
    for c in range(BAYER_FRAMES):
        png = gdal.Open(os.path.join(render, f"bayer-t0000-c{c:04d}.png")).ReadAsArray()
        check(png is not None and png.shape == (3, 120, 160) and png.std() > 0,
              f"bayer frame {c} demosaiced: PNG {None if png is None else png.shape}")


def ground_points_plane(instruments, msi):
    """The pushbroom's ground points on z = 0 (grass), one line per capture."""
    return np.concatenate([ground_points(instruments["Pushbroom"], c["pose"]["instrument"],
                                         0.0) for c in msi])


if __name__ == "__main__":
    sys.exit(main())
