#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Derive glint's gas-absorption band model (data/atmosphere/gas_band_model.csv) from LOWTRAN 7.

LOWTRAN 7 (F. X. Kneizys, E. P. Shettle, L. W. Abreu, J. H. Chetwynd, G. P. Anderson,
W. O. Gallery, J. E. A. Selby, S. A. Clough, "Users Guide to LOWTRAN 7", AFGL-TR-88-0177,
Air Force Geophysics Laboratory, 1988) is a U.S. Government band model of molecular
absorption at 20 cm^-1 resolution, sampled every 5 cm^-1. This script compiles its Fortran
source (the copy in github.com/space-physics/lowtran, src/lowtran/fortran/lowtran7.f, MIT
licence for the wrapper, public domain for LOWTRAN itself; the tables shipped were made from
commit b3b4e0b), runs it for ground-to-space paths through its six model atmospheres at
eight zenith angles without aerosol, and fits, at every wavenumber and for each of three
absorber groups, the band-model law

    T(u) = exp(-tau1 * u^a)

to LOWTRAN's transmittances, where u is the slant absorber amount of the group:

    water   precipitable water along the path, cm (the model atmosphere's column times
            LOWTRAN's own slant-path factor for its water continuum amount)
    ozone   ozone along the path, atm-cm (LOWTRAN's ultraviolet ozone amount)
    mixed   the uniformly mixed gases (O2, CO2, CH4, N2O, CO, the N2 and O2 continua, trace
            gases) in air masses at 1013.25 hPa (LOWTRAN's molecular-scattering amount over
            the 1976 U.S. Standard Atmosphere's vertical amount)

Rayleigh scattering (LOWTRAN's TX(6)) is divided out: glint computes it itself. The groups
are: water = TX(17) * TX(5), ozone = TX(31) * TX(8) below 13,000 cm^-1 and TX(8) above,
mixed = TX(9) / (TX(6) * water * ozone).

Requires gfortran and numpy. Usage:
    scripts/gas_tables/make_gas_tables.py --lowtran PATH/lowtran7.f [--output FILE] [--work DIR]
"""

import argparse
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
REPO = HERE.parent.parent

# LOWTRAN's model atmospheres 1-6 and their precipitable water, cm (G. P. Anderson,
# S. A. Clough, F. X. Kneizys, J. H. Chetwynd, E. P. Shettle, "AFGL Atmospheric Constituent
# Profiles (0-120 km)", AFGL-TR-86-0110, 1986).
MODELS = {
    1: ("tropical", 4.117),
    2: ("mid-latitude summer", 2.924),
    3: ("mid-latitude winter", 0.854),
    4: ("sub-arctic summer", 2.085),
    5: ("sub-arctic winter", 0.418),
    6: ("1976 U.S. Standard", 1.418),
}
# Zenith angles of the paths, degrees (air masses about 1, 1.15, 1.41, 2, 2.5, 3, 4, 5, 6).
ZENITHS_DEG = [0.0, 30.0, 45.0, 60.0, 66.42, 70.53, 75.52, 78.46, 80.4]
# Wavenumbers, cm^-1: 14.29 um to 0.28 um every 5 cm^-1 (LOWTRAN's sampling).
V1, V2, DV = 700.0, 35720.0, 5.0
# Transmittances inside this range inform the fit; outside it a path is transparent or
# saturated (LOWTRAN floors transmittance at 1e-18 or so).
TAU_MIN, TAU_MAX = 1e-6, 25.0
EXPONENT_RANGE = (0.2, 1.5)

PATCHES = [
    # Write LOWTRAN's printed report (absorber amounts) to TAPE6 instead of /dev/null.
    ("OPEN(IPR,FILE=nulunix,STATUS='OLD',ERR=666)",
     "OPEN(IPR,FILE='TAPE6',STATUS='UNKNOWN',ERR=666)"),
    # Return every transmittance component, not only the total.
    ("TXPy(IPython,:) = TX(9)", "TXPy(IPython,:) = TX(1:63)"),
]


def build(lowtran: pathlib.Path, work: pathlib.Path) -> pathlib.Path:
    """Patches and compiles LOWTRAN 7 with the case driver; returns the program."""
    if shutil.which("gfortran") is None:
        sys.exit("make_gas_tables: gfortran not found (apt-get install gfortran)")
    source = lowtran.read_text(encoding="latin-1")
    for old, new in PATCHES:
        if source.count(old) != 1:
            sys.exit(f"make_gas_tables: {lowtran}: expected one '{old}' (another LOWTRAN copy?)")
        source = source.replace(old, new)
    patched = work / "lowtran7_patched.f"
    patched.write_text(source, encoding="latin-1")
    program = work / "lowtran_case"
    subprocess.run(["gfortran", "-O1", "-std=legacy", "-w", str(patched),
                    str(HERE / "lowtran_case.f90"), "-o", str(program)], check=True)
    return program


def amounts(tape6: str) -> dict:
    """The path's equivalent-sea-level absorber amounts LOWTRAN printed."""
    lines = tape6.splitlines()
    start = next(i for i, l in enumerate(lines) if "EQUIVALENT SEA LEVEL TOTAL ABSORBER" in l)
    numbers = []
    for line in lines[start + 1:start + 14]:
        if re.fullmatch(r"\s*([-+0-9.E]+\s*)+", line) and line.strip():
            numbers.append([float(x) for x in line.split()])
    # First row: HNO3, O3 UV, CNTMSLF1, CNTMSLF2, CNTMFRN; second: N2 CONT, MOL SCAT, ...
    return {"o3_atm_cm": numbers[0][1], "water_continuum": numbers[0][4],
            "molecular_scattering": numbers[1][1]}


def run(program: pathlib.Path, work: pathlib.Path, model: int, zenith: float):
    """One case: (wavenumbers, columns, absorber amounts)."""
    case = work / f"m{model}_z{zenith:g}"
    case.mkdir(exist_ok=True)
    out = subprocess.run([str(program), str(model), f"{zenith}", f"{V1}", f"{V2}", f"{DV}"],
                         cwd=case, check=True, capture_output=True, text=True).stdout
    data = np.array([[float(x) for x in line.split()] for line in out.splitlines()])
    return data, amounts((case / "TAPE6").read_text(encoding="latin-1"))


def groups(data: np.ndarray):
    """Water, ozone and mixed-gas transmittances of one case."""
    v, tx5, tx6, tx8, tx9, tx17, tx31 = data.T
    water = tx17 * tx5
    ozone = np.where(v >= 13000.0, tx8, tx31 * tx8)
    # Where water or ozone absorb (nearly) everything, the total says nothing about the
    # mixed gases: those cases are left out of the mixed-gas fit (NaN).
    known = water * ozone > 1e-9
    with np.errstate(divide="ignore", invalid="ignore"):
        mixed = np.where(known, np.clip(tx9 / (tx6 * water * ozone), 0.0, 1.0), np.nan)
    return {"water": water, "ozone": ozone, "mixed": mixed}


def fit(u: np.ndarray, t: np.ndarray):
    """tau1, a of T = exp(-tau1 u^a) from transmittances t at amounts u (one wavenumber);
    NaN transmittances are unknown and left out."""
    known = np.isfinite(t)
    u, t = u[known], t[known]
    if len(t) == 0:
        return 0.0, 1.0
    with np.errstate(divide="ignore"):
        tau = -np.log(np.clip(t, 1e-300, 1.0))
    ok = (tau > TAU_MIN) & (tau < TAU_MAX)
    if ok.sum() >= 2 and np.ptp(np.log(u[ok])) > 0.1:
        a, b = np.polyfit(np.log(u[ok]), np.log(tau[ok]), 1)
        a = float(np.clip(a, *EXPONENT_RANGE))
        tau1 = float(np.exp(np.mean(np.log(tau[ok]) - a * np.log(u[ok]))))
        return tau1, a
    if ok.any():
        # Informative amounts too close together for an exponent: the weak-line law (a = 1).
        return float(np.exp(np.mean(np.log(tau[ok] / u[ok])))), 1.0
    if np.all(tau <= TAU_MIN):
        return 0.0, 1.0
    if np.all(tau >= TAU_MAX):
        # Saturated at every amount: opaque from the smallest amount on.
        return float(TAU_MAX / u.min()), 1.0
    # Transparent at the small amounts and saturated at the large ones, nothing between:
    # the law through the geometric mean of the largest transparent and smallest saturated
    # amounts.
    u_edge = math.sqrt(u[tau <= TAU_MIN].max() * u[tau >= TAU_MAX].min())
    return float(math.sqrt(TAU_MIN * TAU_MAX) / u_edge), 1.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lowtran", required=True, type=pathlib.Path,
                        help="lowtran7.f of github.com/space-physics/lowtran")
    parser.add_argument("--output", type=pathlib.Path,
                        default=REPO / "data" / "atmosphere" / "gas_band_model.csv")
    parser.add_argument("--work", type=pathlib.Path, help="keep the runs here")
    args = parser.parse_args()
    work = args.work or pathlib.Path(tempfile.mkdtemp(prefix="glint-lowtran-"))
    work.mkdir(parents=True, exist_ok=True)
    program = build(args.lowtran, work)

    reference = None
    cases = []
    for model, (_, water_cm) in MODELS.items():
        zenith_amounts = None
        for zenith in ZENITHS_DEG:
            data, a = run(program, work, model, zenith)
            if zenith_amounts is None:
                zenith_amounts = a
            if model == 6 and zenith == 0.0:
                reference = a["molecular_scattering"]
            water = water_cm * a["water_continuum"] / zenith_amounts["water_continuum"]
            cases.append((data, {"water": water, "ozone": a["o3_atm_cm"],
                                 "mixed": a["molecular_scattering"]}))
    for _, u in cases:
        u["mixed"] /= reference
    wavenumbers = cases[0][0][:, 0]
    per_case = [groups(d) for d, _ in cases]

    names = ["water", "ozone", "mixed"]
    params = {}
    residuals = {}
    for name in names:
        u = np.array([c[1][name] for c in cases])
        t = np.array([g[name] for g in per_case])  # [case][wavenumber]
        tau1 = np.zeros(len(wavenumbers))
        expo = np.ones(len(wavenumbers))
        for j in range(len(wavenumbers)):
            tau1[j], expo[j] = fit(u, t[:, j])
        model_t = np.exp(-tau1[None, :] * u[:, None] ** expo[None, :])
        residuals[name] = np.abs(model_t - t)[np.isfinite(t)]
        params[name] = (tau1, expo)

    order = np.argsort(-wavenumbers)  # ascending wavelength
    args.output.parent.mkdir(parents=True, exist_ok=True)
    with open(args.output, "w", encoding="utf-8") as f:
        f.write("# glint gas-absorption band model: T(u) = exp(-tau1 * u^a) per absorber group.\n")
        f.write("# Fitted to LOWTRAN 7 (AFGL-TR-88-0177; 20 cm^-1 resolution, 5 cm^-1 sampling)\n")
        f.write("# ground-to-space paths through its six model atmospheres, no aerosol, zenith\n")
        f.write("# 0-80.4 deg, by scripts/gas_tables/make_gas_tables.py. Rayleigh scattering is\n")
        f.write("# not included. u: water cm of precipitable water, ozone atm-cm, mixed air masses\n")
        f.write("# at 1013.25 hPa (O2, CO2, CH4, N2O, CO, N2/O2 continua, trace gases).\n")
        for name in names:
            r = residuals[name]
            f.write(f"# fit |T_fit - T_lowtran| for {name}: mean {r.mean():.4f}, "
                    f"95th percentile {np.percentile(r, 95):.4f}, max {r.max():.4f}\n")
        f.write("wavelength_um,wavenumber_cm1,water_tau1,water_exponent,"
                "ozone_tau1,ozone_exponent,mixed_tau1,mixed_exponent\n")
        for j in order:
            f.write(f"{1e4 / wavenumbers[j]:.6f},{wavenumbers[j]:.1f}")
            for name in names:
                tau1, expo = params[name]
                f.write(f",{tau1[j]:.5g},{expo[j]:.4f}")
            f.write("\n")
    for name in names:
        r = residuals[name]
        print(f"{name}: |T_fit - T_lowtran| mean {r.mean():.4f}, "
              f"95th percentile {np.percentile(r, 95):.4f}, max {r.max():.4f}")
    print(f"wrote {args.output} ({len(wavenumbers)} wavenumbers); runs in {work}")


if __name__ == "__main__":
    main()
