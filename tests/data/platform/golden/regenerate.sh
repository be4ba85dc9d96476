#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Regenerates the golden --dump-platform outputs beside this script from the test platforms
# in tests/data/platform, with the absolute path of tests/data replaced by $DATA (the CLI
# cases tests/cli/platform2jsim/dump-golden-*.toml compare the same way). Run after a
# deliberate change of the reader or of the "glint-platform" JSON, and review the diff:
#     tests/data/platform/golden/regenerate.sh build/release
set -eu
build=${1:-build/release}
tool="$build/bin/glint-platform2jsim"
here=$(cd "$(dirname "$0")" && pwd)
data=$(cd "$here/../.." && pwd)
for name in minimal two_instruments mounts clocks truth capture_full nanometers; do
    "$tool" -q --dump-platform "$data/platform/$name.platform" |
        sed "s#$data#\$DATA#g" >"$here/$name.json"
done
