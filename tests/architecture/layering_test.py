#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The layering of lib/ holds: each component (lib/CMakeLists.txt, lowest first) links and
includes only components added before it, and no component added before the readers
(dirsig, yaml, inputs) links or includes them — the layers below read no input file: none
of their sources (comments aside) opens a file for reading (std::ifstream, fopen, OpenImageIO)
or calls io's readers (read_input_file, read_text, read_grey_image, EnviReader, ...), except
io itself, whose primitives the readers call, and the files READ_EXCEPTIONS names.

Usage: layering_test.py SOURCE_DIR (exit 0 when it holds, 1 with every violation listed);
layering_test.py --self-test (exit 0 when the checks find what a small planted tree breaks)."""
import pathlib
import re
import sys
import tempfile

import runner

READERS = {"dirsig", "yaml", "inputs"}

# The primitives of reading: what a component below the readers may not call.
READ_CALLS = re.compile(
    r"std::ifstream|std::fstream|\bfopen\s*\(|OIIO::|OpenImageIO/|\bread_text\s*\(|"
    r"\bread_input_file\s*\(|\bread_standard_input\s*\(|\bread_grey_image\b|"
    r"\bread_image\s*\(|\bImageReader\b|\bEnviReader\b|\bBinReader\b|\bread_bin\s*\(")

# Reads below the readers that are known, each with why it is still there. A file listed
# here that no longer reads is a problem too, so the list only shrinks.
READ_EXCEPTIONS = {
    "lib/process/src/trust.cpp":
        "the processing allow-list, a user's setting, not a simulation input",
}


def without_comments(text):
    """C++ text with // and /* */ comments removed (string literals are left as they are)."""
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def components(cmake_text):
    """[(name, {dependencies})] in the order lib/CMakeLists.txt adds them."""
    found = []
    for match in re.finditer(r"glint_add_library\((\w+)(.*?)\)", cmake_text, re.S):
        deps = set(re.findall(r"glint::([\w-]+)", match.group(2)))
        found.append((match.group(1), deps))
    return found


def reads_below_readers(root, name):
    """The problems of component `name`, below the readers: each source that reads a file."""
    problems = []
    for source in sorted((root / "lib" / name).rglob("*")):
        if source.suffix not in {".cpp", ".h"}:
            continue
        relative = source.relative_to(root).as_posix()
        found = READ_CALLS.search(without_comments(source.read_text()))
        if found and relative not in READ_EXCEPTIONS:
            problems.append(f"{relative}: reads a file ({found.group(0)}) but lib/{name} sits "
                            "below the readers: read it in lib/inputs (or dirsig, yaml) and "
                            "hand it model data")
        if not found and relative in READ_EXCEPTIONS:
            problems.append(f"{relative}: listed in READ_EXCEPTIONS but reads no file any more: "
                            "remove it from the list")
    return problems


def check(root):
    """Every problem of the tree at `root`."""
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
        if index < first_reader and name != "io":
            problems.extend(reads_below_readers(root, name))
    for relative in sorted(READ_EXCEPTIONS):
        if not (root / relative).is_file():
            problems.append(f"{relative}: listed in READ_EXCEPTIONS but does not exist")
    return len(ordered), problems


def self_test():
    """Plants a tree whose atmosphere and sensor read files (io's reader, an ifstream, and an
    OIIO call in code, not in a comment) and whose exception list names a file that reads
    nothing; the checks must report exactly those."""
    with tempfile.TemporaryDirectory() as folder:
        root = pathlib.Path(folder)
        files = {
            "lib/CMakeLists.txt": "glint_add_library(core)\nglint_add_library(io)\n"
                                  "glint_add_library(atmosphere)\nglint_add_library(process)\n"
                                  "glint_add_library(sensor)\nglint_add_library(dirsig)\n"
                                  "glint_add_library(yaml)\nglint_add_library(inputs)\n",
            "lib/io/src/read.cpp": "std::ifstream in(path);\n",
            "lib/sensor/src/mask.cpp": "// read_grey_image in a comment is fine\n"
                                       "auto in = OIIO::ImageInput::open(name);\n",
            "lib/sensor/src/psf.cpp": "std::ifstream table(path);\n",
            "lib/dirsig/src/reader.cpp": "std::ifstream in(path);\n",
            "lib/atmosphere/src/solar.cpp": "auto t = io::read_input_file(p, f);\n",
            "lib/process/src/trust.cpp": "double nothing_read = 0;\n",
        }
        for relative, text in files.items():
            (root / relative).parent.mkdir(parents=True, exist_ok=True)
            (root / relative).write_text(text)
        _, problems = check(root)
    expected = ["lib/atmosphere/src/solar.cpp: reads a file (read_input_file",
                "lib/process/src/trust.cpp: listed in READ_EXCEPTIONS",
                "lib/sensor/src/mask.cpp: reads a file (OIIO::)",
                "lib/sensor/src/psf.cpp: reads a file (std::ifstream)"]
    found = sorted(p for p in problems)
    ok = len(found) == len(expected) and all(f.startswith(e) for f, e in zip(found, expected))
    for problem in found:
        print(problem)
    print("self-test " + ("passed" if ok else "FAILED: expected " + "; ".join(expected)))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(runner.run(check, self_test, "components"))
