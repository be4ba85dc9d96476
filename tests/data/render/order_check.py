#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Capture-order independence under one atmosphere (tests/cli/render/order-*.toml).

Proves that every capture's output bytes depend only on (inputs, seed, capture), never on which
captures the same process rendered before it: the sensor-path tables of an atmosphere are
cached per focal plane by rounded geometry (radiometry::SensorPathCache), the Embree scene is
built once or per capture, detection draws from (seed, capture, line) streams — a value that
leaked from one capture into the next would make a capture rendered alone differ from the same
capture rendered after others.

Writes a small simulation into WORK (the 8 x 6 camera of tests/data/render 1000 m over
scene.yaml, an aperture, 0.1 ms integration, a detector model with shot, dark and read noise,
two truth collections, every file on the `capture` schedule) with five captures: task 0 at
0.0, 0.1, 0.2 s — the sun moves ~5e-4 deg between them, so they share the rounded sun
geometry of the sensor-path cache while their exact geometry differs — and task 1, 900 s
later, with another rounded geometry. Then renders, once with the detector model (counts) and
once with --radiance-only (float64 photons/cm2, where a 1e-12 relative difference shows):

  full       every capture in one process (default --threads)
  threads1   every capture, --threads 1
  alone-K    capture K alone in its process (glint-schedule --captures K), K = 0..4
  sel-...    selections {1, 2}, {0, 2, 4}, {2, 3}: captures after other predecessors
  shard-K    glint-schedule --shard K/3

and checks that every composition writes exactly the image and truth files of its captures,
each data file byte for byte equal to the full run's and each header equal to it except for
`glint command line`. Every difference is reported (composition, file, values that differ,
largest absolute and relative difference, first differing line/sample/band).

--atmosphere FILE names the BasicAtmosphere file of the simulation (absolute, or relative to
tests/data); --override X renders with `glint-render --atmosphere X` instead (with
--atmosphere atmosphere/classic.atm, a MODTRAN .atm glint refuses to read without it).
--moving platform: the platform climbs 0.5 m/s (task 0 within one rounded sensor altitude at
different exact altitudes, task 1 450 m higher); --moving scene: a box drives through the
view (the Embree scene is rebuilt for every capture).
Prints one `ok:` line per mode and exits 0, or lists every difference and exits 1.
"""
import argparse
import concurrent.futures
import json
import math
import os
import subprocess
import sys
from array import array

DATA = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # tests/data
SEED = "20200621"
CONVERGENCE = "2,16,1e-4"

PLATFORM = """<platform>
  <clocktable/>
  <attachment>
    <affinetransform/>
    <instrument name="Cam" type="generic">
      <properties>
        <focallength>100</focallength>
        <aperturediameter>0.02</aperturediameter>
        <aperturethroughput>0.8</aperturethroughput>
      </properties>
      <focalplane enabled="true" name="Frame">
        <capturemethod type="simple" name="Simple">
          <imagefile areaunits="cm2" fluxunits="watts">
            <basename>frame</basename><extension>img</extension>
            <schedule>capture</schedule>
          </imagefile>
          <spectralresponse>
            <bandpass spectralunits="microns">
              <minimum>0.50</minimum><maximum>0.60</maximum><delta>0.02</delta>
            </bandpass>
            <channellist>
              <channel name="Green" shape="tophat" normalize="true">
                <center>0.55</center><width>0.1</width>
              </channel>
              <channel name="Edge" shape="tophat" normalize="true">
                <center>0.57</center><width>0.06</width>
              </channel>
            </channellist>
          </spectralresponse>
          <temporalintegration tdi="false"><time>0.0001</time></temporalintegration>
          <detectormodel>
            <quantumefficiency>0.8</quantumefficiency><readnoise>5</readnoise>
            <darkcurrentdensity>1e-5</darkcurrentdensity>
            <minelectrons>0</minelectrons><maxelectrons>100000</maxelectrons><bitdepth>12</bitdepth>
          </detectormodel>
        </capturemethod>
        <truthcollection>
          <enabled>true</enabled>
          <name>labels</name>
          <imagefile><basename>labels</basename><extension>img</extension><schedule>capture</schedule></imagefile>
          <collectorlist>
            <collector><name>Material</name></collector>
            <collector><name>InstanceId</name></collector>
            <collector><name>Abundance</name><materials>white</materials></collector>
            <collector><name>Shadow</name></collector>
            <collector><name>Reflectance</name></collector>
            <collector><name>Temperature</name></collector>
          </collectorlist>
        </truthcollection>
        <truthcollection>
          <enabled>true</enabled>
          <name>geometry</name>
          <imagefile><basename>geometry</basename><extension>img</extension><schedule>capture</schedule></imagefile>
          <collectorlist>
            <collector><name>GeoLocation</name></collector>
            <collector><name>Intersection</name></collector>
            <collector><name>SampleCount</name></collector>
            <collector><name>StandardError</name></collector>
          </collectorlist>
        </truthcollection>
        <detectorarray spatialunits="microns">
          <clock type="independent" temporalunits="hertz"><rate>10</rate><offset>0</offset></clock>
          <xelementcount>8</xelementcount><yelementcount>6</yelementcount>
          <xelementsize>20</xelementsize><yelementsize>20</yelementsize>
          <xelementspacing>20</xelementspacing><yelementspacing>20</yelementspacing>
        </detectorarray>
      </focalplane>
    </instrument>
  </attachment>
</platform>
"""

TASKS = """<tasklist>
  <reference><datetime type="absolute">2020-06-21T12:00:00.0000-04:00</datetime></reference>
  <task>
    <start><datetime type="relative">0.0</datetime></start>
    <stop><datetime type="relative">0.25</datetime></stop>
  </task>
  <task>
    <start><datetime type="relative">900.0</datetime></start>
    <stop><datetime type="relative">900.15</datetime></stop>
  </task>
</tasklist>
"""


def ppd(entries):
    """A raw GenericMotion (.ppd) through (t, x, y, z) scene points, level attitude."""
    rows = "".join(
        f"""    <entry>
      <datetime type="relative">{t}</datetime>
      <position><location type="scene"><point><x>{x}</x><y>{y}</y><z>{z}</z></point></location></position>
      <orientation><eulerangles><cartesiantriple><x>0</x><y>0</y><z>0</z></cartesiantriple></eulerangles></orientation>
    </entry>
""" for t, x, y, z in entries)
    return f"""<platformmotion type="generic">
  <method type="raw"/>
  <data rotationframe="sceneenu" rotationorder="xyz" angletype="absolute"
        angularunits="degrees" spatialunits="meters">
{rows}  </data>
</platformmotion>
"""


# Task 0 climbs 0.05 m per capture (one rounded sensor altitude, different exact ones); task 1
# is 450 m higher.
CLIMB = ppd([(0, 0, 0, 1000), (1000, 0, 0, 1500)])
STATIC = ppd([(0, 0, 0, 1000)])
# A 0.4 m cube crossing the view at 2 m/s in task 0 and back in task 1.
CART = ppd([(0, -0.3, 0.4, 0), (0.25, 0.2, 0.4, 0), (900, 0.2, -0.4, 0), (900.25, -0.3, -0.4, 0)])
CART_OBJECT = ("  - {name: cart, primitive: box, material: white, lower: [-0.2, -0.2, 0], "
               "upper: [0.2, 0.2, 0.4], instances: [{name: cart, motion: cart.ppd}]}\n")


def write_inputs(work, atmosphere, moving):
    scene = open(os.path.join(DATA, "render", "scene.yaml")).read()
    if moving == "scene":
        scene = scene.rstrip("\n") + "\n" + CART_OBJECT
        open(os.path.join(work, "cart.ppd"), "w").write(CART)
    open(os.path.join(work, "scene.yaml"), "w").write(scene)
    open(os.path.join(work, "cam.platform"), "w").write(PLATFORM)
    open(os.path.join(work, "order.tasks"), "w").write(TASKS)
    open(os.path.join(work, "cam.ppd"), "w").write(CLIMB if moving == "platform" else STATIC)
    sim = [{
        "scene_list": [{"inputs": "scene.yaml"}],
        "plugin_list": [
            {"name": "BasicAtmosphere", "inputs": {"atmosphere_filename": atmosphere}},
            {"name": "BasicPlatform", "inputs": {"platform_filename": "cam.platform",
                                                 "motion_filename": "cam.ppd",
                                                 "tasks_filename": "order.tasks"}},
        ],
    }]
    with open(os.path.join(work, "sim.jsim"), "w") as f:
        json.dump(sim, f, indent=1)


def run(argv, cwd):
    try:
        done = subprocess.run(argv, cwd=cwd, capture_output=True, text=True)
    except OSError as e:
        raise SystemExit(f"cannot run {argv[0]}: {e}")
    if done.returncode != 0:
        raise SystemExit(f"FAILED (exit {done.returncode}): {' '.join(argv)}\n{done.stderr}")
    return done.stdout


def check_premise(captures, moving):
    """The captures must exercise the cache: some share a rounded key with different exact
    geometry, some have another key (the steps of radiometry::SensorPathCache)."""
    def key(c):
        alt = c["pose"]["instrument"]["geodetic"]["altitude_m"]
        return (round(c["sun"]["zenith_deg"] / 0.05), round(c["sun"]["azimuth_deg"] / 0.05),
                round(alt))

    def margin(c):  # distance of each rounded quantity from a rounding boundary, in steps
        alt = c["pose"]["instrument"]["geodetic"]["altitude_m"]
        vals = (c["sun"]["zenith_deg"] / 0.05, c["sun"]["azimuth_deg"] / 0.05, alt)
        return min(0.5 - abs(v - round(v)) for v in vals)

    task0 = [c for c in captures if c["task_index"] == 0]
    task1 = [c for c in captures if c["task_index"] == 1]
    assert len(task0) == 3 and len(task1) == 2, [c["index"] for c in captures]
    assert len({key(c) for c in task0}) == 1, ("task 0 should share one rounded geometry",
                                              [key(c) for c in task0])
    assert min(margin(c) for c in task0) > 0.02, "task 0 lies too near a rounding boundary"
    assert len({c["sun"]["azimuth_deg"] for c in task0}) == 3, "task 0's exact sun should differ"
    assert key(task0[0]) != key(task1[0]), "task 1 should have another rounded geometry"
    if moving == "platform":
        alts = [c["pose"]["instrument"]["geodetic"]["altitude_m"] for c in task0]
        assert len(set(alts)) == 3, alts


def header(path):
    """ENVI header → {key: value} (values in braces may span lines)."""
    keys, pending = {}, None
    for line in open(path).read().splitlines()[1:]:
        if pending is not None:
            keys[pending] += "\n" + line
            if "}" in line:
                pending = None
            continue
        if "=" not in line:
            continue
        k, v = (s.strip() for s in line.split("=", 1))
        keys[k] = v
        if v.startswith("{") and "}" not in v:
            pending = k
    return keys


# ENVI data type → array typecode (standard sizes: b 1, h 2, i 4, f 4, d 8, H 2, I 4, q 8, Q 8).
DTYPES = {1: "B", 2: "h", 3: "i", 4: "f", 5: "d", 12: "H", 13: "I", 14: "q", 15: "Q"}


def values(path, hdr):
    data = array(DTYPES[int(hdr["data type"])], open(path, "rb").read())
    if (hdr.get("byte order", "0") == "1") != (sys.byteorder == "big"):
        data.byteswap()
    return data


def describe(a_path, b_path, hdr):
    """How two data files differ, in values."""
    a, b = values(a_path, hdr), values(b_path, hdr)
    if len(a) != len(b):
        return f"{len(a)} values vs {len(b)}"
    diff = [i for i, (x, y) in enumerate(zip(a, b))
            if x != y and not (math.isnan(x) and math.isnan(y))]
    if not diff:
        return "same values, different bytes (NaN payload or -0.0)"
    absd = [abs(a[i] - b[i]) for i in diff]
    rel = [abs(a[i] - b[i]) / max(abs(a[i]), abs(b[i])) for i in diff]
    first = diff[0]
    samples, bands = int(hdr["samples"]), int(hdr["bands"])
    line, rest = divmod(first, samples * bands)
    sample, band = divmod(rest, bands)
    return (f"{len(diff)} of {len(a)} values differ, max |diff| {max(absd):.3g}, max relative "
            f"{max(rel):.3g}; first at line {line} sample {sample} band {band}: "
            f"{a[first]!r} vs {b[first]!r}")


def compare(work, mode, name, captures, files_of, problems):
    """Checks one composition's folder against the full run's; returns the files compared."""
    full, here = os.path.join(work, mode, "full"), os.path.join(work, mode, name)
    expected = sorted(f for c in captures for f in files_of[c])
    expected_all = sorted(expected + [f + ".hdr" for f in expected])
    present = sorted(os.listdir(here))
    if present != expected_all:
        problems.append(f"{mode}/{name}: files {present}, expected {expected_all}")
        return 0
    for f in expected:
        a, b = os.path.join(full, f), os.path.join(here, f)
        ha, hb = header(a + ".hdr"), header(b + ".hdr")
        ha.pop("glint command line", None)
        hb.pop("glint command line", None)
        if ha != hb:
            keys = sorted(k for k in set(ha) | set(hb) if ha.get(k) != hb.get(k))
            problems.append(f"{mode}/{name}: {f}.hdr differs from the full run's in "
                            + "; ".join(f"{k}: {ha.get(k)!r} vs {hb.get(k)!r}" for k in keys))
        if open(a, "rb").read() != open(b, "rb").read():
            problems.append(f"{mode}/{name}: {f} differs from the full run's: "
                            + describe(a, b, ha))
    return len(expected)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bin", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--atmosphere", required=True)
    parser.add_argument("--override")
    parser.add_argument("--moving", choices=["platform", "scene"])
    parser.add_argument("--jobs", type=int, default=2, help="renders run at once")
    args = parser.parse_args()
    work = os.path.abspath(args.work)
    atmosphere = os.path.join(DATA, args.atmosphere)  # an absolute path stays as it is
    write_inputs(work, atmosphere, args.moving)
    schedule = os.path.join(os.path.abspath(args.bin), "glint-schedule")
    render = os.path.join(os.path.abspath(args.bin), "glint-render")

    run([schedule, "sim.jsim", "--seed", SEED, "-o", "all.json", "-q"], work)
    doc = json.load(open(os.path.join(work, "all.json")))
    captures = doc["captures"]
    assert [c["index"] for c in captures] == list(range(5)), [c["index"] for c in captures]
    check_premise(captures, args.moving)
    files_of = {c["index"]: [c["files"]["image"]] + list(c["files"]["truth"]) for c in captures}
    assert all(len(v) == 3 for v in files_of.values()), files_of

    # The compositions: name → (captures, extra glint-render arguments).
    compositions = {"full": (list(range(5)), []), "threads1": (list(range(5)), ["--threads", "1"])}
    for k in range(5):
        run([schedule, "sim.jsim", "--seed", SEED, "--captures", str(k), "-o", f"alone-{k}.json",
             "-q"], work)
        compositions[f"alone-{k}"] = ([k], ["--schedule", f"alone-{k}.json"])
    for sel in ([1, 2], [0, 2, 4], [2, 3]):  # shard 3/3 is {3, 4}
        name = "sel-" + "-".join(map(str, sel))
        selected = dict(doc, captures=[c for c in captures if c["index"] in sel])
        with open(os.path.join(work, name + ".json"), "w") as f:
            json.dump(selected, f)
        compositions[name] = (sel, ["--schedule", name + ".json"])
    shards = []
    for k in (1, 2, 3):
        run([schedule, "sim.jsim", "--seed", SEED, "--shard", f"{k}/3", "-o", f"shard-{k}.json",
             "-q"], work)
        shard = json.load(open(os.path.join(work, f"shard-{k}.json")))
        got = [c["index"] for c in shard["captures"]]
        shards += got
        if got:
            compositions[f"shard-{k}"] = (got, ["--schedule", f"shard-{k}.json"])
    assert sorted(shards) == list(range(5)), shards

    common = ["--seed", SEED, "--convergence", CONVERGENCE, "-q"]
    if args.override:
        common += ["--atmosphere", args.override]
    modes = {"counts": [], "radiance": ["--radiance-only"]}
    jobs = [(mode, name, [render, "sim.jsim", "--output-folder", os.path.join(mode, name)]
             + common + flag + extra)
            for mode, flag in modes.items() for name, (_, extra) in compositions.items()]
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        list(pool.map(lambda job: run(job[2], work), jobs))

    problems = []
    summary = []
    for mode in modes:
        compared = 0
        for name, (sel, _) in compositions.items():
            if name != "full":
                compared += compare(work, mode, name, sel, files_of, problems)
        summary.append(f"ok: {mode}: {len(compositions) - 1} compositions, {compared} files "
                       f"byte-identical to the full run")
    # The comparison is not vacuous: the modes differ, and so do the captures of a task.
    counts = header(os.path.join(work, "counts", "full", files_of[0][0] + ".hdr"))
    radiance = header(os.path.join(work, "radiance", "full", files_of[0][0] + ".hdr"))
    if radiance.get("data units") != "Photons/cm2" or counts.get("data units") == "Photons/cm2":
        problems.append(f"data units: counts {counts.get('data units')!r}, "
                        f"radiance-only {radiance.get('data units')!r}")
    for mode in modes:
        image = [open(os.path.join(work, mode, "full", files_of[k][0]), "rb").read()
                 for k in range(3)]
        if len(set(image)) != 3:
            problems.append(f"{mode}: the three captures of task 0 are not all different")
    if problems:
        print("\n".join(problems))
        return 1
    print("\n".join(summary))
    return 0


if __name__ == "__main__":
    sys.exit(main())
