#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Regenerates data/atmosphere/aerosol_optics.csv: OPAC's aerosol components
# (data/atmosphere/aerosol_size_distributions.csv, aerosol_refractive_indices.csv) through
# glint's Mie code, averaged over each size distribution (tests/tools/aerosol_tables.cpp;
# docs/physics.md, "Aerosol optics"). Builds the generator in the release preset's tree
# first. Takes 12-17 minutes on 2 cores (the coarse sea salt at short wavelengths dominates).
# Usage: scripts/make-aerosol-tables.sh
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
cmake --preset release >/dev/null
cmake --build --preset release --target aerosol_tables
out=data/atmosphere/aerosol_optics.csv
build/release/tests/aerosol_tables data "$out.tmp"
mv "$out.tmp" "$out"
echo "wrote $out ($(grep -vc '^#' "$out") lines)"
