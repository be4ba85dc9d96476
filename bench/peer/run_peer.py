#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The peer benchmark driver (bench/peer/README.md): glint-render against Blender Cycles on
the same scene, interleaved, with the machine's other load recorded for every run.

For every (image size, spp, bands) configuration it runs glint, Cycles, glint, Cycles, ...
until each has --repeats quiet runs (or --max-attempts pairs were tried), after one
untimed warm-up run of each. Every run is one process; measured per run:

- wall_s: the whole process, start to exit (the runner's clock);
- render_s: the path tracing phase, from the console line that starts it to the line that
  ends it, each time-stamped by the runner as it arrives (same clock for both):
  glint `-v`: "Starting capture" .. "Samples per pixel" (environment, tracing, unit
  conversion and writing the capture's lines into the output file, which is on a tmpfs);
  Cycles: "Sample 0/N" .. "Finished" (every sample and the film; the EXR is written after);
- prepare_s: process start to the start of render_s (inputs, OBJ parsing, BVH build);
- other load: before the run, the share of the machine busy over --idle-window seconds
  while the runner itself is idle (from /proc/stat) and the 1-minute load average
  (recorded only: the benchmark's own previous run raises it); during the run, the share
  of all cores' time that other processes took (busy jiffies of the machine minus the
  run's own user + system time, over cores x wall time; steal counts as other load).
  A run whose pre-run load exceeds --max-load or whose interference exceeds
  --max-interference is discarded (kept in the JSON, marked, left out of the medians).

Prints a table (medians of the kept runs) and one JSON line; --json writes the full report.
"""
import argparse
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import make_scene  # noqa: E402

CLK_TCK = os.sysconf("SC_CLK_TCK")
NCPU = os.cpu_count() or 1


def cpu_times():
    """(busy, total) jiffies of the whole machine; iowait counts as idle, steal as busy."""
    with open("/proc/stat") as f:
        fields = [int(v) for v in f.readline().split()[1:]]
    idle = fields[3] + (fields[4] if len(fields) > 4 else 0)
    total = sum(fields[:8])
    return total - idle, total


def busy_share(seconds):
    b0, t0 = cpu_times()
    time.sleep(seconds)
    b1, t1 = cpu_times()
    return (b1 - b0) / (t1 - t0) if t1 > t0 else 0.0


def loadavg1():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def run_timed(cmd, cwd, start_patterns, end_patterns, log_path):
    """Runs cmd; returns wall time, the times (relative to the start) of the first line
    matching a start pattern and the first matching an end pattern after it, the run's own
    CPU time, the interference, the exit status."""
    lines = []
    lock = threading.Lock()
    b0, tot0 = cpu_times()
    t0 = time.monotonic()
    proc = subprocess.Popen(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE)

    def reader(stream, name):
        for raw in iter(stream.readline, b""):
            t = time.monotonic() - t0
            with lock:
                lines.append((t, name, raw.decode("utf-8", "replace").rstrip("\n")))
        stream.close()

    threads = [threading.Thread(target=reader, args=(proc.stdout, "out")),
               threading.Thread(target=reader, args=(proc.stderr, "err"))]
    for th in threads:
        th.start()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - t0
    b1, tot1 = cpu_times()
    for th in threads:
        th.join()
    proc.returncode = os.waitstatus_to_exitcode(status)
    own_jiffies = (usage.ru_utime + usage.ru_stime) * CLK_TCK
    busy = b1 - b0
    total = tot1 - tot0
    interference = max(0.0, (busy - own_jiffies) / total) if total > 0 else None
    lines.sort(key=lambda x: x[0])
    with open(log_path, "w") as f:
        f.write("$ " + " ".join(cmd) + "\n")
        for t, name, text in lines:
            f.write("%9.4f %s %s\n" % (t, name, text))
    start = end = None
    for t, _, text in lines:
        if start is None and any(re.search(p, text) for p in start_patterns):
            start = t
        elif start is not None and any(re.search(p, text) for p in end_patterns):
            end = t
            break
    return {
        "returncode": proc.returncode,
        "wall_s": wall,
        "prepare_s": start,
        "render_s": (end - start) if start is not None and end is not None else None,
        "cpu_s": usage.ru_utime + usage.ru_stime,
        "max_rss_mb": usage.ru_maxrss / 1024.0,
        "interference": interference,
        "lines": lines,
    }


def cycles_internal_render_s(lines):
    """Cycles' own clock (the 'Time:' field, 10 ms resolution) from 'Sample 0/N' to
    'Finished': a cross-check of the runner's time stamps."""
    def clock(text):
        m = re.search(r"Time:(\d+):(\d+\.\d+)", text)
        return int(m.group(1)) * 60 + float(m.group(2)) if m else None
    start = end = None
    for _, _, text in lines:
        tail = text.rsplit("|", 1)[-1].strip()
        if start is None and re.match(r"Sample 0/\d+", tail):
            start = clock(text)
        elif start is not None and tail == "Finished":
            end = clock(text)
            break
    return (end - start) if start is not None and end is not None else None


def read_envi_means(img):
    hdr = {}
    with open(img + ".hdr") as f:
        text = f.read()
    for m in re.finditer(r"^([^=\n]+?)\s*=\s*(\{[^}]*\}|[^\n]*)", text, re.M):
        hdr[m.group(1).strip()] = m.group(2).strip()
    samples, lines_, bands = int(hdr["samples"]), int(hdr["lines"]), int(hdr["bands"])
    dtype = {"4": np.float32, "5": np.float64}[hdr["data type"]]
    assert hdr.get("interleave", "bsq").lower() == "bip"
    data = np.fromfile(img, dtype=dtype).reshape(lines_, samples, bands)
    wl = None
    if "wavelength" in hdr:
        wl = [float(v) for v in hdr["wavelength"].strip("{}").replace("\n", " ").split(",")]
    return data.reshape(-1, bands).mean(axis=0).astype(float).tolist(), wl


def median(values):
    return statistics.median(values) if values else None


def main():
    ap = argparse.ArgumentParser(description=" ".join(__doc__.split("\n\n")[0].split()))
    ap.add_argument("--bin", required=True, help="folder of glint-render, glint-schedule, glint-envi")
    ap.add_argument("--work", required=True, help="scene folder (the OBJ is cached here)")
    ap.add_argument("--out", default=None, help="keep logs and the JSON report here")
    ap.add_argument("--blender", default="blender", help="the blender program")
    ap.add_argument("--sizes", default="1024", help="image sides in pixels, comma-separated")
    ap.add_argument("--spp", default="1,4,16", help="samples per pixel, comma-separated")
    ap.add_argument("--bands", default="3,32", help="glint band counts (Cycles: always RGB)")
    ap.add_argument("--repeats", type=int, default=3, help="quiet runs wanted of each")
    ap.add_argument("--max-attempts", type=int, default=None,
                    help="most glint+Cycles pairs per configuration (default 2 x repeats)")
    ap.add_argument("--threads", type=int, default=2, help="threads of both renderers")
    ap.add_argument("--max-bounces", type=int, default=8, help="both renderers get it")
    ap.add_argument("--min-bounces", type=int, default=2,
                    help="Cycles min light bounces: no Russian roulette at bounces 0..N "
                         "(glint starts it with its 3rd continuation ray)")
    ap.add_argument("--max-load", type=float, default=0.10,
                    help="discard a run when the machine was busier than this before it")
    ap.add_argument("--max-interference", type=float, default=0.05,
                    help="discard a run when other processes took more than this share")
    ap.add_argument("--idle-window", type=float, default=1.0,
                    help="seconds over which the pre-run load is measured")
    ap.add_argument("--wait-quiet", type=float, default=0.0,
                    help="before a run, wait up to this many seconds for the pre-run load to "
                         "drop below --max-load (0: measure once and go)")
    ap.add_argument("--scratch", default="/dev/shm" if os.path.isdir("/dev/shm") else None,
                    help="where the images are written (a tmpfs: glint fsyncs its output)")
    ap.add_argument("--quick", action="store_true",
                    help="256 x 256, spp 1 and 4, bands 3 and 32, 1 repeat: checks the script")
    ap.add_argument("--canopy", type=int, default=0,
                    help="render the canopy scene of this many instanced trees of transmitting "
                         "leaves instead of the terrain (make_scene.py --canopy)")
    ap.add_argument("--view-zenith", type=float, default=0.0,
                    help="camera tilt from nadir, degrees (make_scene.py --view-zenith)")
    ap.add_argument("--json", default=None, help="write the full report here")
    args = ap.parse_args()
    if args.quick:
        args.sizes, args.spp, args.repeats = "256", "1,4", 1
    if args.max_attempts is None:
        args.max_attempts = 2 * args.repeats
    sizes = [int(v) for v in args.sizes.split(",")]
    spps = [int(v) for v in args.spp.split(",")]
    bandss = [int(v) for v in args.bands.split(",")]
    binp = os.path.abspath(args.bin)
    work = os.path.abspath(args.work)
    out = os.path.abspath(args.out) if args.out else tempfile.mkdtemp(prefix="glint-peer-")
    os.makedirs(os.path.join(out, "logs"), exist_ok=True)

    subprocess.run([sys.executable, os.path.join(HERE, "make_scene.py"), work,
                    "--sizes", ",".join(map(str, sizes)), "--bands", ",".join(map(str, bandss))]
                   + (["--canopy", str(args.canopy)] if args.canopy else [])
                   + ["--view-zenith", str(args.view_zenith)],
                   check=True)
    with open(os.path.join(work, "peer.json")) as f:
        peer = json.load(f)

    # The sun glint computes (NREL SPA) for the scene's date, time and place: Cycles gets the
    # very same direction.
    first_jsim = os.path.join(work, "peer-%d-b%d.jsim" % (sizes[0], bandss[0]))
    sched = json.loads(subprocess.run([os.path.join(binp, "glint-schedule"), first_jsim],
                                      check=True, capture_output=True, text=True).stdout)
    sun = sched["captures"][0]["sun"]
    sun_dir = ",".join("%.12g" % v for v in sun["direction_enu"])
    cos_sun = sun["direction_enu"][2]

    blender_version = subprocess.run([args.blender, "--version"], capture_output=True,
                                     text=True).stdout.splitlines()[0].strip()
    glint_version = subprocess.run([os.path.join(binp, "glint-render"), "--version"],
                                   capture_output=True, text=True).stdout.strip()
    print("peer benchmark: %s vs %s (Cycles, CPU), %d threads, %d cores; %d triangles; sun "
          "zenith %.3f deg azimuth %.3f deg; max bounces %d; logs in %s"
          % (glint_version, blender_version, args.threads, NCPU, peer["triangles"],
             sun["zenith_deg"], sun["azimuth_deg"], args.max_bounces, out), file=sys.stderr)

    d_au = peer["earth_sun_distance_au"]
    rho, sky = peer["reflectance"], peer["sky_radiance"]

    def expected(e_sun):  # flat patch in the sun: rho (E cos / pi + L_sky)
        return rho * (e_sun * cos_sun / math.pi + sky)

    scratch_root = tempfile.mkdtemp(prefix="glint-peer-", dir=args.scratch)

    def glint_cmd(px, bands, spp, folder):
        return [os.path.join(binp, "glint-render"), os.path.join(work, "peer-%d-b%d.jsim" % (px, bands)),
                "--convergence", "%d,%d,0" % (spp, spp), "--threads", str(args.threads),
                "--max-bounces", str(args.max_bounces), "--output-folder", folder,
                "--no-processing", "-v"]

    def cycles_cmd(px, spp, folder):
        return [args.blender, "-b", "--factory-startup", "-noaudio", "-t", str(args.threads),
                "-P", os.path.join(HERE, "cycles_render.py"), "--", "--work", work,
                "--px", str(px), "--spp", str(spp), "--threads", str(args.threads),
                "--max-bounces", str(args.max_bounces), "--min-bounces", str(args.min_bounces),
                "--sun-dir=" + sun_dir, "--exr", os.path.join(folder, "cycles.exr"),
                "--json", os.path.join(folder, "cycles.json")]

    def one_run(engine, px, bands, spp, attempt, measure_image):
        label = "%s-%d-b%d-spp%d-%s" % (engine, px, bands, spp, attempt)
        folder = os.path.join(scratch_root, label)
        os.makedirs(folder)
        pre_load = busy_share(args.idle_window)
        waited = args.idle_window
        while pre_load > args.max_load and waited < args.wait_quiet:
            pre_load = busy_share(args.idle_window)
            waited += args.idle_window
        la = loadavg1()
        if engine == "glint":
            r = run_timed(glint_cmd(px, bands, spp, folder), work,
                          [r"Starting capture"], [r"Samples per pixel"],
                          os.path.join(out, "logs", label + ".log"))
        else:
            cmd = cycles_cmd(px, spp, folder)
            if attempt == "warmup":  # untimed: Cycles' log says which kernels and BVH it uses
                cmd.insert(1, "--debug-cycles")
            r = run_timed(cmd, work,
                          [r"\| Sample 0/\d+$"], [r"\| Finished$"],
                          os.path.join(out, "logs", label + ".log"))
            r["render_s_cycles_clock"] = cycles_internal_render_s(r["lines"])
            js = os.path.join(folder, "cycles.json")
            if os.path.exists(js):
                with open(js) as f:
                    cj = json.load(f)
                r["obj_import_s"] = cj.get("obj_import_s")
                r["cycles_settings"] = cj.get("settings")
                r["triangles"] = cj.get("triangles")
        lines = r.pop("lines")
        if engine == "cycles" and attempt == "warmup":
            info.extend(sorted({re.sub(r"^I\d+ [\d:.]+ +\d+ ", "", t) for _, _, t in lines if re.search(
                r"CPU kernels|Using \w+ layout|Number of lights|TBB threads|Path tracing on", t)}))
        r.update({"engine": engine, "px": px, "bands": bands, "spp": spp, "attempt": attempt,
                  "pre_load": pre_load, "loadavg1": la})
        reasons = []
        if r["returncode"] != 0:
            reasons.append("exit %d" % r["returncode"])
            sys.stderr.write("".join("    %s\n" % t for _, _, t in lines[-15:]))
        if r["render_s"] is None:
            reasons.append("no render phase in the log")
        if pre_load > args.max_load:
            reasons.append("machine %.0f%% busy before" % (100 * pre_load))
        if r["interference"] is not None and r["interference"] > args.max_interference:
            reasons.append("%.0f%% other load during" % (100 * r["interference"]))
        r["kept"] = not reasons
        r["discarded_because"] = "; ".join(reasons) or None
        if measure_image and r["returncode"] == 0 and attempt != "warmup":
            if engine == "glint":
                means, wl = read_envi_means(os.path.join(folder, "glint.img"))
                exp = expected(make_scene.solar_irradiance(
                    os.path.join(HERE, "..", "..", "data"), wl) / d_au ** 2)
            else:
                img = os.path.join(folder, "cycles.img")
                subprocess.run([os.path.join(binp, "glint-envi"), "convert", "-q",
                                os.path.join(folder, "cycles.exr"), img], check=True)
                means, _ = read_envi_means(img)
                exp = np.array([expected(e) for e in peer["sun_irradiance_rgb"]])
            r["mean_radiance"] = means
            r["expected_flat"] = list(map(float, exp))
            r["mean_over_expected"] = float(np.mean(np.array(means) / np.array(exp)))
        shutil.rmtree(folder, ignore_errors=True)
        print("  %-6s %4d px %2d bands %3d spp #%-6s render %8.3f s  wall %8.3f s  pre-load %3.0f%%"
              "  other %3.0f%%  load1 %.2f%s"
              % (engine, px, bands, spp, attempt, r["render_s"] or float("nan"), r["wall_s"],
                 100 * pre_load, 100 * (r["interference"] or 0.0), la,
                 "" if r["kept"] else "  DISCARDED: " + r["discarded_because"]),
              file=sys.stderr)
        return r

    runs = []
    info = []  # what Cycles' debug log says about its kernels, BVH and lights (warm-up run)
    try:
        # Warm-up: the OBJ into the page cache, Blender's and glint's libraries loaded once.
        runs.append(one_run("glint", sizes[0], bandss[0], spps[0], "warmup", False))
        runs.append(one_run("cycles", sizes[0], bandss[0], spps[0], "warmup", False))
        for px in sizes:
            for bands in bandss:
                for spp in spps:
                    kept = {"glint": 0, "cycles": 0}
                    attempt = 0
                    while attempt < args.max_attempts and min(kept.values()) < args.repeats:
                        for engine in ("glint", "cycles"):  # A B A B ...
                            if kept[engine] >= args.repeats:
                                continue
                            r = one_run(engine, px, bands, spp, str(attempt + 1),
                                        measure_image=not any(
                                            x.get("mean_radiance") for x in runs
                                            if x["engine"] == engine and x["px"] == px
                                            and x["bands"] == bands and x["spp"] == spp))
                            runs.append(r)
                            kept[engine] += r["kept"]
                        attempt += 1
    finally:
        shutil.rmtree(scratch_root, ignore_errors=True)

    rows = []
    for px in sizes:
        for bands in bandss:
            for spp in spps:
                sel = {e: [r for r in runs if r["engine"] == e and r["px"] == px and r["bands"] == bands
                           and r["spp"] == spp and r["attempt"] != "warmup"] for e in ("glint", "cycles")}
                row = {"px": px, "spp": spp, "bands": bands, "cycles_channels": 3}
                for e in ("glint", "cycles"):
                    kept = [r for r in sel[e] if r["kept"]]
                    use = kept or [r for r in sel[e] if r["render_s"] is not None]
                    row[e + "_render_s"] = median([r["render_s"] for r in use])
                    row[e + "_wall_s"] = median([r["wall_s"] for r in use])
                    row[e + "_prepare_s"] = median([r["prepare_s"] for r in use])
                    if e == "cycles":
                        row["cycles_obj_import_s"] = median(
                            [r["obj_import_s"] for r in use if r.get("obj_import_s") is not None])
                    row[e + "_kept"] = len(kept)
                    row[e + "_runs"] = len(sel[e])
                    row[e + "_noisy"] = not kept
                    m = [r["mean_over_expected"] for r in sel[e] if r.get("mean_over_expected")]
                    row[e + "_mean_over_expected"] = m[0] if m else None
                g, c = row["glint_render_s"], row["cycles_render_s"]
                row["render_ratio"] = g / c if g and c else None
                g, c = row["glint_wall_s"], row["cycles_wall_s"]
                row["wall_ratio"] = g / c if g and c else None
                g, c = row["glint_mean_over_expected"], row["cycles_mean_over_expected"]
                row["radiance_ratio"] = g / c if g and c else None
                rows.append(row)

    def f(v, fmt="%.3f"):
        return fmt % v if v is not None else "-"

    print("| px | spp | bands (glint / Cycles) | glint render s | Cycles render s | ratio | "
          "glint wall s | Cycles wall s | ratio | kept glint / Cycles | mean/flat glint / Cycles |")
    print("|---:|---:|---|---:|---:|---:|---:|---:|---:|---|---|")
    for row in rows:
        print("| %d | %d | %d / %d | %s | %s | %s | %s | %s | %s | %d/%d / %d/%d%s | %s / %s |" % (
            row["px"], row["spp"], row["bands"], row["cycles_channels"],
            f(row["glint_render_s"]), f(row["cycles_render_s"]), f(row["render_ratio"], "%.2f"),
            f(row["glint_wall_s"]), f(row["cycles_wall_s"]), f(row["wall_ratio"], "%.2f"),
            row["glint_kept"], row["glint_runs"], row["cycles_kept"], row["cycles_runs"],
            " (noisy: all runs used)" if row["glint_noisy"] or row["cycles_noisy"] else "",
            f(row["glint_mean_over_expected"], "%.4f"), f(row["cycles_mean_over_expected"], "%.4f")))
    if info:
        print("Cycles: " + "; ".join(info))
    discarded = [r for r in runs if not r["kept"] and r["attempt"] != "warmup"]
    if discarded:
        print("discarded %d of %d timed runs (medians use the kept runs; a row with none kept "
              "uses all its runs and says noisy): %s" % (
            len(discarded), sum(r["attempt"] != "warmup" for r in runs), "; ".join(
                "%s %dpx b%d spp%d #%s: %s" % (r["engine"], r["px"], r["bands"], r["spp"],
                                               r["attempt"], r["discarded_because"])
                for r in discarded)))
    print("ratio = glint / Cycles (below 1: glint faster). render = path tracing phase; wall = "
          "whole process. mean/flat = image mean / rho (E cos(sun zenith) / pi + L_sky) of a "
          "flat sunlit patch, each renderer against its own sun and sky.")
    report = {
        "bench": "peer",
        "glint": glint_version,
        "blender": blender_version,
        "threads": args.threads,
        "cores": NCPU,
        "triangles": peer["triangles"],
        "sun": sun,
        "max_bounces": args.max_bounces,
        "cycles_min_light_bounces": args.min_bounces,
        "max_load": args.max_load,
        "max_interference": args.max_interference,
        "quick": args.quick,
        "cycles_info": info,
        "results": rows,
    }
    print(json.dumps(report, separators=(",", ":")))
    report["runs"] = runs
    path = args.json or os.path.join(out, "peer.json")
    with open(path, "w") as fjson:
        json.dump(report, fjson, indent=1)
    print("full report (every run): %s" % path, file=sys.stderr)


if __name__ == "__main__":
    main()
