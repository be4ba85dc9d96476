#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The layering of lib/ holds: each component (lib/CMakeLists.txt, lowest first) links and
includes only components added before it, and no component added before the readers
(dirsig, yaml, inputs) links or includes them — the layers below read no input file.

Usage: layering_test.py SOURCE_DIR (exit 0 when it holds, 1 with every violation listed)."""
import pathlib
import re
import sys

READERS = {"dirsig", "yaml", "inputs"}


def components(cmake_text):
    """[(name, {dependencies})] in the order lib/CMakeLists.txt adds them."""
    found = []
    for match in re.finditer(r"glint_add_library\((\w+)(.*?)\)", cmake_text, re.S):
        deps = set(re.findall(r"glint::([\w-]+)", match.group(2)))
        found.append((match.group(1), deps))
    return found


def main():
    root = pathlib.Path(sys.argv[1])
    ordered = components((root / "lib" / "CMakeLists.txt").read_text())
    names = [name for name, _ in ordered]
    own = set(names)
    problems = []
    first_reader = min(names.index(r) for r in READERS)
    for index, (name, deps) in enumerate(ordered):
        allowed = set(names[:index])
        for dep in sorted(deps & own):
            if dep not in allowed:
                problems.append(f"lib/CMakeLists.txt: {name} links {dep}, added after it")
        headers = set()
        for source in (root / "lib" / name).rglob("*"):
            if source.suffix not in {".cpp", ".h"}:
                continue
            for included in re.findall(r'#include "glint/(\w+)/', source.read_text()):
                headers.add(included)
                if included != name and included in own and included not in allowed:
                    problems.append(f"{source.relative_to(root)}: includes glint/{included}/, "
                                    f"a component added after {name}")
        if index < first_reader and (deps | headers) & READERS:
            problems.append(f"lib/{name} uses a reader ({', '.join(sorted((deps | headers) & READERS))}) "
                            "but sits below the readers: hand it model data instead")
    for problem in problems:
        print(problem)
    print(f"{len(ordered)} components checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
