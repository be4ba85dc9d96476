#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Writes june.wth, the demo site's weather history in DIRSIG's .wth layout (docs/formats.md):
72 h every 0.25 h, local time (EDT) from 2020-06-20 00:00, the same clear early-summer day
three times over. Made up for the demo, not observed data:

- air 21.5 +/- 5.5 C, coolest at 05:00 and warmest at 15:00 (a cosine);
- dew point 12 C (relative humidity from the Magnus formula), pressure 995 mbar (150 m up);
- wind 2.0 m/s at night rising to 3.5 m/s in the afternoon;
- the sun at 43.0 N, 77.6 W on 21 June (declination 23.44 deg, equation of time -1.7 min);
  beam (normal incidence) 1353 * 0.7 ** (m ** 0.678) W/m2 (Meinel and Meinel 1976, m the
  Kasten-Young air mass), diffuse on the horizontal 0.3 * (1353 - beam) * sin(elevation), in
  Langley/h as DIRSIG writes them; no sun below the horizon; a clear sky (exposure 1).

Run it to regenerate the file: /usr/bin/python3 make_weather.py
"""
import math
import pathlib

LANGLEY_PER_HOUR = 41868.0 / 3600.0  # W/m2
LATITUDE_DEG = 43.0
LONGITUDE_DEG = -77.6
UTC_OFFSET_H = -4.0           # EDT
DECLINATION_DEG = 23.44       # 21 June
EQUATION_OF_TIME_H = -1.7 / 60.0
SOLAR_CONSTANT_W_M2 = 1353.0
STEP_H = 0.25
HOURS = 72


def sun_elevation_deg(local_hour):
    solar_time_h = (local_hour - UTC_OFFSET_H + LONGITUDE_DEG / 15.0 + EQUATION_OF_TIME_H) % 24.0
    hour_angle = math.radians(15.0 * (solar_time_h - 12.0))
    lat, dec = math.radians(LATITUDE_DEG), math.radians(DECLINATION_DEG)
    sin_e = math.sin(lat) * math.sin(dec) + math.cos(lat) * math.cos(dec) * math.cos(hour_angle)
    return math.degrees(math.asin(sin_e))


def insolation_w_m2(elevation_deg):
    """(beam at normal incidence, diffuse on the horizontal)."""
    if elevation_deg <= 0.0:
        return 0.0, 0.0
    zenith = 90.0 - elevation_deg
    air_mass = 1.0 / (math.cos(math.radians(zenith)) + 0.50572 * (96.07995 - zenith) ** -1.6364)
    beam = SOLAR_CONSTANT_W_M2 * 0.7 ** (air_mass ** 0.678)
    diffuse = 0.3 * (SOLAR_CONSTANT_W_M2 - beam) * math.sin(math.radians(elevation_deg))
    return beam, diffuse


def saturation_hpa(celsius):
    return 6.1094 * math.exp(17.625 * celsius / (celsius + 243.04))


def main():
    rows = ["%d %.6f" % (int(HOURS / STEP_H) + 1, STEP_H)]
    for i in range(int(HOURS / STEP_H) + 1):
        t = STEP_H * i
        hour = t % 24.0
        air = 21.5 - 5.5 * math.cos(2.0 * math.pi * (hour - 5.0) / 20.0) if 5.0 <= hour <= 15.0 \
            else 21.5 + 5.5 * math.cos(2.0 * math.pi * ((hour - 15.0) % 24.0) / 28.0)
        dew = 12.0
        humidity = min(1.0, saturation_hpa(dew) / saturation_hpa(air))
        wind = 2.0 + 1.5 * max(0.0, math.sin(math.pi * (hour - 8.0) / 14.0))
        beam, diffuse = insolation_w_m2(sun_elevation_deg(hour))
        rows.append("%.2f %6.2f %8.2f %5.2f %6.2f %7.2f %9.2f %9.2f %5.2f %2d %2d %7.2f %6.2f" % (
            t, air, 995.0, humidity, dew, wind, beam / LANGLEY_PER_HOUR,
            diffuse / LANGLEY_PER_HOUR, 1.0, 0, 0, 0.0, air))
    pathlib.Path(__file__).with_name("june.wth").write_text("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
