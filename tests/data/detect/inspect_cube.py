#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Prints what the glint-detect CLI cases check of an ENVI BIP file, one `key = value` line
each: samples, lines, bands, data type, min, max, mean (6 significant digits), the number of
distinct values, and with --pixel X,Y the values of that pixel (all bands). Reads the raw
file with the standard library only, so it is an oracle independent of glint's reader."""
import argparse
import struct
import sys

FORMATS = {1: "B", 2: "h", 3: "i", 4: "f", 5: "d", 12: "H", 13: "I", 14: "q", 15: "Q"}


def header_fields(path):
    fields = {}
    for line in open(path + ".hdr"):
        key, sep, value = line.partition("=")
        if sep:
            fields[key.strip().lower()] = value.strip()
    return fields


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("image")
    p.add_argument("--pixel", action="append", default=[], help="X,Y (0-based)")
    a = p.parse_args()
    h = header_fields(a.image)
    samples, lines, bands = int(h["samples"]), int(h["lines"]), int(h["bands"])
    code = int(h["data type"])
    order = "<" if h.get("byte order", "0") == "0" else ">"
    data = open(a.image, "rb").read()
    n = samples * lines * bands
    values = struct.unpack(order + FORMATS[code] * n, data)
    print("samples = %d" % samples)
    print("lines = %d" % lines)
    print("bands = %d" % bands)
    print("data type = %d" % code)
    print("min = %.6g" % min(values))
    print("max = %.6g" % max(values))
    print("mean = %.6g" % (sum(values) / n))
    print("distinct = %d" % len(set(values)))
    for spec in a.pixel:
        x, y = (int(v) for v in spec.split(","))
        first = (y * samples + x) * bands
        print("pixel %d,%d = %s" % (x, y, " ".join("%.6g" % v for v in values[first:first + bands])))
    return 0


if __name__ == "__main__":
    sys.exit(main())
