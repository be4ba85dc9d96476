#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes a small float64 BIP ENVI cube for the glint-detect CLI cases.

Every pixel of band b holds VALUES[b] (times 1 + sample index with --ramp, so that pixels
differ); the header gets `data units` and any extra `key=value` pairs given with --key.

    make_cube.py OUT.img --samples 8 --lines 6 --values 1e6,2e6,3e6 --units Photons/cm2 \
        --key "glint focal plane=Frame"
"""
import argparse
import struct
import sys


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("output")
    p.add_argument("--samples", type=int, required=True)
    p.add_argument("--lines", type=int, required=True)
    p.add_argument("--values", required=True, help="one value per band, comma-separated")
    p.add_argument("--units", default="Photons/cm2")
    p.add_argument("--ramp", action="store_true")
    p.add_argument("--key", action="append", default=[], help="extra header entry key=value")
    a = p.parse_args()
    values = [float(v) for v in a.values.split(",")]
    with open(a.output, "wb") as f:
        for _ in range(a.lines):
            for x in range(a.samples):
                scale = (1 + x) if a.ramp else 1
                f.write(struct.pack("<" + "d" * len(values), *[v * scale for v in values]))
    header = [
        "ENVI",
        "samples = %d" % a.samples,
        "lines = %d" % a.lines,
        "bands = %d" % len(values),
        "header offset = 0",
        "file type = ENVI Standard",
        "data type = 5",
        "interleave = bip",
        "byte order = 0",
    ]
    if a.units:
        header.append("data units = " + a.units)
    for entry in a.key:
        key, _, value = entry.partition("=")
        header.append("%s = %s" % (key.strip(), value.strip()))
    with open(a.output + ".hdr", "w") as f:
        f.write("\n".join(header) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
