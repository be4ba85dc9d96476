#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Generates the peer benchmark's scene (bench/peer/README.md) into a work folder.

One terrain and one lighting, written twice: as glint inputs (a .jsim per image size and
band count, with its platform, motion, tasks, YAML scene and a tabulated atmosphere that
gives a uniform sky and no path effects) and as the numbers the Blender script
(cycles_render.py) builds the same scene from (peer.json).

- terrain.obj: a 4 km x 4 km heightfield of 710 x 710 cells (711 x 711 vertices,
  2 * 710 * 710 = 1,008,200 triangles), heights from the smooth sum of sines glint-bench
  uses (bench/glint_bench/procedural_scene.cpp, about +-60 m), z up, counter-clockwise
  seen from above. Written once and kept (terrain.obj.stamp records its parameters).
- one grey Lambertian material, reflectance 0.25 at every wavelength;
- the sun 35 degrees from the zenith (date, time and latitude chosen for it; the check in
  run_peer.py reads the zenith glint-schedule computes), a uniform sky of
  SKY_RADIANCE W/(cm2 sr um) at every wavelength, no path radiance, transmittances 1;
- a nadir pinhole camera 3,000 m above the origin: focal length 10 mm, a 10.24 mm square
  array of PX x PX elements (27.1 degrees from the centre to an edge), so every pixel sees
  terrain;
- bands: a bandpass of N samples and N normalized tophat channels, one per sample, so the
  ENVI output holds the radiance at each sample in W/(cm2 sr um).

Usage: make_scene.py WORK_DIR [--sizes 1024,256] [--bands 3,32] [--data-dir DIR]
Only numpy is needed (Debian's python3-numpy).
"""
import argparse
import json
import math
import os
import sys

import numpy as np

QUADS = 710            # cells per side: 2 * 710 * 710 = 1,008,200 triangles
TERRAIN_SIZE_M = 4000.0
REFLECTANCE = 0.25
SKY_RADIANCE = 0.004   # W/(cm2 sr um), isotropic: the table's diffuse irradiance is pi times it
CAMERA_HEIGHT_M = 3000.0
FOCAL_LENGTH_MM = 10.0
ARRAY_WIDTH_MM = 10.24
# Sun at 35.0 degrees from the zenith: local solar noon at longitude 0 on 2021-04-04 (the
# Earth-sun distance is within 0.1 % of 1 AU), latitude = 35 + the sun's declination.
# The values were tuned with glint-schedule (NREL SPA); run_peer.py prints the zenith
# glint-schedule reports for every run, so a change shows.
LATITUDE_DEG = 40.8830
LONGITUDE_DEG = 0.0
DATETIME = "2021-04-04T12:02:55.0000+00:00"
SUN_HALF_ANGLE_DEG = 0.2666  # glint's sun disk (docs/physics.md, "What one path computes")
SUN_ZENITH_DEG = 35.0        # nominal; the .jsim gives glint the sun through the date above
SUN_AZIMUTH_DEG = 180.0      # nominal (solar noon: due south)


def bands_grid(n):
    """(minimum, maximum, delta) in um of an n-band run: 3 -> 0.45, 0.55, 0.65; up to 32
    -> 0.01 um steps from 0.40 (32: 0.40 ... 0.71); more -> 0.40 ... 0.70 evenly."""
    if n == 3:
        return 0.45, 0.65, 0.10
    if n == 1:
        return 0.55, 0.55, 0.10
    delta = 0.01 if n <= 32 else 0.30 / (n - 1)
    return 0.40, round(0.40 + (n - 1) * delta, 9), delta


def terrain_height_m(x, y):
    k = 2.0 * math.pi
    return (40.0 * np.sin(k * x / 1500.0) * np.cos(k * y / 1100.0)
            + 15.0 * np.sin(k * (x + y) / 430.0) + 5.0 * np.cos(k * (x - 2.0 * y) / 170.0))


def write_terrain(path):
    stamp = "quads=%d size_m=%g heights=glint-bench-v1\n" % (QUADS, TERRAIN_SIZE_M)
    if os.path.exists(path) and os.path.exists(path + ".stamp"):
        with open(path + ".stamp") as f:
            if f.read() == stamp:
                return False
    side = QUADS + 1
    step = TERRAIN_SIZE_M / QUADS
    coords = -0.5 * TERRAIN_SIZE_M + step * np.arange(side)
    x, y = np.meshgrid(coords, coords)  # x varies along a row: vertex j * side + i
    z = terrain_height_m(x, y).astype(np.float32)
    v = np.column_stack([x.ravel().astype(np.float32), y.ravel().astype(np.float32), z.ravel()])
    i, j = np.meshgrid(np.arange(QUADS), np.arange(QUADS))
    v00 = (j * side + i).ravel() + 1  # OBJ indices start at 1
    v10, v01 = v00 + 1, v00 + side
    v11 = v01 + 1
    faces = np.empty((2 * v00.size, 3), dtype=np.int64)
    faces[0::2] = np.column_stack([v00, v10, v11])  # counter-clockwise from above: normal +z
    faces[1::2] = np.column_stack([v00, v11, v01])
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("# glint peer benchmark terrain: %d x %d cells, %g m, %d triangles\n"
                % (QUADS, QUADS, TERRAIN_SIZE_M, len(faces)))
        np.savetxt(f, v, fmt="v %.4f %.4f %.4f")
        np.savetxt(f, faces, fmt="f %d %d %d")
    os.replace(tmp, path)
    with open(path + ".stamp", "w") as f:
        f.write(stamp)
    return True


def solar_irradiance(data_dir, wavelengths_um):
    """glint's top-of-atmosphere sun at 1 AU, W/(cm2 um), point-sampled as glint does."""
    rows = []
    with open(os.path.join(data_dir, "solar", "astm_g173.csv")) as f:
        for line in f.readlines()[2:]:
            parts = line.split(",")
            rows.append((float(parts[0]) / 1000.0, float(parts[1]) * 0.1))
    wl, e = np.array(rows).T
    return np.interp(wavelengths_um, wl, e)


def earth_sun_distance_au(day_of_year):
    return 1.0 - 0.01672 * math.cos(math.radians(0.9856 * (day_of_year - 4)))


def platform_xml(px, bands):
    lo, hi, delta = bands_grid(bands)
    n = int(round((hi - lo) / delta)) + 1
    size_um = ARRAY_WIDTH_MM * 1000.0 / px
    channels = "\n".join(
        '              <channel name="b%02d" shape="tophat" normalize="true">'
        "<center>%.12g</center><width>%.12g</width></channel>" % (k, lo + k * delta, delta)
        for k in range(n))
    return f"""<!-- glint peer benchmark camera (bench/peer): nadir pinhole, {px} x {px}, {n} bands,
     radiance in W/(cm2 sr um) (no aperture: no G#), float32. -->
<platform>
  <clocktable/>
  <attachment>
    <affinetransform/>
    <instrument name="Peer" type="generic">
      <properties><focallength>{FOCAL_LENGTH_MM}</focallength></properties>
      <focalplane enabled="true" name="Frame">
        <capturemethod type="simple" name="Simple">
          <imagefile areaunits="cm2" fluxunits="watts">
            <basename>glint</basename><extension>img</extension>
            <schedule>simulation</schedule>
            <datatype>4</datatype>
          </imagefile>
          <spectralresponse>
            <bandpass spectralunits="microns">
              <minimum>{lo:.12g}</minimum><maximum>{hi:.12g}</maximum><delta>{delta:.12g}</delta>
            </bandpass>
            <channellist>
{channels}
            </channellist>
          </spectralresponse>
          <temporalintegration tdi="false"><time>0</time></temporalintegration>
        </capturemethod>
        <detectorarray spatialunits="microns">
          <clock type="independent" temporalunits="hertz"><rate>1</rate><offset>0</offset></clock>
          <xelementcount>{px}</xelementcount><yelementcount>{px}</yelementcount>
          <xelementsize>{size_um:g}</xelementsize><yelementsize>{size_um:g}</yelementsize>
          <xelementspacing>{size_um:g}</xelementspacing><yelementspacing>{size_um:g}</yelementspacing>
        </detectorarray>
      </focalplane>
    </instrument>
  </attachment>
</platform>
""", n


# The canopy scene (--canopy N): examples/vegetation's tree (a trunk and 6,000 leaf quads)
# instanced N times on a jittered grid centred under the camera, over a flat soil of
# REFLECTANCE; spectrally flat leaves (reflectance and transmittance LEAF_RT each, so that
# Cycles' Diffuse + Translucent mix gives the same numbers in every channel) and bark.
CANOPY_CAMERA_HEIGHT_M = 300.0
CANOPY_SPACING_M = 7.0
# The soil: large enough that a camera tilted 30 degrees sees soil to its image's far edge
# (glint sees nothing below the horizon beyond the scene, Cycles its world colour).
CANOPY_GROUND_SIZE_M = 4000.0
LEAF_RT = 0.45
BARK_REFLECTANCE = 0.2


def write_canopy(work, trees, put):
    import importlib.util
    import random
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                        "vegetation", "make_forest.py")
    spec = importlib.util.spec_from_file_location("make_forest", path)
    forest = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(forest)
    rng = random.Random(20261128)
    forest.write_tree(os.path.join(work, "tree.obj"), 6000, rng)
    side = int(math.ceil(math.sqrt(trees)))
    half = (side - 1) * CANOPY_SPACING_M / 2.0
    instances = []
    for i in range(side):
        for j in range(side):
            if len(instances) == trees:
                break
            x = -half + (i + rng.uniform(-0.3, 0.3)) * CANOPY_SPACING_M
            y = -half + (j + rng.uniform(-0.3, 0.3)) * CANOPY_SPACING_M
            instances.append([round(x, 2), round(y, 2), round(rng.uniform(0, 360), 1),
                              round(rng.uniform(0.8, 1.2), 3)])
    flat = lambda v: "{wavelengths: [0.3, 1.0], values: [%g, %g]}" % (v, v)
    lines = ["# glint peer benchmark canopy (bench/peer/make_scene.py --canopy %d)" % trees,
             "origin: {latitude: %s, longitude: %s, altitude: 0}" % (LATITUDE_DEG, LONGITUDE_DEG),
             "materials:",
             "  - {id: soil, reflectance: %s}" % flat(REFLECTANCE),
             "  - {id: leaf, reflectance: %s, transmittance: %s}" % (flat(LEAF_RT), flat(LEAF_RT)),
             "  - {id: bark, reflectance: %s}" % flat(BARK_REFLECTANCE),
             "objects:",
             "  - {name: ground, primitive: ground_plane, material: soil, size: %g}"
             % CANOPY_GROUND_SIZE_M,
             "  - name: tree", "    obj: tree.obj", "    instances:"]
    lines += ["      - {translation: [%g, %g, 0], rotation_deg: [0, 0, %g], scale: %g}" % tuple(v)
              for v in instances]
    put("scene.yaml", "\n".join(lines) + "\n")
    return {"tree_obj": "tree.obj", "instances": instances, "leaf_rt": LEAF_RT,
            "bark_reflectance": BARK_REFLECTANCE, "ground_size_m": CANOPY_GROUND_SIZE_M,
            "triangles": 12010 * len(instances)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("work")
    ap.add_argument("--sizes", default="1024,256")
    ap.add_argument("--bands", default="3,32")
    ap.add_argument("--canopy", type=int, default=0,
                    help="instead of the terrain: this many instanced trees of transmitting "
                         "leaves (examples/vegetation's tree) over a flat soil, the camera at "
                         "CANOPY_CAMERA_HEIGHT_M")
    ap.add_argument("--view-zenith", type=float, default=0.0,
                    help="tilt the camera this many degrees from nadir about the east axis "
                         "(positive: looking north, from south of the origin), keeping its "
                         "height and aiming at the origin")
    ap.add_argument("--data-dir", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "data"))
    args = ap.parse_args()
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)

    def put(name, text):
        with open(os.path.join(work, name), "w") as f:
            f.write(text)

    camera_height_m = CAMERA_HEIGHT_M
    canopy = None
    if args.canopy:
        canopy = write_canopy(work, args.canopy, put)
        camera_height_m = CANOPY_CAMERA_HEIGHT_M
    else:
        wrote = write_terrain(os.path.join(work, "terrain.obj"))
        print("terrain.obj: %s" % ("written" if wrote else "kept (cached)"), file=sys.stderr)
        put("scene.yaml", f"""# glint peer benchmark scene (bench/peer/make_scene.py)
origin: {{latitude: {LATITUDE_DEG}, longitude: {LONGITUDE_DEG}, altitude: 0}}
materials:
  - id: soil
    reflectance: {{wavelengths: [0.3, 1.0], values: [{REFLECTANCE}, {REFLECTANCE}]}}
objects:
  - name: terrain
    obj: terrain.obj
    material: soil
""")
    # Pitch (nose up) tilts the nadir boresight towards +y, north (docs/motion.md).
    camera_y_m = -camera_height_m * math.tan(math.radians(args.view_zenith))
    sky_e = SKY_RADIANCE * math.pi
    put("sky.txt", "# uniform sky, no path effects (bench/peer/make_scene.py)\n"
        "# wavelength_um sun_T sensor_T path_radiance sky_irradiance thermal_sky\n"
        f"0.30 1 1 0 {sky_e:.9g} 0\n1.00 1 1 0 {sky_e:.9g} 0\n")
    put("atmosphere.yaml", "# Uniform sky of %g W/(cm2 sr um), transmittances 1, no path radiance\n"
        "model: tabulated\ntable: sky.txt\n" % SKY_RADIANCE)
    put("peer.ppd", f"""<platformmotion type="generic">
  <method type="raw"/>
  <data rotationframe="sceneenu" rotationorder="xyz" angletype="absolute"
        angularunits="degrees" spatialunits="meters">
    <entry>
      <datetime type="relative">0</datetime>
      <position><location type="scene"><point><x>0</x><y>{camera_y_m:.6f}</y><z>{camera_height_m}</z></point></location></position>
      <orientation><eulerangles><cartesiantriple><x>{args.view_zenith}</x><y>0</y><z>0</z></cartesiantriple></eulerangles></orientation>
    </entry>
  </data>
</platformmotion>
""")
    put("peer.tasks", f"""<tasklist>
  <reference><datetime type="absolute">{DATETIME}</datetime></reference>
  <task>
    <start><datetime type="relative">0.0</datetime></start>
    <stop><datetime type="relative">0.0</datetime></stop>
  </task>
</tasklist>
""")
    configs = []
    for px in [int(s) for s in args.sizes.split(",") if s]:
        for b in [int(s) for s in args.bands.split(",") if s]:
            xml, n = platform_xml(px, b)
            name = "peer-%d-b%d" % (px, b)
            put(name + ".platform", xml)
            put(name + ".jsim", json.dumps([{
                "scene_list": [{"inputs": "scene.yaml"}],
                "plugin_list": [
                    {"name": "BasicAtmosphere", "inputs": {"atmosphere_filename": "atmosphere.yaml"}},
                    {"name": "BasicPlatform", "inputs": {
                        "platform_filename": name + ".platform", "motion_filename": "peer.ppd",
                        "tasks_filename": "peer.tasks"}}]}], indent=1) + "\n")
            configs.append({"px": px, "bands": n, "jsim": name + ".jsim"})

    # The sun Cycles gets: glint's sun at the 3-band samples (G173 at 0.45/0.55/0.65 um over
    # d^2), one per RGB channel, so that Cycles' R, G, B should equal glint's three bands.
    day = 94  # 2021-04-04
    d = earth_sun_distance_au(day)
    rgb_um = [0.45, 0.55, 0.65]
    e_rgb = (solar_irradiance(args.data_dir, rgb_um) / d ** 2).tolist()
    peer = {
        "terrain_obj": "terrain.obj",
        "triangles": canopy["triangles"] if canopy else 2 * QUADS * QUADS,
        "canopy": canopy,
        "reflectance": REFLECTANCE,
        "sky_radiance": SKY_RADIANCE,
        "sun_zenith_deg": SUN_ZENITH_DEG,
        "sun_azimuth_deg": SUN_AZIMUTH_DEG,
        "sun_angle_deg": 2.0 * SUN_HALF_ANGLE_DEG,
        "sun_irradiance_rgb": e_rgb,
        "sun_wavelengths_um": rgb_um,
        "earth_sun_distance_au": d,
        "camera_height_m": camera_height_m,
        "camera_y_m": camera_y_m,
        "view_zenith_deg": args.view_zenith,
        "focal_length_mm": FOCAL_LENGTH_MM,
        "sensor_width_mm": ARRAY_WIDTH_MM,
        "configs": configs,
    }
    put("peer.json", json.dumps(peer, indent=1) + "\n")
    brief = dict(peer)
    if canopy:
        brief["canopy"] = {k: v for k, v in canopy.items() if k != "instances"}
        brief["canopy"]["trees"] = len(canopy["instances"])
    print(json.dumps(brief), file=sys.stderr)


if __name__ == "__main__":
    main()
