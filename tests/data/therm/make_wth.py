#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes day.wth, the synthetic weather history of glint's THERM fixture: 48 h every 0.25 h
(DIRSIG's layout), the same clear summer day twice: air 20 +/- 6 C peaking at 15:00, dew point
10 C, wind 2 m/s, direct insolation 850 sqrt(sin e) W/m2 and diffuse 100 sin e W/m2 from 06:00
to 18:00 (e the sun's elevation), in Langley/h. Run it to regenerate the file."""
import math
import pathlib

LANGLEY_PER_HOUR = 41868.0 / 3600.0  # W/m2


def main():
    rows = ["193 0.250000"]
    for i in range(193):
        t = 0.25 * i
        hour = t % 24.0
        air = 20.0 + 6.0 * math.cos(2.0 * math.pi * (hour - 15.0) / 24.0)
        elevation = math.sin(math.pi * (hour - 6.0) / 12.0)
        direct = 850.0 * math.sqrt(elevation) if elevation > 0 else 0.0
        diffuse = 100.0 * elevation if elevation > 0 else 0.0
        # DIRSIG's field widths: a negative number runs into the field before it.
        rows.append("%.2f%6.2f %8.2f %5.2f%6.2f %7.2f %9.2f %9.2f %5.2f %2d %2d %7.2f %6.2f" % (
            t, air, 1013.0, 0.5, 10.0, 2.0, direct / LANGLEY_PER_HOUR,
            diffuse / LANGLEY_PER_HOUR, 1.0, 0, 0, 0.0, air))
    pathlib.Path(__file__).with_name("day.wth").write_text("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
