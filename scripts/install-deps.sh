#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the Debian 12 packages glint needs.
#   scripts/install-deps.sh          everything: the build, the tests and their oracles (make test)
#   scripts/install-deps.sh --demo   only what building the tools and running the demo need
#                                    (make demo): no test framework, oracle, fuzzer or cluster
# Idempotent: asks dpkg what is missing and runs apt-get only for that, so a second run
# on a prepared machine does nothing and needs no network.
set -euo pipefail

demo_packages=(
    # toolchain
    build-essential cmake ninja-build pkg-config
    # libraries (pinned by Debian 12: Embree 3.13, OIIO 2.4, CLI11 2.1, yaml-cpp 0.7,
    # tinyxml2 9, nlohmann_json 3.11)
    libembree-dev libopenimageio-dev libcli11-dev libyaml-cpp-dev libtinyxml2-dev
    nlohmann-json3-dev libtbb-dev libeigen3-dev libgeographiclib-dev zlib1g-dev
    # Debian's OpenImageIO CMake package names its tools (iconvert, oiiotool), so
    # find_package(OpenImageIO) fails without them
    openimageio-tools
    # the program glint runs (the demo's video)
    ffmpeg
)
test_packages=(
    git
    # the test framework (GTest 1.12)
    libgtest-dev libgmock-dev
    # the fuzz targets (scripts/fuzz.sh, docs/testing.md): clang 14 and libFuzzer's runtime
    clang libclang-rt-dev
    # the tools' man pages (generated from --help; optional: skipped without it)
    help2man
    # test oracles
    gdal-bin python3 python3-gdal python3-numpy python3-spectral
    python3-sgp4 python3-astropy python3-opencv jq
    # the one-node Slurm cluster of tests/cluster (examples/slurm): slurmctld, slurmd, sbatch, munged
    slurm-wlm munge
)

case "${1:-}" in
    "") packages=("${demo_packages[@]}" "${test_packages[@]}") ;;
    --demo) packages=("${demo_packages[@]}") ;;
    *) echo "install-deps: unknown option '$1'; usage: scripts/install-deps.sh [--demo]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
    [ "$status" = "installed" ] || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi

echo "install-deps: installing ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
    sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
