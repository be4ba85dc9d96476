#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes the terrain example's scene as DIRSIG users build terrain (examples/terrain/
README.md): a few thousand large facets of one proxy material, whose materials come from a
land-cover classification draped over them and whose spectral variety comes from a texture.

  terrain.scene       the scene: the glist, the .mat, a <materialmap> and a <texturemap>
  terrain.glist       the terrain OBJ with the proxy material (matid 1)
  geometry/terrain.obj  a 400 m x 400 m height field (65 x 65 vertices, hills and a valley)
  materials/terrain.mat, *.txt, grass.ems   water, grass (6 texture classes), forest, soil,
                      road; smooth spectra over 0.4-2.5 um
  maps/landcover.pgm  200 x 200 texels of 2 m: the class of each place (by height, slope,
                      a noise field and a road)
  maps/grass.pgm      128 x 128 texels of 0.5 m, tiled: the grass's brightness (0.4-0.7 um)

Deterministic: the same arguments give the same bytes. Needs NumPy.
Usage: make_terrain.py OUT_DIR
"""
import os
import sys

import numpy as np

SIZE_M = 400.0
GRID = 65  # vertices per side
CLASS_TEXELS = 200  # land-cover texels per side (2 m)
# Land-cover digital counts → material ids (the <dcmatlut>).
CLASSES = {30: ("11", "Water"), 90: ("12", "Grass"), 150: ("13", "Forest"),
           200: ("14", "Soil"), 250: ("15", "Road")}


def smooth_noise(rng, n, octaves):
    """A smooth random field on an n x n grid in [0, 1] (summed bilinear octaves)."""
    field = np.zeros((n, n))
    for k in range(octaves):
        cells = 2 ** (k + 2)
        coarse = rng.random((cells + 1, cells + 1))
        x = np.linspace(0, cells, n)
        i = np.minimum(x.astype(int), cells - 1)
        f = x - i
        rows = coarse[i] * (1 - f)[:, None] + coarse[i + 1] * f[:, None]
        field += (rows[:, i] * (1 - f) + rows[:, i + 1] * f) / 2 ** k
    field -= field.min()
    return field / field.max()


def height_m(x, y):
    """Hills rising to the north-east, a valley running north-south west of centre."""
    hills = 30 * np.exp(-((x - 80) ** 2 + (y - 90) ** 2) / 9000.0)
    hills += 18 * np.exp(-((x + 120) ** 2 + (y + 110) ** 2) / 6000.0)
    valley = -12 * np.exp(-((x + 40 + 15 * np.sin(y / 40.0)) ** 2) / 900.0)
    return 14 + hills + valley


def write_obj(path):
    coords = np.linspace(-SIZE_M / 2, SIZE_M / 2, GRID)
    lines = ["# glint terrain example: a height field (make_terrain.py)"]
    for y in coords:
        for x in coords:
            lines.append("v %.3f %.3f %.3f" % (x, y, height_m(x, y)))
    for j in range(GRID - 1):
        for i in range(GRID - 1):
            a = j * GRID + i + 1
            lines.append("f %d %d %d" % (a, a + 1, a + GRID + 1))
            lines.append("f %d %d %d" % (a, a + GRID + 1, a + GRID))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def landcover(rng):
    """The class of each 2 m texel, line 0 the northern edge."""
    n = CLASS_TEXELS
    centres = -SIZE_M / 2 + (np.arange(n) + 0.5) * SIZE_M / n
    x = centres[None, :]
    y = centres[::-1, None]  # line 0 is north
    z = height_m(x, y)
    patches = smooth_noise(rng, n, 5)
    dc = np.full((n, n), 90, dtype=np.uint8)  # grass
    dc[patches > 0.62] = 150  # forest
    dc[(patches < 0.35) & (z > 18)] = 200  # bare soil on the hills
    dc[z < 6.0] = 30  # water in the valley floor
    road = np.abs(y - 0.35 * x - 60) < 4.0
    dc[road & (z >= 6.0)] = 250
    return dc


def grass_texture(rng):
    """The grass's relative brightness: smooth clumps and fine speckle, 0-255."""
    clumps = smooth_noise(rng, 128, 4)
    speckle = rng.random((128, 128))
    v = 0.7 * clumps + 0.3 * speckle
    return np.round(255 * (v - v.min()) / (v.max() - v.min())).astype(np.uint8)


def write_pgm(path, image):
    with open(path, "wb") as f:
        f.write(b"P5\n%d %d\n255\n" % (image.shape[1], image.shape[0]))
        f.write(image.tobytes())


WAVELENGTHS = np.round(np.arange(0.40, 2.501, 0.01), 3)


def vegetation(green, red, nir):
    """A smooth vegetation reflectance: a green peak, a red trough, the red edge at
    0.72 um, a NIR plateau and the water bands beyond."""
    w = WAVELENGTHS
    vis = red + (green - red) * np.exp(-((w - 0.55) / 0.04) ** 2)
    edge = 1 / (1 + np.exp(-(w - 0.72) / 0.015))
    swir = np.where(w > 1.3, 0.55, 1.0)
    return vis * (1 - edge) + nir * edge * swir


def spectra():
    w = WAVELENGTHS
    return {
        "water": 0.06 * np.exp(-(w - 0.4) / 0.25) + 0.005,
        "forest": vegetation(0.06, 0.03, 0.42),
        "soil": 0.10 + 0.20 * (w - 0.4) / 2.1 + 0.06 * np.tanh((w - 0.4) / 0.3),
        "road": np.full_like(w, 0.09),
        "proxy": np.full_like(w, 0.2),
    }


# The grass's texture classes: from sparse, dry and bright-red to dense and dark-green.
GRASS_CLASSES = [(0.09, 0.08, 0.30), (0.09, 0.07, 0.34), (0.10, 0.06, 0.38),
                 (0.10, 0.05, 0.42), (0.11, 0.045, 0.46), (0.12, 0.04, 0.50)]


def write_materials(folder):
    os.makedirs(folder, exist_ok=True)
    for name, values in spectra().items():
        with open(os.path.join(folder, name + ".txt"), "w") as f:
            f.write("# glint terrain example: %s reflectance (make_terrain.py)\n" % name)
            for w, v in zip(WAVELENGTHS, values):
                f.write("%.3f %.5f\n" % (w, v))
    # A classic .ems: curve count, then each class's emissivity (1 - reflectance) after
    # CURVE_BEGIN, sorted so that the brightest grass in 0.4-0.7 um is the last class.
    lines = ["%d" % len(GRASS_CLASSES)]
    for green, red, nir in GRASS_CLASSES:
        lines.append("CURVE_BEGIN")
        rho = vegetation(green, red, nir)
        lines += ["%.3f %.5f" % (w, 1 - r) for w, r in zip(WAVELENGTHS, rho)]
        lines.append("CURVE_END")
    with open(os.path.join(folder, "grass.ems"), "w") as f:
        f.write("\n".join(lines) + "\n")
    entries = [("1", "Terrain proxy", "REFLECTANCE", "SimpleReflectance", "proxy.txt"),
               ("11", "Water", "REFLECTANCE", "SimpleReflectance", "water.txt"),
               ("12", "Grass", "EMISSIVITY", "ClassicEmissivity", "grass.ems"),
               ("13", "Forest", "REFLECTANCE", "SimpleReflectance", "forest.txt"),
               ("14", "Soil", "REFLECTANCE", "SimpleReflectance", "soil.txt"),
               ("15", "Road", "REFLECTANCE", "SimpleReflectance", "road.txt")]
    with open(os.path.join(folder, "terrain.mat"), "w") as f:
        f.write("# glint terrain example materials (make_terrain.py)\n")
        for mid, name, slot, model, curve in entries:
            key = "FILENAME" if curve.endswith(".ems") else "TXT_FILENAME"
            f.write("MATERIAL_ENTRY {\n    ID = %s\n    NAME = %s\n    TEMPERATURE = 293\n"
                    "    SURFACE_PROPERTIES {\n        %s_PROP_NAME = %s\n"
                    "        %s_PROP {\n            %s = %s\n        }\n    }\n}\n"
                    % (mid, name, slot, model, slot, key, curve))


SCENE = """<?xml version="1.0" encoding="UTF-8"?>
<!-- glint terrain example (make_terrain.py; examples/terrain/README.md): a height field of
     one proxy material (1), split into land-cover classes by a draped classification map,
     its grass (12) varied by a tiled texture map over the grass's six texture classes. -->
<classicscene>
  <sceneorigin>
    <location frame="geodetic"><latitude>43.1</latitude><longitude>-77.5</longitude><altitude>150</altitude></location>
  </sceneorigin>
  <geometrylist enabled="true">
    <geometrylistinclude name="Terrain" enabled="true">terrain.glist</geometrylistinclude>
  </geometrylist>
  <matfilename>$SCENE_DIR/materials/terrain.mat</matfilename>
  <mapdirectory>$SCENE_DIR/maps</mapdirectory>
  <maplist>
    <materialmap name="Land cover" enabled="true" mixing="false">
      <matidlist><matid>1</matid></matidlist>
      <projector origin="image" flipx="false" flipy="false" extendx="clamp" extendy="clamp">
        <drapeprojector>
          <insertpoint><x>-200</x><y>200</y><z>0</z></insertpoint>
          <gsd>2.0</gsd>
        </drapeprojector>
      </projector>
      <dcmatlut>
%(lut)s
      </dcmatlut>
      <image><filename>landcover.pgm</filename></image>
    </materialmap>
    <texturemap name="Grass texture" enabled="true">
      <matidlist><matid>12</matid></matidlist>
      <projector origin="cartesian" extendx="mirror" extendy="mirror">
        <drapeprojector>
          <insertpoint><x>0</x><y>0</y></insertpoint>
          <gsd>0.5</gsd>
        </drapeprojector>
      </projector>
      <bandlist>
        <band>
          <bandpass><min>0.4</min><max>0.7</max></bandpass>
          <image><filename>grass.pgm</filename></image>
        </band>
      </bandlist>
    </texturemap>
  </maplist>
</classicscene>
"""

GLIST = """<?xml version="1.0" encoding="UTF-8"?>
<!-- glint terrain example: the height field, all of the proxy material the maps split -->
<geometrylist enabled="true">
  <object>
    <basegeometry><obj><filename>geometry/terrain.obj</filename><matid>1</matid></obj></basegeometry>
    <staticinstance name="Terrain"/>
  </object>
</geometrylist>
"""


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: make_terrain.py OUT_DIR")
    out = sys.argv[1]
    rng = np.random.default_rng(20261128)
    for sub in ("geometry", "maps", "materials"):
        os.makedirs(os.path.join(out, sub), exist_ok=True)
    write_obj(os.path.join(out, "geometry", "terrain.obj"))
    write_pgm(os.path.join(out, "maps", "landcover.pgm"), landcover(rng))
    write_pgm(os.path.join(out, "maps", "grass.pgm"), grass_texture(rng))
    write_materials(os.path.join(out, "materials"))
    lut = "\n".join("        <entry><dc>%d</dc><matid>%s</matid></entry>" % (dc, mid)
                    for dc, (mid, _) in sorted(CLASSES.items()))
    with open(os.path.join(out, "terrain.scene"), "w") as f:
        f.write(SCENE % {"lut": lut})
    with open(os.path.join(out, "terrain.glist"), "w") as f:
        f.write(GLIST)


if __name__ == "__main__":
    main()
