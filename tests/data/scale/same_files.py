#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Asserts that two output folders hold the same files: the same names, data files equal
# byte for byte, ENVI headers equal line for line except `glint command line` (the run that
# wrote them). Prints "same N files" on success.
# Usage: same_files.py EXPECTED_FOLDER ACTUAL_FOLDER [MIN_FILES]
import os
import sys

expected, actual = sys.argv[1], sys.argv[2]
least = int(sys.argv[3]) if len(sys.argv) > 3 else 1


def listing(folder):
    out = []
    for root, _, files in os.walk(folder):
        out += [os.path.relpath(os.path.join(root, f), folder) for f in files]
    return sorted(out)


a, b = listing(expected), listing(actual)
assert a == b, ('different files', a, b)
assert len(a) >= least, ('too few files', a)
for name in a:
    x = open(os.path.join(expected, name), 'rb').read()
    y = open(os.path.join(actual, name), 'rb').read()
    if name.endswith('.hdr'):
        strip = lambda t: [l for l in t.decode().splitlines()
                           if not l.startswith('glint command line')]
        assert strip(x) == strip(y), (name, set(strip(x)) ^ set(strip(y)))
    else:
        assert x == y, name
print('same %d files' % len(a))
