#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the vegetation example's scene: tree.obj (one broadleaf tree: a bark trunk and a
crown of flat leaves, each leaf a 2-triangle quad) and forest_scene.yaml (the tree instanced
on a jittered grid over bare soil, beside a shed with a Ward metal roof, a glass-roofed cold
frame, a pond and a white reference panel). Deterministic: the same arguments give the same
bytes. Standard library only.

Usage: make_forest.py OUT_DIR [--trees N] [--leaves N] [--spacing M]
"""
import argparse
import math
import os
import random


def write_tree(path, leaves, rng):
    """A trunk (0.3 m square, 4.5 m) and `leaves` leaves in an ellipsoidal crown (radius
    2.5 m, half-height 2 m, centred 6 m up); each leaf a 0.12 m x 0.07 m quad facing a
    random direction (leaves are two-sided sheets)."""
    lines = ["# glint vegetation example: one tree (make_forest.py)", "usemtl bark"]
    v = []
    t = 0.15
    for z in (0.0, 4.5):
        v += [(-t, -t, z), (t, -t, z), (t, t, z), (-t, t, z)]
    faces = [(0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7), (4, 5, 6, 7)]
    lines += ["v %.4f %.4f %.4f" % p for p in v]
    lines += ["f %d %d %d %d" % tuple(i + 1 for i in f) for f in faces]
    lines.append("usemtl leaf")
    base = len(v)
    for k in range(leaves):
        # A point in the crown (rejection from the bounding box).
        while True:
            x, y, z = (rng.uniform(-1, 1) for _ in range(3))
            if x * x + y * y + z * z <= 1.0:
                break
        cx, cy, cz = 2.5 * x, 2.5 * y, 6.0 + 2.0 * z
        # A random unit normal and two tangents.
        nz = rng.uniform(-1, 1)
        phi = rng.uniform(0, 2 * math.pi)
        r = math.sqrt(1 - nz * nz)
        n = (r * math.cos(phi), r * math.sin(phi), nz)
        a = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
        u = (n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0])
        lu = math.sqrt(sum(c * c for c in u))
        u = tuple(c / lu for c in u)
        w = (n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0])
        hu, hw = 0.06, 0.035
        for su, sw in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            lines.append("v %.4f %.4f %.4f" % tuple(
                c + su * hu * uu + sw * hw * ww for c, uu, ww in zip((cx, cy, cz), u, w)))
        i = base + 4 * k + 1
        lines.append("f %d %d %d %d" % (i, i + 1, i + 2, i + 3))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


SCENE_HEAD = """# glint vegetation example (make_forest.py; examples/vegetation/README.md): %(trees)d
# instanced trees of %(leaves)d leaves each over bare soil, a shed with a Ward metal roof, a
# cold frame with a clear glass roof, a pond and a white reference panel. Spectra are smooth
# made-up curves shaped like measured ones (a green leaf, a dry loam), not measured data.
origin: {latitude: 43.0, longitude: -77.6, altitude: 150.0}
materials:
  - id: leaf          # reflects and transmits ~45 %% each in the NIR, absorbs the red
    reflectance:   {wavelengths: [0.40, 0.50, 0.55, 0.60, 0.67, 0.70, 0.75, 0.80, 1.00], values: [0.05, 0.06, 0.13, 0.08, 0.05, 0.12, 0.42, 0.47, 0.47]}
    transmittance: {wavelengths: [0.40, 0.50, 0.55, 0.60, 0.67, 0.70, 0.75, 0.80, 1.00], values: [0.01, 0.03, 0.10, 0.05, 0.02, 0.10, 0.40, 0.45, 0.45]}
  - {id: bark, reflectance: {wavelengths: [0.40, 0.70, 1.00], values: [0.05, 0.12, 0.25]}}
  - {id: soil, reflectance: {wavelengths: [0.40, 0.55, 0.70, 1.00], values: [0.08, 0.14, 0.20, 0.28]}}
  - {id: wall, reflectance: {wavelengths: [0.40, 1.00], values: [0.45, 0.50]}}
  - id: metal_roof    # corrugated steel: Ward, grooves along x (east)
    ward: {diffuse: 0.10, specular: 0.55, alpha_x: 0.05, alpha_y: 0.25}
  - id: glass         # 4 %% mirror, 90 %% straight through
    reflectance: {wavelengths: [0.40, 1.00], values: [0.04, 0.04]}
    specular: {fraction: 1, roughness: 0}
    transmittance: {wavelengths: [0.40, 1.00], values: [0.90, 0.90]}
    transmission: straight
  - id: seedlings     # green leaves under the glass
    reflectance: {wavelengths: [0.40, 0.50, 0.55, 0.60, 0.67, 0.70, 0.75, 0.80, 1.00], values: [0.04, 0.05, 0.11, 0.07, 0.04, 0.10, 0.38, 0.44, 0.44]}
  - id: water
    reflectance: {wavelengths: [0.40, 0.60, 0.80, 1.00], values: [0.04, 0.03, 0.02, 0.02]}
    specular: {fraction: 0.9, roughness: 0}
  - {id: white_panel, reflectance: {wavelengths: [0.40, 1.00], values: [0.99, 0.99]}}
objects:
  - {name: ground, primitive: ground_plane, material: soil, size: 2000}
  - {name: shed, primitive: box, material: wall, lower: [-34, -6, 0], upper: [-22, 6, 3]}
  - {name: shed_roof, primitive: box, material: metal_roof, lower: [-34.5, -6.5, 3], upper: [-21.5, 6.5, 3.05]}
  - {name: cold_frame_bed, primitive: box, material: seedlings, lower: [22, -6, 0], upper: [34, 6, 0.3]}
  - {name: cold_frame_glass, primitive: box, material: glass, lower: [22, -6, 1.2], upper: [34, 6, 1.21]}
  - {name: pond, primitive: box, material: water, lower: [-8, -34, 0], upper: [8, -24, 0.02]}
  - {name: reference_panel, primitive: box, material: white_panel, lower: [-2, 26, 0], upper: [2, 30, 0.02]}
  - name: tree
    obj: tree.obj
    instances:
"""


def write_scene(path, trees, leaves, spacing, rng):
    lines = [SCENE_HEAD % {"trees": trees, "leaves": leaves}]
    side = int(math.ceil(math.sqrt(trees)))
    half = (side - 1) * spacing / 2.0
    placed = 0
    for i in range(side):
        for j in range(side):
            if placed == trees:
                break
            x = -half + i * spacing + rng.uniform(-0.3, 0.3) * spacing
            y = -half + j * spacing + rng.uniform(-0.3, 0.3) * spacing
            # Keep the shed, the cold frame, the pond and the panel clear.
            if (abs(y) < 10 and abs(x) > 18 and abs(x) < 38) or (abs(x) < 12 and -38 < y < -20) \
                    or (abs(x) < 6 and 22 < y < 34):
                continue
            s = rng.uniform(0.8, 1.2)
            lines.append("      - {translation: [%.2f, %.2f, 0], rotation_deg: [0, 0, %.1f], scale: %.3f}"
                         % (x, y, rng.uniform(0, 360), s))
            placed += 1
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return placed


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--trees", type=int, default=120)
    parser.add_argument("--leaves", type=int, default=6000)
    parser.add_argument("--spacing", type=float, default=7.0, help="grid step, m")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rng = random.Random(20261128)
    write_tree(os.path.join(args.out, "tree.obj"), args.leaves, rng)
    placed = write_scene(os.path.join(args.out, "forest_scene.yaml"), args.trees, args.leaves,
                         args.spacing, rng)
    print("%d trees x %d leaves (%d leaf triangles through instancing)"
          % (placed, args.leaves, placed * args.leaves * 2))


if __name__ == "__main__":
    main()
