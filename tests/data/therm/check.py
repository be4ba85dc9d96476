#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Checks glint-render's THERM against an independent NumPy THERM (docs/thermal.md's
equations written again here) for the ground plane of therm.mat under day.wth, at noon and at
02:00 local time (UTC-4, as the tasks write it) on 2020-06-21 at 43 N, 77.6 W:

- the Temperature truth is uniform over the 8 x 6 pixels (one facet pair, no shadow) and equals
  this script's slab within 0.05 K (the truth is stored as float32, 0.003 K; the sun's
  position here is NOAA's low-precision formula, which differs from glint's SPA by about 0.01
  degree, a few mK at noon);
- noon is far above the air (sun), 02:00 below it (a clear sky);
- at 02:00 (no sun, a black sky under the 'none' atmosphere) the radiance is 0.7 B(T), the
  band mean of the 10-11 um tophat, within 1 %.

- shadow.jsim (noon, a 3 m wall south of the view): lines of the view whose ground the wall
  shaded through the morning are at least 15 K cooler than the open ground, the lines it never
  shaded have the open ground's temperature (0.05 K), and none is warmer.

- moving.jsim (shadow.jsim's scene and a THERM van driving past out of view): THERM is solved
  for what stays put, the van casting no shadow in its history, so the Temperature truth is
  shadow.jsim's bit for bit.

Usage: check.py NOON_FOLDER NIGHT_FOLDER [SHADOW_FOLDER [MOVING_FOLDER]]"""
import math
import pathlib
import re
import sys

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
SIGMA = 5.670374419e-8
LAT, LON = 43.0, -77.6


def weather():
    rows = (HERE / "day.wth").read_text().splitlines()[1:]
    number = re.compile(r"[-+]?\d+\.?\d*")
    data = np.array([[float(x) for x in number.findall(r)] for r in rows])
    assert data.shape == (193, 13), data.shape
    langley = 41868.0 / 3600.0
    return {"t": data[:, 0], "air": data[:, 1] + 273.15, "dew": data[:, 4] + 273.15,
            "wind": data[:, 5], "direct": data[:, 6] * langley, "diffuse": data[:, 7] * langley,
            "exposure": data[:, 8]}


def sun_up_component(unix_s):
    """sin(elevation) of the sun at LAT, LON (NOAA's solar position equations)."""
    jd = unix_s / 86400.0 + 2440587.5
    t = (jd - 2451545.0) / 36525.0
    l0 = (280.46646 + t * (36000.76983 + 0.0003032 * t)) % 360.0
    m = 357.52911 + t * (35999.05029 - 0.0001537 * t)
    e = 0.016708634 - t * (0.000042037 + 0.0000001267 * t)
    mr = math.radians(m)
    c = (math.sin(mr) * (1.914602 - t * (0.004817 + 0.000014 * t)) +
         math.sin(2 * mr) * (0.019993 - 0.000101 * t) + math.sin(3 * mr) * 0.000289)
    true_long = l0 + c
    omega = 125.04 - 1934.136 * t
    app_long = true_long - 0.00569 - 0.00478 * math.sin(math.radians(omega))
    eps0 = 23.0 + (26.0 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0
    eps = eps0 + 0.00256 * math.cos(math.radians(omega))
    decl = math.asin(math.sin(math.radians(eps)) * math.sin(math.radians(app_long)))
    y = math.tan(math.radians(eps) / 2) ** 2
    l0r = math.radians(l0)
    eq_time = 4 * math.degrees(y * math.sin(2 * l0r) - 2 * e * math.sin(mr) +
                               4 * e * y * math.sin(mr) * math.cos(2 * l0r) -
                               0.5 * y * y * math.sin(4 * l0r) - 1.25 * e * e * math.sin(2 * mr))
    minutes = (unix_s % 86400.0) / 60.0
    true_solar = (minutes + eq_time + 4 * LON) % 1440.0
    hour_angle = math.radians(true_solar / 4 - 180.0)
    lat = math.radians(LAT)
    return (math.sin(lat) * math.sin(decl) +
            math.cos(lat) * math.cos(decl) * math.cos(hour_angle))


def therm(w, hour, hour_to_unix):
    """The slab of therm.mat (5 cm, insulated back) at weather hour `hour`."""
    k = 12 * 4.1868 / 36.0
    rho_c = 2300.0 * 0.21 * 4186.8
    alpha, eps, exposed, thickness = 0.7, 0.7, 1.0, 0.05
    d = math.sqrt(2 * k / rho_c / (2 * math.pi / 86400.0))
    n = min(max(math.ceil(thickness / (0.1 * d)) + 1, 3), 41)
    dz = thickness / (n - 1)
    width = np.full(n, dz)
    width[0] = width[-1] = dz / 2

    def forcing(h):
        air = np.interp(h, w["t"], w["air"])
        dew = np.interp(h, w["t"], w["dew"])
        td = dew - 273.15
        vapour = 6.112 * math.exp(17.62 * td / (243.12 + td))
        clear = min(1.24 * (vapour / air) ** (1 / 7), 1.0)
        exposure = np.interp(h, w["t"], w["exposure"])
        sky = clear + (1 - clear) * (1 - exposure)
        up = sun_up_component(hour_to_unix(h))
        sun = alpha * (np.interp(h, w["t"], w["direct"]) * max(up, 0.0) * (up > 0) +
                       np.interp(h, w["t"], w["diffuse"]))
        h_conv = 2.8 + 3.0 * np.interp(h, w["t"], w["wind"])
        return sun, sky * SIGMA * air**4, air, h_conv

    t_h = hour - 24.0
    temps = np.full(n, np.interp(t_h, w["t"], w["air"]))
    main = np.zeros(n)
    while t_h < hour - 1e-12:
        dt_h = min(300.0 / 3600.0, hour - t_h)
        sun, lw, air, h_conv = forcing(t_h + dt_h)
        dt = dt_h * 3600.0
        old = temps.copy()
        s = old[0]
        for _ in range(50):
            a = np.zeros((n, n))
            b = rho_c * width / dt * old
            for i in range(n):
                a[i, i] = rho_c * width[i] / dt
                if i > 0:
                    a[i, i] += k / dz
                    a[i, i - 1] = -k / dz
                if i + 1 < n:
                    a[i, i] += k / dz
                    a[i, i + 1] = -k / dz
            flux = sun + eps * (lw - SIGMA * s**4) + exposed * h_conv * (air - s)
            deriv = -4 * eps * SIGMA * s**3 - exposed * h_conv
            a[0, 0] -= deriv
            b[0] += flux - deriv * s
            temps = np.linalg.solve(a, b)
            change = abs(temps[0] - s)
            s = temps[0]
            if change < 1e-10:
                break
        t_h += dt_h
    return temps[0], np.interp(hour, w["t"], w["air"])


def planck_band(temperature_k):
    h, c, kb = 6.62607015e-34, 2.99792458e8, 1.380649e-23
    wl = np.linspace(10.0, 11.0, 101) * 1e-6
    return (2 * h * c**2 / wl**5 / np.expm1(h * c / (wl * kb * temperature_k)) * 1e-10).mean()


def main():
    w = weather()
    noon_utc = 1592755200.0  # 2020-06-21T16:00:00Z = 12:00 at UTC-4
    results = {}
    for name, folder, local_hour in (("noon", sys.argv[1], 12.0), ("02:00", sys.argv[2], 2.0)):
        out = pathlib.Path(folder)
        truth = np.fromfile(out / "truth.img", dtype="<f8")
        assert truth.size == 48 and np.ptp(truth) < 1e-6, truth
        hour = 24.0 + local_hour  # hour 24 is the local midnight that starts the day
        day_start_unix = noon_utc - 12 * 3600.0

        def to_unix(h):
            return day_start_unix + (h - 24.0) * 3600.0

        expected, air = therm(w, hour, to_unix)
        assert abs(truth[0] - expected) < 0.05, (name, truth[0], expected)
        results[name] = (truth[0], expected, air, out)
    noon, night = results["noon"], results["02:00"]
    assert noon[0] > noon[2] + 10.0, noon
    assert night[0] < night[2], night
    radiance = np.fromfile(night[3] / "frame.img", dtype="<f8")
    scale = radiance.mean() / (0.7 * planck_band(night[0]))
    assert abs(scale - 1.0) < 0.01, scale
    shaded_text = ""
    if len(sys.argv) > 3:
        shaded = np.fromfile(pathlib.Path(sys.argv[3]) / "truth.img", dtype="<f8")
        open_ground = noon[0]
        assert shaded.max() < open_ground + 0.05, (shaded.max(), open_ground)
        assert (np.abs(shaded - open_ground) < 0.05).sum() >= 4, shaded
        assert (shaded < open_ground - 15.0).sum() >= 4, shaded
        shaded_text = f", shaded ground down to {shaded.min():.2f} K"
    if len(sys.argv) > 4:
        moving = np.fromfile(pathlib.Path(sys.argv[4]) / "truth.img", dtype="<f8")
        assert np.array_equal(moving, shaded), (moving, shaded)
        shaded_text += ", the same with a van driving past"
    print(f"therm ok{shaded_text}: noon {noon[0]:.3f} K (NumPy {noon[1]:.3f}, air {noon[2]:.2f}), "
          f"02:00 {night[0]:.3f} K (NumPy {night[1]:.3f}, air {night[2]:.2f}), "
          f"radiance / 0.7 B = {scale:.4f}")


if __name__ == "__main__":
    main()
