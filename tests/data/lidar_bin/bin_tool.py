#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""An independent DIRSIG lidar BIN reader and writer, written from the layout table of
docs/lidar-bin.md with the standard library only (struct, zlib), for glint's tests.

  bin_tool.py write OUT.bin --version V --order little|big   writes the sample file below
  bin_tool.py read IN.bin                                     prints the file as JSON
  bin_tool.py check IN.bin                                    compares IN with the sample
  bin_tool.py forge OUT.bin --x X --y Y --bins B --samples S [--claim N]
      a hostile version-2 file of one pulse: X x Y pixels of 1 + B * S zero values, zlib
      compressed a megabyte at a time (a zip bomb when they are many), its data size field
      N when --claim is given (data claimed beyond the end of the file)

The sample: 3 x 2 pixels, 2 tasks (2 pulses, then 1), 4 bins x 2 samples per bin (version 0:
1 sample), values v = 1000 * pulse + 10 * pixel + value index (the passive rate first), the
pixels in file order: pixel p is (x, y) = (p // 2, p % 2), x slowest (docs/lidar-bin.md)."""
import json
import struct
import sys
import zlib

X, Y = 3, 2


def sample():
    tasks = []
    pulse_number = 0
    for t, pulses in enumerate((2, 1)):
        task = {"description": f"task {t}", "start": "20200621T160000", "stop": "20200621T160001",
                "focal_length_mm": 50.0 + t, "pulse_rate_hz": 1000.0, "pulse_duration_s": 5e-9,
                "pulse_energy_j": 1e-3, "laser_center_um": 1.064, "laser_width_um": 0.001, "pulses": []}
        for p in range(pulses):
            task["pulses"].append({"index": pulse_number, "time_s": 0.001 * pulse_number,
                                   "gate": [6.0e-6, 7.0e-6], "bins": 4, "samples": 2,
                                   "location": [1.0, 2.0, 1000.0 + pulse_number], "rotation": [0.1, 0.2, 0.3]})
            pulse_number += 1
        tasks.append(task)
    return {"created": "20200621T160000", "dirsig_version": "glint bin_tool.py",
            "description": "independent sample", "origin": [43.0, -77.6, 150.0],
            "transmitter_mount": "fixed", "receiver_mount": "fixed", "x": X, "y": Y,
            "pitch": [2e-5, 2e-5], "offset": [0.0, 1e-6], "k": [0.01, -0.002], "tasks": tasks}


def values(pulse, samples):
    per_pixel = 1 + pulse["bins"] * samples
    return [1000.0 * pulse["index"] + 10.0 * pixel + i for pixel in range(X * Y) for i in range(per_pixel)]


def write(path, version, order):
    s = sample()
    e = "<" if order == "little" else ">"
    out = bytearray(b"DIRSIGPROTO")
    pack = lambda fmt, *v: out.extend(struct.pack(e + fmt, *v))
    text = lambda t, n: out.extend(t.encode().ljust(n, b"\0")[:n])
    pack("B", version)
    pack("B", 1 if order == "little" else 0)
    text(s["created"], 15)
    text(s["dirsig_version"], 32)
    text(s["description"], 256)
    pack("3d", *s["origin"])
    text(s["transmitter_mount"], 16)
    text(s["receiver_mount"], 16)
    pack("2I", X, Y)
    pack("2d", *s["pitch"])
    if version >= 1:
        pack("2d", *s["offset"])
        pack("2d", *s["k"])
    pack("I", len(s["tasks"]))
    if version >= 2:
        pack("H", 7)
    identity = [1.0 if i % 5 == 0 else 0.0 for i in range(16)]
    for task in s["tasks"]:
        text(task["description"], 64)
        text(task["start"], 15)
        text(task["stop"], 15)
        pack("6d", task["focal_length_mm"], task["pulse_rate_hz"], task["pulse_duration_s"],
             task["pulse_energy_j"], task["laser_center_um"], task["laser_width_um"])
        pack("I", len(task["pulses"]))
        for p in task["pulses"]:
            samples = p["samples"] if version >= 1 else 1
            pack("d", p["time_s"])
            pack("2d", *p["gate"])
            pack("I", p["bins"])
            if version >= 1:
                pack("I", samples)
            pack("3d", *p["location"])
            if version < 2:
                text("xyz", 3)
            pack("3d", *p["rotation"])
            if version >= 2:
                pack("16d", *identity)
            else:
                pack("3d", 0.0, 0.0, 0.5)
                text("xyz", 3)
            pack("3d", 0.0, 0.0, 0.0)
            if version >= 2:
                pack("16d", *identity)
                pack("16d", *identity)
            else:
                pack("3d", 0.0, 0.0, -0.5)
                text("xyz", 3)
            pack("3d", 0.0, 0.0, 0.0)
            if version >= 2:
                pack("16d", *identity)
            data = zlib.compress(struct.pack(e + "%dd" % (X * Y * (1 + p["bins"] * samples)), *values(p, samples)))
            pack("i", 5)
            pack("B", 1)
            if version >= 2:
                pack("I", p["index"])
            else:
                pack("B", 0)
            pack("Q", len(data))
            if version >= 2:
                pack("16d", *identity)
                pack("16d", *identity)
            out.extend(data)
    open(path, "wb").write(bytes(out))


def read(path):
    data = open(path, "rb").read()
    at = [0]

    def take(n):
        chunk = data[at[0]:at[0] + n]
        assert len(chunk) == n, "truncated"
        at[0] += n
        return chunk

    assert take(11) == b"DIRSIGPROTO"
    version, order = struct.unpack("2B", take(2))
    e = "<" if order == 1 else ">"
    u = lambda fmt: struct.unpack(e + fmt, take(struct.calcsize(e + fmt)))
    t = lambda n: take(n).split(b"\0")[0].decode()
    f = {"version": version, "order": "little" if order == 1 else "big", "created": t(15),
         "dirsig_version": t(32), "description": t(256), "origin": list(u("3d")),
         "transmitter_mount": t(16), "receiver_mount": t(16)}
    f["x"], f["y"] = u("2I")
    f["pitch"] = list(u("2d"))
    if version >= 1:
        f["offset"] = list(u("2d"))
        f["k"] = list(u("2d"))
    (task_count,) = u("I")
    if version >= 2:
        (f["focal_plane_id"],) = u("H")
    f["tasks"] = []
    for _ in range(task_count):
        task = {"description": t(64), "start": t(15), "stop": t(15)}
        (task["focal_length_mm"], task["pulse_rate_hz"], task["pulse_duration_s"], task["pulse_energy_j"],
         task["laser_center_um"], task["laser_width_um"]) = u("6d")
        (pulses,) = u("I")
        task["pulses"] = []
        for _ in range(pulses):
            p = {}
            (p["time_s"],) = u("d")
            p["gate"] = list(u("2d"))
            (p["bins"],) = u("I")
            p["samples"] = u("I")[0] if version >= 1 else 1
            p["location"] = list(u("3d"))
            if version < 2:
                t(3)
            p["rotation"] = list(u("3d"))
            if version >= 2:
                u("16d"); u("3d"); u("16d"); u("16d"); u("3d"); u("16d")
            else:
                u("3d"); t(3); u("3d"); u("3d"); t(3); u("3d")
            (dtype,) = u("i")
            (compression,) = u("B")
            if version >= 2:
                (p["index"],) = u("I")
            else:
                u("B")
            (size,) = u("Q")
            if version >= 2:
                u("16d"); u("16d")
            assert dtype == 5 and compression == 1, (dtype, compression)
            raw = zlib.decompress(take(size))
            p["values"] = list(struct.unpack(e + "%dd" % (len(raw) // 8), raw))
            task["pulses"].append(p)
        f["tasks"].append(task)
    assert at[0] == len(data), "bytes after the last pulse"
    return f


def check(path):
    """Compares a BIN file (any version, as glint's bin_rewrite writes it: version 2) with the sample."""
    s, f = sample(), read(path)
    for key in ("created", "dirsig_version", "description", "origin", "transmitter_mount",
                "receiver_mount", "x", "y", "pitch"):
        assert f[key] == s[key], (key, f[key], s[key])
    assert len(f["tasks"]) == len(s["tasks"])
    for task, want in zip(f["tasks"], s["tasks"]):
        for key in ("description", "start", "stop", "focal_length_mm", "pulse_rate_hz",
                    "pulse_duration_s", "pulse_energy_j", "laser_center_um", "laser_width_um"):
            assert task[key] == want[key], (key, task[key], want[key])
        for p, w in zip(task["pulses"], want["pulses"]):
            for key in ("time_s", "gate", "bins", "location", "rotation"):
                assert p[key] == w[key], (key, p[key], w[key])
            assert p["values"] == values(w, p["samples"]), "pulse values differ"
    return f


def forge(path, x, y, bins, samples, claim=None):
    out = bytearray(b"DIRSIGPROTO")
    pack = lambda fmt, *v: out.extend(struct.pack("<" + fmt, *v))
    pack("BB", 2, 1)
    out.extend(b"\0" * (15 + 32 + 256))
    pack("3d", 0.0, 0.0, 0.0)
    out.extend(b"\0" * 32)
    pack("2I", x, y)
    pack("6d", 1e-5, 1e-5, 0.0, 0.0, 0.0, 0.0)
    pack("I", 1)
    pack("H", 0)
    out.extend(b"\0" * (64 + 15 + 15))
    pack("6d", 50.0, 1000.0, 5e-9, 1e-3, 1.064, 0.001)
    pack("I", 1)
    identity = [1.0 if i % 5 == 0 else 0.0 for i in range(16)]
    pack("3d", 0.0, 6e-6, 7e-6)
    pack("2I", bins, samples)
    pack("6d", 0, 0, 0, 0, 0, 0)
    pack("16d", *identity)
    pack("3d", 0, 0, 0)
    pack("16d", *identity)
    pack("16d", *identity)
    pack("3d", 0, 0, 0)
    pack("16d", *identity)
    pack("iBI", 5, 1, 0)
    zeros = (x * y * (1 + bins * samples) * 8) if x * y * (1 + bins * samples) < 2 ** 31 else 0
    z = zlib.compressobj(9)
    data = bytearray()
    chunk = bytes(1 << 20)
    while zeros > 0:
        n = min(zeros, len(chunk))
        data.extend(z.compress(chunk[:n]))
        zeros -= n
    data.extend(z.flush())
    pack("Q", len(data) if claim is None else claim)
    pack("16d", *identity)
    pack("16d", *identity)
    out.extend(data)
    open(path, "wb").write(bytes(out))


if __name__ == "__main__":
    mode = sys.argv[1]
    if mode == "write":
        args = dict(zip(sys.argv[3::2], sys.argv[4::2]))
        write(sys.argv[2], int(args.get("--version", "2")), args.get("--order", "little"))
    elif mode == "read":
        f = read(sys.argv[2])
        for task in f["tasks"]:
            for p in task["pulses"]:
                p["values"] = len(p["values"])
        print(json.dumps(f, indent=1))
    elif mode == "forge":
        args = dict(zip(sys.argv[3::2], sys.argv[4::2]))
        forge(sys.argv[2], int(args["--x"]), int(args["--y"]), int(args["--bins"]),
              int(args["--samples"]), int(args["--claim"]) if "--claim" in args else None)
    elif mode == "check":
        f = check(sys.argv[2])
        print("ok version %d %s" % (f["version"], f["order"]))
