#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes a small colour filter array mosaic (ENVI, uint16) for the glint-demosaic CLI cases.

The scene is a flat colour field (--rgbp R,G,B,P, default 1200,2000,800,3000) sampled
through the Bayer (--phase rggb|grbg|gbrg|bggr, the 2x2 block from pixel (0,0)) or TrueSense
layout (lines "PGPR", "GPRP", "PBPG", "BPGP"), as docs/tools/glint-demosaic.md defines them.
This is the tests' own sampling code, independent of lib/demosaic. --bands N repeats the
mosaic into N bands (an invalid input for glint-demosaic). --record writes the pattern
(and Bayer phase) into the header as glint-detect does (`glint cfa pattern`, `glint cfa phase`).

    make_mosaic.py OUT.img --pattern truesense --samples 64 --lines 48
"""
import argparse
import struct
import sys

TRUESENSE = ["PGPR", "GPRP", "PBPG", "BPGP"]


def letter(pattern: str, phase: str, x: int, y: int) -> str:
    if pattern == "truesense":
        return TRUESENSE[y % 4][x % 4]
    return phase[(y % 2) * 2 + (x % 2)].upper()


def main() -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("output")
    p.add_argument("--pattern", choices=["bayer", "truesense"], default="bayer")
    p.add_argument("--phase", choices=["rggb", "grbg", "gbrg", "bggr"], default="rggb")
    p.add_argument("--samples", type=int, default=64)
    p.add_argument("--lines", type=int, default=48)
    p.add_argument("--bands", type=int, default=1)
    p.add_argument("--rgbp", default="1200,2000,800,3000")
    p.add_argument("--record", action="store_true")
    a = p.parse_args()
    r, g, b, pan = (int(v) for v in a.rgbp.split(","))
    value = {"R": r, "G": g, "B": b, "P": pan}
    with open(a.output, "wb") as f:
        for y in range(a.lines):
            line = [value[letter(a.pattern, a.phase, x, y)] for x in range(a.samples)]
            for x in range(a.samples):
                f.write(struct.pack("<" + "H" * a.bands, *([line[x]] * a.bands)))
    header = [
        "ENVI",
        "description = {%s %s mosaic of a flat field R,G,B,P = %s}" % (a.pattern, a.phase, a.rgbp),
        "samples = %d" % a.samples,
        "lines = %d" % a.lines,
        "bands = %d" % a.bands,
        "header offset = 0",
        "file type = ENVI Standard",
        "data type = 12",
        "interleave = bip",
        "byte order = 0",
        "data units = DN",
    ]
    if a.record:
        header.append("glint cfa pattern = %s" % a.pattern)
        if a.pattern == "bayer":
            header.append("glint cfa phase = %s" % a.phase)
    with open(a.output + ".hdr", "w") as f:
        f.write("\n".join(header) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
