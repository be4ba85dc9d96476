#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Draw docs/images/atmosphere_direct.png and atmosphere_global.png: glint's parametric
atmosphere at the ASTM G173-03 conditions against the standard's SMARTS 2.9.2 spectra.

The spectra come from the tests that check them (GasAbsorption's direct-normal test and
GlobalTilt's rendered plate), which write them as CSV when GLINT_ATMOSPHERE_PLOT_DIR is set.
Needs python3-matplotlib. Usage (from the repository, after a build):
    scripts/atmosphere_plots.py [--build build/release]
"""

import argparse
import csv
import os
import pathlib
import subprocess
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

REPO = pathlib.Path(__file__).resolve().parent.parent


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def draw(path, wavelengths_nm, x_range, title, curves):
    """One spectral plot: `curves` are (values, colour, line width, label)."""
    fig, ax = plt.subplots(figsize=(9, 4.2), dpi=110)
    for values, colour, width, label in curves:
        ax.plot(wavelengths_nm, values, color=colour, lw=width, label=label)
    ax.set_xlim(*x_range)
    ax.set_xlabel("wavelength (nm)")
    ax.set_ylabel("irradiance (W m$^{-2}$ nm$^{-1}$)")
    ax.set_title(title)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=str(REPO / "build" / "release"))
    parser.add_argument("--output", default=str(REPO / "docs" / "images"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        env = dict(os.environ, GLINT_ATMOSPHERE_PLOT_DIR=work)
        tests = pathlib.Path(args.build) / "tests"
        subprocess.run([str(tests / "test_atmosphere"),
                        "--gtest_filter=ParametricAtmosphereGases.DirectNormal*"],
                       env=env, check=True, stdout=subprocess.DEVNULL)
        subprocess.run([str(tests / "test_radiometry"), "--gtest_filter=GlobalTilt.*"],
                       env=env, check=True, stdout=subprocess.DEVNULL)
        direct = read(pathlib.Path(work) / "direct.csv")
        tilt = read(pathlib.Path(work) / "global_tilt.csv")

    out = pathlib.Path(args.output)
    draw(out / "atmosphere_direct.png", direct["wavelength_nm"], (280, 2500),
         "Direct sun at air mass 1.5, 1976 U.S. Standard Atmosphere, rural aerosol",
         [(direct["extraterrestrial"], "0.75", 0.8, "extraterrestrial (ASTM G173)"),
          (direct["astm_direct"], "tab:orange", 0.9, "direct normal, SMARTS 2.9.2 (ASTM G173)"),
          (direct["glint_direct"], "tab:blue", 0.7, "direct normal, glint (LOWTRAN 7 gas bands)")])
    draw(out / "atmosphere_global.png", tilt["wavelength_nm"], (300, 2500),
         "Global tilt: plate tilted 37° towards the sun, ground albedo 0.2",
         [(tilt["astm_global_tilt"], "tab:orange", 0.9,
           "global on a 37° tilt, SMARTS 2.9.2 (ASTM G173)"),
          (tilt["glint_pi_l"], "tab:blue", 0.7,
           "π·L of a rendered white plate, glint (5 nm bands)")])
    print("wrote", out / "atmosphere_direct.png", "and", out / "atmosphere_global.png")


if __name__ == "__main__":
    main()
