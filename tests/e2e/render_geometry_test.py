#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""End-to-end: a ground target at a known position appears at the predicted pixel.

A dark ground plane (ρ = 0.02) carries small bright thin boxes (ρ = 0.9, 1 cm high) at known
scene positions, in "sites" of two targets each: a 1 m × 1 m square A north-east of the site
centre and a 1.4 m (east) × 0.6 m (north) bar B south-west of it, so that a mirror, a
transposition or a rotation of the image moves or turns them visibly. The exo-atmospheric sun
is ~20° from the zenith (YAML atmosphere `model: none`: black sky, no path effects).

glint-render runs twice (f = 100 mm, pitch 20 µm, height ≈ 1000 m: GSD ≈ 0.2 m):

- `level`: a level vehicle at (0, 0, 1000) flying north (+Y), identity attitude. One
  identity-mounted instrument carries focal planes for the nadir view with odd (51 × 41) and
  even (50 × 40) pixel counts, xflipaxis, yflipaxis, an array offset, and both flips with an
  offset; a second instrument sits on a static mount (12°, −9°, 35°, order zyx) and looks
  15° off nadir.
- `attitude`: the vehicle pitched 8°, rolled −11° and yawed 27° (GenericMotion Euler angles,
  order xyz), placed so that its boresight (13.6° off nadir) hits the origin; an
  identity-mounted instrument (plain, and yflip + offset) and an instrument on the same static
  mount as above (vehicle and mount rotations composed, 28° off nadir).

The pixel of each target is predicted here independently of glint, from the documented
conventions only: Euler matrices written from docs/motion.md §3 (active, right-handed,
extrinsic, first-applied on the right; the DIRSIG triple is (pitch, roll, yaw) = angles about
(X, Y, Z)), instrument → scene = vehicle · mount (docs/motion.md "The attachment chain"), the
pinhole (x, y) = f (d_x, d_y)/(−d_z) in the instrument frame (boresight −Z), and the pixel
layout of docs/camera.md §2 inverted: column i, row j centred at
x = (i + ½ − N/2) p + x_off, y = −(j + ½ − M/2) p + y_off, a flip mirroring x − x_off (or
y − y_off). The target's image is found in glint's ENVI product (parsed here, BIP float64) as
a connected component above a threshold, and its centroid weighted by the radiance above the
background must lie within 0.25 px of the predicted pixel (why 0.25: see CENTROID_TOLERANCE_PX);
bar B's long axis must point where the projection of its ends says. The number of targets
found in each image must equal the number predicted in it (none from another site). For the
level vehicle flying north the test also asserts the "top line forward" convention: a target
north of nadir is in a smaller row index than the nadir row, one east of it in a larger
column.

Usage: render_geometry_test.py --bin BUILD/bin --data SOURCE/data --work DIR [--seed S]
Exit status: 0 pass, 1 fail, 77 skipped (numpy is missing).
"""
import argparse
import itertools
import math
import os
import shutil
import subprocess
import sys

import dirsig_inputs

SKIP = 77

try:
    import numpy as np
except ImportError as error:  # the oracle is not installed: skip, do not fail
    print(f"skipped: cannot import {error.name} (install python3-numpy for this test)")
    sys.exit(SKIP)

# --- the scene, the sun and the sensor ---------------------------------------------------------

LATITUDE_DEG, LONGITUDE_DEG = 43.0, -77.6
UTC = "2020-06-21T17:10:00"       # local solar noon ≈ 17:12 UTC: sun ≈ 20° from the zenith
GROUND_REFLECTANCE = 0.02
TARGET_REFLECTANCE = 0.9
TARGET_HEIGHT_M = 0.01             # thin boxes: the top face is what the camera sees
HEIGHT_M = 1000.0
FOCAL_LENGTH_MM = 100.0
PITCH_UM = 20.0                    # GSD at nadir = 1000 m × 20 µm / 100 mm = 0.2 m
CONVERGENCE = "16,16,0"            # threshold 0: every pixel takes exactly 16 samples

# The targets of a site: (name, east offset, north offset, east size, north size), metres from
# the site centre. The offsets are not multiples of the GSD, so the targets sit at fractional
# pixel positions and cover their edge pixels partly.
TARGETS = [
    ("A", 1.87, 1.13, 1.0, 1.0),
    ("B", -1.43, -0.87, 1.4, 0.6),
]

# Why 0.25 px: the centroid is Σ w·c / Σ w with w = radiance above the background, i.e. the
# covered fraction of each pixel. Interior pixels are fully covered (w exact up to the sun-disk
# jitter, ≤ 0.2 %); an edge pixel's fraction is estimated from 16 uniform samples of its area,
# a binomial with σ ≤ √(¼/16) = 0.125. With Σ w ≈ 25 px (a 1 m² target at 0.2 m) and ≈ 12
# partly covered edge pixels about 2.5–3 px from the centre along each axis, σ(centroid) ≈
# √(12 × 0.125² × 3²)/25 ≈ 0.05 px: 0.25 px is 5 σ, while any convention error (a sign, a flip,
# the offset, a half-pixel shift, the Euler order) moves a target by ≥ 0.5 px, mostly by many.
# Measured over seeds 1-16 (20 targets each): σ 0.045 px in columns, 0.036 px in rows, mean
# error within 0.003 px of 0, largest distance 0.16 px.
CENTROID_TOLERANCE_PX = 0.25
ORIENTATION_TOLERANCE_DEG = 10.0   # bar B: 7 × 3 px, principal axis from the weighted moments
EDGE_MARGIN_PX = 3.0               # a predicted target must be this far inside its image


# --- rotations, written from docs/motion.md ----------------------------------------------------

def rot_x(deg):
    """Active right-handed rotation about X (takes +Y towards +Z)."""
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def rot_y(deg):
    """Active right-handed rotation about Y (takes +Z towards +X)."""
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def rot_z(deg):
    """Active right-handed rotation about Z (takes +X towards +Y)."""
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def euler(triple_deg, order):
    """docs/motion.md §3: the triple holds the angles about (X, Y, Z); `order` lists the axes in
    the order the (extrinsic, active) rotations are applied, the first-applied matrix on the
    right: xyz → Rz · Ry · Rx. Maps body vectors to parent vectors."""
    by_axis = {"x": rot_x(triple_deg[0]), "y": rot_y(triple_deg[1]), "z": rot_z(triple_deg[2])}
    matrix = np.eye(3)
    for axis in order:
        matrix = by_axis[axis] @ matrix
    return matrix


# --- the runs and the cases --------------------------------------------------------------------

MOUNT = {"angles_deg": (12.0, -9.0, 35.0), "order": "zyx"}
VEHICLE_ATTITUDE_DEG = (8.0, -11.0, 27.0)   # (pitch, roll, yaw): the .ppd's <cartesiantriple>
VEHICLE_ORDER = "xyz"


def vehicle_rotation(run):
    return euler(run["attitude_deg"], VEHICLE_ORDER)


def instrument_rotation(run, mounted):
    """Instrument → scene ENU: V · M (identity attachments; docs/motion.md §2 of the chain)."""
    rotation = vehicle_rotation(run)
    if mounted:
        rotation = rotation @ euler(MOUNT["angles_deg"], MOUNT["order"])
    return rotation


def boresight_ground_hit(position, rotation):
    """Where the instrument's −Z axis meets the ground z = 0."""
    boresight = rotation @ np.array([0.0, 0.0, -1.0])
    assert boresight[2] < 0.0, "test design: boresight does not look down"
    return position + (position[2] / -boresight[2]) * boresight


def make_runs():
    """The two runs, their vehicle positions and their sites (where each boresight meets the
    ground, rounded to 0.1 m: the target sites are placed there)."""
    level = {"name": "level", "attitude_deg": (0.0, 0.0, 0.0),
             "position": np.array([0.0, 0.0, HEIGHT_M])}
    attitude = {"name": "attitude", "attitude_deg": VEHICLE_ATTITUDE_DEG}
    # Place the rolled vehicle so that its identity-mounted boresight hits the origin.
    hit = boresight_ground_hit(np.array([0.0, 0.0, HEIGHT_M]), vehicle_rotation(attitude))
    attitude["position"] = np.array([-hit[0], -hit[1], HEIGHT_M])
    runs = [level, attitude]
    sites = [np.zeros(3)]
    for run in runs:
        hit = boresight_ground_hit(run["position"], instrument_rotation(run, mounted=True))
        sites.append(np.array([round(hit[0], 1), round(hit[1], 1), 0.0]))
    for a in range(len(sites)):
        for b in range(a):
            assert np.linalg.norm(sites[a] - sites[b]) > 50.0, "test design: sites overlap"
    return runs, sites


# Focal planes: (name, run, mounted, columns, rows, xflip, yflip, xoffset µm, yoffset µm).
CASES = [
    ("nadir_odd", "level", False, 51, 41, False, False, 0.0, 0.0),
    ("nadir_even", "level", False, 50, 40, False, False, 0.0, 0.0),
    ("flip_x", "level", False, 51, 41, True, False, 0.0, 0.0),
    ("flip_y", "level", False, 50, 40, False, True, 0.0, 0.0),
    ("offset", "level", False, 51, 40, False, False, 130.0, -70.0),
    ("flip_xy_offset", "level", False, 50, 41, True, True, 130.0, -70.0),
    ("mount", "level", True, 51, 41, False, False, 0.0, 0.0),
    ("attitude", "attitude", False, 51, 41, False, False, 0.0, 0.0),
    ("attitude_flip_y_offset", "attitude", False, 50, 40, False, True, -90.0, 50.0),
    ("attitude_mount", "attitude", True, 51, 41, False, False, 0.0, 0.0),
]


# --- the prediction ----------------------------------------------------------------------------

def pixel_of(point, position, rotation, case):
    """(column, row) as continuous pixel indices (pixel i's centre at i) of a scene point, or
    None behind the camera: pinhole in the instrument frame, then docs/camera.md §2 inverted."""
    _, _, _, columns, rows, x_flip, y_flip, x_off_um, y_off_um = case
    d = rotation.T @ (point - position)          # scene → instrument (passive: Rᵀ)
    if d[2] >= 0.0:
        return None
    f = FOCAL_LENGTH_MM * 1e-3
    pitch = PITCH_UM * 1e-6
    x = f * d[0] / -d[2]
    y = f * d[1] / -d[2]
    # x = ±(i + ½ − N/2) p + x_off (− with xflipaxis); y = ±(−(j + ½ − M/2) p) + y_off.
    rel_x = (x - x_off_um * 1e-6) * (-1.0 if x_flip else 1.0)
    rel_y = (y - y_off_um * 1e-6) * (-1.0 if y_flip else 1.0)
    return np.array([rel_x / pitch + columns / 2.0 - 0.5, -rel_y / pitch + rows / 2.0 - 0.5])


def predict(case, run, sites):
    """The targets of every site that fall in this image: name → (centre pixel, bar direction
    in the image as (Δcolumn, Δrow) or None, extent in pixels)."""
    name, _, mounted, columns, rows = case[:5]
    rotation = instrument_rotation(run, mounted)
    position = run["position"]
    predicted = {}
    for s, site in enumerate(sites):
        for target, east, north, size_e, size_n in TARGETS:
            top = np.array([site[0] + east, site[1] + north, TARGET_HEIGHT_M])
            centre = pixel_of(top, position, rotation, case)
            corners = [pixel_of(top + np.array([a * size_e / 2, b * size_n / 2, 0.0]),
                                position, rotation, case) for a in (-1, 1) for b in (-1, 1)]
            if centre is None or any(c is None for c in corners):
                continue
            corners = np.array(corners)
            low, high = corners.min(axis=0), corners.max(axis=0)
            # A target whose footprint touches the image must lie well inside it, else its
            # centroid would be cut: that would be a mistake of this test, not of glint.
            if high[0] < -0.5 or high[1] < -0.5 or low[0] > columns - 0.5 or low[1] > rows - 0.5:
                continue
            inside = (low[0] >= EDGE_MARGIN_PX - 0.5 and low[1] >= EDGE_MARGIN_PX - 0.5 and
                      high[0] <= columns - 0.5 - EDGE_MARGIN_PX and
                      high[1] <= rows - 0.5 - EDGE_MARGIN_PX)
            assert inside, (f"test design: {name}: site {s} target {target} at pixel {centre} "
                            f"is not {EDGE_MARGIN_PX} px inside the {columns} × {rows} image")
            ends = [pixel_of(top + np.array([a * size_e / 2, 0.0, 0.0]), position, rotation, case)
                    for a in (-1, 1)]
            axis = ends[1] - ends[0] if size_e != size_n else None
            predicted[f"site{s}/{target}"] = (centre, axis)
    return predicted


# --- inputs ------------------------------------------------------------------------------------

def scene_yaml(sites):
    lines = [
        "# Dark ground, bright thin boxes at known positions (render_geometry_test.py).",
        f"origin: {{latitude: {LATITUDE_DEG}, longitude: {LONGITUDE_DEG}, altitude: 0}}",
        "materials:",
        "  - id: ground",
        f"    reflectance: {{wavelengths: [0.3, 1.0], values: [{GROUND_REFLECTANCE}, "
        f"{GROUND_REFLECTANCE}]}}",
        "  - id: target",
        f"    reflectance: {{wavelengths: [0.3, 1.0], values: [{TARGET_REFLECTANCE}, "
        f"{TARGET_REFLECTANCE}]}}",
        "objects:",
        "  - {name: ground, primitive: ground_plane, material: ground, size: 100000}",
    ]
    for s, site in enumerate(sites):
        for target, east, north, size_e, size_n in TARGETS:
            x, y = site[0] + east, site[1] + north
            lines.append(
                f"  - {{name: site{s}_{target}, primitive: box, material: target, "
                f"lower: [{x - size_e / 2:.6f}, {y - size_n / 2:.6f}, 0], "
                f"upper: [{x + size_e / 2:.6f}, {y + size_n / 2:.6f}, {TARGET_HEIGHT_M}]}}")
    return "\n".join(lines) + "\n"


ATMOSPHERE_YAML = "# Exo-atmospheric sun, black sky, no path effects.\nmodel: none\n"


def ppd(run):
    """Two entries 10 s apart; the capture is at t = 0, the first entry's pose. The level
    vehicle flies north (+Y) at 10 m/s; the rolled one hovers."""
    entries = []
    for t in (0, 10):
        p = run["position"] + (np.array([0.0, 10.0 * t, 0.0]) if run["name"] == "level" else 0.0)
        entries.append((t, p, run["attitude_deg"]))
    return dirsig_inputs.ppd(entries, VEHICLE_ORDER)


TASKS = dirsig_inputs.snapshot_tasks(UTC)


def sim(run_name):
    return dirsig_inputs.sim("targets.yaml", f"{run_name}.platform", f"{run_name}.ppd")


def focal_plane_xml(case):
    name, _, _, columns, rows, x_flip, y_flip, x_off_um, y_off_um = case
    return f"""\
      <focalplane enabled="true" name="{name}">
        <capturemethod type="simple" name="Simple">
          <imagefile areaunits="cm2" fluxunits="watts">
            <basename>{name}</basename><extension>img</extension>
            <schedule>simulation</schedule><datatype>5</datatype>
          </imagefile>
          <spectralresponse>
            <bandpass spectralunits="microns">
              <minimum>0.5</minimum><maximum>0.6</maximum><delta>0.01</delta>
            </bandpass>
            <channellist>
              <channel name="Green" shape="gaussian" normalize="false">
                <center>0.55</center><width>0.04</width>
              </channel>
            </channellist>
          </spectralresponse>
          <temporalintegration tdi="false"><time>0</time></temporalintegration>
        </capturemethod>
        <detectorarray spatialunits="microns">
          <clock type="independent" temporalunits="hertz"><rate>1</rate><offset>0</offset></clock>
          <xelementcount>{columns}</xelementcount><yelementcount>{rows}</yelementcount>
          <xelementsize>{PITCH_UM}</xelementsize><yelementsize>{PITCH_UM}</yelementsize>
          <xelementspacing>{PITCH_UM}</xelementspacing><yelementspacing>{PITCH_UM}</yelementspacing>
          <xarrayoffset>{x_off_um}</xarrayoffset><yarrayoffset>{y_off_um}</yarrayoffset>
          <xflipaxis>{int(x_flip)}</xflipaxis><yflipaxis>{int(y_flip)}</yflipaxis>
        </detectorarray>
      </focalplane>
"""


def instrument_xml(name, cases):
    planes = "".join(focal_plane_xml(c) for c in cases)
    return f"""\
    <instrument name="{name}" type="generic">
      <properties><focallength>{FOCAL_LENGTH_MM}</focallength></properties>
{planes}    </instrument>
"""


def platform_xml(run_name):
    """An identity-mounted instrument and one on the static mount, each carrying the focal
    planes of this run's cases."""
    body = [c for c in CASES if c[1] == run_name and not c[2]]
    mounted = [c for c in CASES if c[1] == run_name and c[2]]
    x, y, z = MOUNT["angles_deg"]
    return f"""<platform>
  <clocktable/>
  <attachment>
    <affinetransform/>
{instrument_xml("Body", body)}  </attachment>
  <attachment>
    <affinetransform/>
    <mount name="Tilt" type="static">
      <data angularunits="degrees" rotationorder="{MOUNT['order']}">
        <xrotation>{x}</xrotation><yrotation>{y}</yrotation><zrotation>{z}</zrotation>
      </data>
      <attachment>
        <affinetransform/>
{instrument_xml("Mounted", mounted)}      </attachment>
    </mount>
  </attachment>
</platform>
"""


def write_inputs(folder, runs, sites):
    files = {"targets.yaml": scene_yaml(sites), "none.atm.yaml": ATMOSPHERE_YAML,
             "snapshot.tasks": TASKS}
    for run in runs:
        files[f"{run['name']}.platform"] = platform_xml(run["name"])
        files[f"{run['name']}.ppd"] = ppd(run)
        files[f"{run['name']}.sim"] = sim(run["name"])
    for name, text in files.items():
        with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
            f.write(text)


# --- reading the products ----------------------------------------------------------------------

def read_envi(img_path):
    """The first band of an ENVI pair as a lines × samples float64 array, from the header
    parsed here (single-line values; docs/formats.md "ENVI images")."""
    fields = {}
    with open(img_path + ".hdr", encoding="utf-8") as f:
        if f.readline().strip() != "ENVI":
            raise AssertionError(f"{img_path}.hdr: no ENVI magic")
        for line in f:
            if "=" in line:
                key, value = line.split("=", 1)
                fields[" ".join(key.split()).lower()] = value.strip()
    samples, lines, bands = (int(fields[k]) for k in ("samples", "lines", "bands"))
    if fields.get("data type") != "5" or fields.get("interleave", "bsq").lower() != "bip":
        raise AssertionError(f"{img_path}: data type {fields.get('data type')}, interleave "
                             f"{fields.get('interleave')}, expected 5 (float64) and bip")
    dtype = np.dtype(">f8" if fields.get("byte order") == "1" else "<f8")
    data = np.fromfile(img_path, dtype=dtype, offset=int(fields.get("header offset", "0")))
    if data.size != samples * lines * bands:
        raise AssertionError(f"{img_path}: {data.size} values, expected {samples} × {lines} × "
                             f"{bands}")
    return data.reshape(lines, samples, bands)[:, :, 0].astype(np.float64)


def components(mask):
    """Connected components (4-neighbour) of a boolean image, as lists of (row, column)."""
    seen = np.zeros_like(mask, dtype=bool)
    found = []
    for start in zip(*np.nonzero(mask)):
        if seen[start]:
            continue
        stack, pixels = [start], []
        seen[start] = True
        while stack:
            r, c = stack.pop()
            pixels.append((r, c))
            for rr, cc in ((r - 1, c), (r + 1, c), (r, c - 1), (r, c + 1)):
                if 0 <= rr < mask.shape[0] and 0 <= cc < mask.shape[1] and mask[rr, cc] \
                        and not seen[rr, cc]:
                    seen[rr, cc] = True
                    stack.append((rr, cc))
        found.append(pixels)
    return found


def measure(image):
    """The bright targets in an image: a list of (centroid (column, row), long-axis angle in
    degrees in the (column, row) plane, Σ weight in pixels). The background is the image
    median (the uniform dark ground); a target is a connected component above half-way from
    the background to the brightest pixel; its centroid is weighted by the radiance above the
    background over the component's bounding box grown by 2 px, so that the partly covered
    edge pixels below the threshold count with their covered fraction (a threshold cut alone
    would bias the centroid)."""
    background = float(np.median(image))
    peak = float(np.max(image))
    if not peak > 2.0 * background > 0.0:
        return background, peak, []
    weights = np.clip(image - background, 0.0, None) / (peak - background)
    found = []
    for pixels in components(image > background + 0.5 * (peak - background)):
        rows_, cols_ = zip(*pixels)
        r0, r1 = max(min(rows_) - 2, 0), min(max(rows_) + 3, image.shape[0])
        c0, c1 = max(min(cols_) - 2, 0), min(max(cols_) + 3, image.shape[1])
        w = weights[r0:r1, c0:c1]
        rr, cc = np.mgrid[r0:r1, c0:c1]
        total = float(w.sum())
        col, row = float((w * cc).sum() / total), float((w * rr).sum() / total)
        cov_cc = float((w * (cc - col) ** 2).sum() / total)
        cov_rr = float((w * (rr - row) ** 2).sum() / total)
        cov_cr = float((w * (cc - col) * (rr - row)).sum() / total)
        angle = 0.5 * math.degrees(math.atan2(2.0 * cov_cr, cov_cc - cov_rr))
        found.append((np.array([col, row]), angle, total))
    return background, peak, found


def match(predicted, found):
    """Pairs each predicted target with a different found one (as many as there are), the
    pairing with the smallest total distance: target name → (centroid, angle, weight)."""
    names = list(predicted)
    best, best_cost = {}, math.inf
    for chosen in itertools.permutations(range(len(found)), min(len(names), len(found))):
        cost = sum(float(np.linalg.norm(found[f][0] - predicted[n][0]))
                   for n, f in zip(names, chosen))
        if cost < best_cost:
            best, best_cost = {n: found[f] for n, f in zip(names, chosen)}, cost
    return best


def angle_difference_deg(a, b):
    """|a − b| for undirected axes (modulo 180°)."""
    d = (a - b) % 180.0
    return min(d, 180.0 - d)


# --- the test ----------------------------------------------------------------------------------

def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bin", required=True, help="folder of the built glint tools")
    parser.add_argument("--data", required=True, help="glint's data folder (solar spectrum)")
    parser.add_argument("--work", required=True, help="scratch folder (emptied first)")
    parser.add_argument("--seed", default="1", help="glint-render's --seed (default 1)")
    args = parser.parse_args()

    render = os.path.join(args.bin, "glint-render")
    if not os.access(render, os.X_OK):
        print(f"FAIL: {render} does not exist or is not executable (build glint-render first)")
        return 1
    shutil.rmtree(args.work, ignore_errors=True)
    inputs = os.path.join(args.work, "inputs")
    os.makedirs(inputs)
    runs, sites = make_runs()
    write_inputs(inputs, runs, sites)
    print("sites (scene ENU, m): " + ", ".join(f"site{s} ({p[0]:.1f}, {p[1]:.1f})"
                                               for s, p in enumerate(sites)))

    failures = []
    for run in runs:
        outputs = os.path.join(args.work, "out", run["name"])
        os.makedirs(outputs)
        command = [render, os.path.join(inputs, run["name"] + ".sim"), "--output-folder",
                   outputs, "--convergence", CONVERGENCE, "--threads", "2", "--seed", args.seed,
                   "--data-dir", args.data]
        print("running:", " ".join(command))
        done = subprocess.run(command, capture_output=True, text=True, timeout=240)
        if done.returncode != 0:
            print(f"FAIL: glint-render exited {done.returncode}\n--- stderr:\n{done.stderr}"
                  f"\n--- stdout:\n{done.stdout}")
            return 1

        for case in (c for c in CASES if c[1] == run["name"]):
            name, _, _, columns, rows = case[:5]
            img = os.path.join(outputs, name + ".img")
            if not (os.path.isfile(img) and os.path.isfile(img + ".hdr")):
                failures.append(f"{name}: {img} or its .hdr was not written")
                continue
            image = read_envi(img)
            if image.shape != (rows, columns):
                failures.append(f"{name}: image is {image.shape[1]} × {image.shape[0]}, "
                                f"expected {columns} × {rows}")
                continue
            predicted = predict(case, run, sites)
            background, peak, found = measure(image)
            print(f"{name} ({columns} × {rows}, background {background:.3e}, "
                  f"peak {peak:.3e}):")
            if not predicted:
                failures.append(f"{name}: test design: no target predicted in the image")
                continue
            if len(found) != len(predicted):
                failures.append(f"{name}: found {len(found)} targets at " +
                                str([f"({m[0][0]:.2f}, {m[0][1]:.2f})" for m in found]) +
                                f", predicted {len(predicted)} at " +
                                str({k: f"({v[0][0]:.2f}, {v[0][1]:.2f})"
                                     for k, v in predicted.items()}) +
                                " (column, row)")
            measured_of = match(predicted, found)
            for target, (centre, axis) in predicted.items():
                if target not in measured_of:
                    continue
                nearest = measured_of[target]
                error = nearest[0] - centre
                distance = float(np.linalg.norm(error))
                line = (f"  {target}: predicted (col {centre[0]:8.3f}, row {centre[1]:8.3f})  "
                        f"measured ({nearest[0][0]:8.3f}, {nearest[0][1]:8.3f})  "
                        f"error ({error[0]:+.3f}, {error[1]:+.3f}) px")
                if axis is not None:
                    want = math.degrees(math.atan2(axis[1], axis[0]))
                    line += f"  bar axis {nearest[1]:7.2f}° (predicted {want:7.2f}°)"
                    if angle_difference_deg(nearest[1], want) > ORIENTATION_TOLERANCE_DEG:
                        failures.append(f"{name}: {target}: long axis at {nearest[1]:.2f}° in "
                                        f"the (column, row) plane, predicted {want:.2f}°")
                print(line)
                if not distance <= CENTROID_TOLERANCE_PX:
                    failures.append(f"{name}: {target}: centroid (column {nearest[0][0]:.3f}, "
                                    f"row {nearest[0][1]:.3f}) is {distance:.3f} px from the "
                                    f"predicted ({centre[0]:.3f}, {centre[1]:.3f}), more than "
                                    f"{CENTROID_TOLERANCE_PX}")
            if name in ("nadir_odd", "nadir_even") and "site0/A" in measured_of \
                    and "site0/B" in measured_of:
                # Top line forward (north), left column west, for a level northbound vehicle:
                # A is north-east of nadir, B south-west.
                nadir_col, nadir_row = (columns - 1) / 2.0, (rows - 1) / 2.0
                a, b = measured_of["site0/A"][0], measured_of["site0/B"][0]
                if not (a[1] < nadir_row < b[1]):
                    failures.append(f"{name}: target A (north of nadir) is in row {a[1]:.2f} and "
                                    f"B (south) in row {b[1]:.2f}, expected A above the nadir "
                                    f"row {nadir_row} and B below it (top line forward)")
                if not (b[0] < nadir_col < a[0]):
                    failures.append(f"{name}: target A (east of nadir) is in column {a[0]:.2f} "
                                    f"and B (west) in column {b[0]:.2f}, expected A right of "
                                    f"the nadir column {nadir_col} and B left of it")

    if failures:
        print("\n".join("FAIL: " + f for f in failures))
        return 1
    print(f"PASS: every target is within {CENTROID_TOLERANCE_PX} px of its predicted pixel in "
          f"all {len(CASES)} images; top line forward, left column west")
    return 0


if __name__ == "__main__":
    sys.exit(main())
