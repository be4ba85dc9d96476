#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Every library source has a test home: each lib/<component>/src/<name>.cpp (those under
lib/io/module/, the image module built apart, aside) either has a unit test of its own name,
tests/unit/<component>/<name>_test.cpp, or a row in docs/testing.md, in the section headed
exactly "## Where each library source is tested", whose first cell is the source's path in
backticks and whose second cell names, in backticks, the test files that cover it
(| `lib/render/src/render_plan.cpp` | `tests/unit/render/render_test.cpp`: ... |).

The table stays true as well as complete: a row whose source does not exist, that names a
test path (a backticked `tests/...` file or folder) that does not exist or no test path at
all, that repeats a source, or that is for a source with a unit test of its own name (the
row is redundant) is a problem too.

Usage: test_homes_test.py SOURCE_DIR (exit 0 when it holds, 1 with every problem listed);
test_homes_test.py --self-test (exit 0 when the checks find what a small planted tree breaks)."""
import pathlib
import re
import sys
import tempfile

import runner

DOC = "docs/testing.md"
HEADING = "## Where each library source is tested"


def own_test(source):
    """tests/unit/<component>/<stem>_test.cpp for lib/<component>/src/<stem>.cpp."""
    component = source.split("/")[1]
    return f"tests/unit/{component}/{pathlib.PurePosixPath(source).stem}_test.cpp"


def library_sources(root):
    """The relative paths of every lib/*/src/*.cpp, sorted (lib/io/module/ is not under src/
    and is left out all the same, should it ever move)."""
    found = []
    for source in sorted((root / "lib").glob("*/src/*.cpp")):
        relative = source.relative_to(root).as_posix()
        if not relative.startswith("lib/io/module/"):
            found.append(relative)
    return found


def cells(line):
    """The cells of a markdown table row (the text between its pipes, stripped)."""
    text = line.strip()
    if text.startswith("|"):
        text = text[1:]
    if text.endswith("|"):
        text = text[:-1]
    return [cell.strip() for cell in text.split("|")]


def table_rows(doc_text):
    """[(line number, cells)] of the table rows in the section HEADING of doc_text (up to the
    next heading of the same or a higher level; fenced code is skipped), the header and
    separator rows left out; None when there is no such section."""
    rows = []
    inside = False
    seen = False
    fenced = False
    for number, line in enumerate(doc_text.splitlines(), start=1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        if re.match(r"#{1,2} ", line):
            inside = line.rstrip() == HEADING
            seen = seen or inside
            continue
        if not inside or not line.lstrip().startswith("|"):
            continue
        row = cells(line)
        if all(re.fullmatch(r":?-+:?", cell) for cell in row):
            continue
        if row and row[0] == "source":
            continue
        rows.append((number, row))
    return rows if seen else None


def check_rows(root, rows, sources):
    """The problems of the table rows, and {source: whether its row is sound} for each source
    that has a row (a source whose row is broken is reported for its row, not again as having
    no home)."""
    problems = []
    covered = {}
    for number, row in rows:
        where = f"{DOC}:{number}"
        first = re.fullmatch(r"`([^`]+)`", row[0]) if row else None
        if first is None or len(row) < 2:
            problems.append(f"{where}: not a row of the form | `lib/<component>/src/<name>.cpp` "
                            "| `tests/...` ... |")
            continue
        source = first.group(1)
        tests = [name for name in re.findall(r"`([^`]+)`", row[1]) if name.startswith("tests/")]
        row_ok = True
        if source in covered:
            problems.append(f"{where}: {source} has a row already")
            continue
        if not (root / source).is_file():
            problems.append(f"{where}: {source} does not exist: remove its row (or fix its path)")
            row_ok = False
        elif source not in sources:
            problems.append(f"{where}: {source} is not a library source "
                            "(lib/<component>/src/<name>.cpp): remove its row")
            row_ok = False
        elif (root / own_test(source)).is_file():
            problems.append(f"{where}: {source} has its own unit test {own_test(source)}: "
                            "remove its row")
            row_ok = False
        if not tests:
            problems.append(f"{where}: {source}: the row names no test path in backticks "
                            "(`tests/...`)")
            row_ok = False
        for test in tests:
            if not (root / test.rstrip("/")).exists():
                problems.append(f"{where}: {source}: {test} does not exist")
                row_ok = False
        covered[source] = row_ok
    return problems, covered


def check(root):
    """(number of sources, every problem of the tree at `root`)."""
    sources = library_sources(root)
    doc = root / DOC
    rows = table_rows(doc.read_text()) if doc.is_file() else None
    problems = []
    if rows is None:
        problems.append(f"{DOC}: no section \"{HEADING}\"")
        rows = []
    row_problems, covered = check_rows(root, rows, set(sources))
    for source in sources:
        if (root / own_test(source)).is_file() or source in covered:
            continue
        problems.append(f"{source}: no test home: add {own_test(source)} or a row in "
                        f"{DOC} (\"{HEADING}\") naming the tests that cover it")
    return len(sources), problems + row_problems


def self_test():
    """Plants a tree with a source that has its own unit test (a), one covered by a row (b), one
    with no home (c, its row in another section does not count), a row that names a missing
    test file (d), a row for a source that does not exist (e), a row for a source with its own
    unit test (a again) and a source under lib/io/module/ (left out); the checks must report
    exactly the problems of c, d, e and the redundant row of a."""
    with tempfile.TemporaryDirectory() as folder:
        root = pathlib.Path(folder)
        files = {
            "lib/x/src/a.cpp": "",
            "lib/x/src/b.cpp": "",
            "lib/x/src/c.cpp": "",
            "lib/x/src/d.cpp": "",
            "lib/io/module/m.cpp": "",
            "tests/unit/x/a_test.cpp": "",
            "tests/cli/x/help.toml": "",
            DOC: "# Testing\n\n## Other\n\n| source | tested by |\n|---|---|\n"
                 "| `lib/x/src/c.cpp` | `tests/unit/x/a_test.cpp` |\n\n"
                 f"{HEADING}\n\nA sentence.\n\n| source | tested by |\n|---|---|\n"
                 "| `lib/x/src/a.cpp` | `tests/unit/x/a_test.cpp` |\n"
                 "| `lib/x/src/b.cpp` | `tests/unit/x/a_test.cpp`: calls `b()`; `tests/cli/x/` |\n"
                 "| `lib/x/src/d.cpp` | `tests/unit/x/d_test.cpp` |\n"
                 "| `lib/x/src/e.cpp` | `tests/cli/x/help.toml` |\n\n## After\n",
        }
        for relative, text in files.items():
            (root / relative).parent.mkdir(parents=True, exist_ok=True)
            (root / relative).write_text(text)
        count, problems = check(root)
    expected = [f"{DOC}:15: lib/x/src/a.cpp has its own unit test",
                f"{DOC}:17: lib/x/src/d.cpp: tests/unit/x/d_test.cpp does not exist",
                f"{DOC}:18: lib/x/src/e.cpp does not exist",
                "lib/x/src/c.cpp: no test home"]
    found = sorted(problems)
    ok = (count == 4 and len(found) == len(expected)
          and all(f.startswith(e) for f, e in zip(found, expected)))
    for problem in found:
        print(problem)
    print("self-test " + ("passed" if ok else "FAILED: expected 4 sources and " +
                          "; ".join(expected)))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(runner.run(check, self_test, "sources"))
