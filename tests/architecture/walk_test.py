#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The walk of one render in docs/architecture.md, the section headed exactly "## One render,
from `main` to the pixel written", holds to the code:

1. its hops (the items "1. ", "2. ", ...) are numbered 1..N with no gap, N <= 15, and its first
   paragraph says "re-counted from the code: N hops" with that N;
2. each hop names the component it enters in its first parenthetical whose first item is a
   lib/ folder ("(inputs)", "(render, `render.cpp`)"); leaving out the shell (core, app_*),
   each component is entered in one hop only, and those entered, in hop order, are the list the
   first paragraph gives after "in pipeline order:", as many as its "enters <number> library
   components" says (eight at most);
3. every code name in backticks exists: a path (with "/") under SOURCE_DIR, a file name
   (.cpp, .h) under lib/ or tools/, the last part of a qualified name (a::b) as a word under
   lib/ or tools/ (under lib/a/ when a is a component), and an identifier with an underscore or
   an inner capital (make_render_inputs, PixelRaySource) as a word under lib/ or tools/.

Usage: walk_test.py SOURCE_DIR (exit 0 when it holds, 1 with every problem listed);
walk_test.py --self-test (exit 0 when the checks find what a small planted tree breaks)."""
import pathlib
import re
import sys
import tempfile

import runner

DOC = "docs/architecture.md"
HEADING = "## One render, from `main` to the pixel written"
MOST_HOPS = 15
MOST_COMPONENTS = 8
NUMBERS = {word: value for value, word in enumerate(
    "zero one two three four five six seven eight nine ten eleven twelve thirteen fourteen "
    "fifteen".split())}


def blocks(doc_text):
    """[(where, text)] of the section HEADING: "intro" (the text before the first hop), then
    "hop N" for each numbered item (its lines up to a blank line or the next item) and "after
    the hops" for anything else; None when there is no such section."""
    lines = doc_text.splitlines()
    if HEADING not in (line.rstrip() for line in lines):
        return None
    start = [line.rstrip() for line in lines].index(HEADING) + 1
    found = [["intro", []]]
    for line in lines[start:]:
        if line.startswith("## "):
            break
        item = re.match(r"(\d+)\. ", line)
        if item:
            found.append([f"hop {item.group(1)}", []])
        elif not line.strip() and found[-1][0].startswith("hop"):
            found.append(["after the hops", []])
        found[-1][1].append(line.strip())
    return [(where, " ".join(text).strip()) for where, text in found]


def first_paragraph(doc_text):
    """The section's first paragraph, its lines joined by spaces."""
    section = doc_text.split(HEADING, 1)[1].strip()
    return " ".join(section.split("\n\n", 1)[0].split())


def entered(text, names):
    """The component a hop enters: the first item of its first parenthetical that is a lib/
    folder, or None."""
    for inside in re.findall(r"\(([^()]*)\)", text.replace("()", "")):
        first = inside.split(",")[0].strip()
        if first in names:
            return first
    return None


def check_hops(intro, hops, names):
    """The problems of the hops' numbering and of the components they enter."""
    problems = []
    numbers = [int(where.split()[1]) for where, _ in hops]
    if numbers != list(range(1, len(numbers) + 1)):
        problems.append(f"{DOC}: the hops are numbered {numbers}, not 1..{len(numbers)}")
    if len(numbers) > MOST_HOPS:
        problems.append(f"{DOC}: the walk has {len(numbers)} hops, more than {MOST_HOPS}")
    stated = re.search(r"re-counted from the code: (\d+) hops", intro)
    if not stated or int(stated.group(1)) != len(numbers):
        problems.append(f"{DOC}: intro: the first paragraph does not say \"re-counted from the "
                        f"code: {len(numbers)} hops\" ({len(numbers)} numbered hops)")
    order, first_hop = [], {}
    for where, text in hops:
        name = entered(text, names)
        if name is None or name == "core" or name.startswith("app_"):
            continue
        if name in first_hop:
            problems.append(f"{DOC}: {where}: enters {name} again (entered in {first_hop[name]}): "
                            "each component is entered in one hop")
            continue
        first_hop[name] = where
        order.append(name)
    sentence = re.search(r"in pipeline order:(.*?)\.(\s|$)", intro)
    # The backticked names of the sentence, their parenthesised roles left out.
    listed = sentence and re.findall(r"`([^`]+)`", re.sub(r"\([^()]*\)", "", sentence.group(1)))
    if sentence is None:
        problems.append(f"{DOC}: intro: the first paragraph gives no list \"in pipeline order:\"")
    elif listed != order:
        problems.append(f"{DOC}: intro: the pipeline order {listed} is not the order the hops "
                        f"enter the components, {order}")
    count = re.search(r"enters (\w+) library components", intro)
    word = count.group(1).lower() if count else ""
    value = int(word) if word.isdigit() else NUMBERS.get(word)
    if value != len(order):
        problems.append(f"{DOC}: intro: the first paragraph does not say \"enters "
                        f"{len(order)} library components\" (the hops enter {len(order)})")
    if len(order) > MOST_COMPONENTS:
        problems.append(f"{DOC}: the hops enter {len(order)} library components, more than "
                        f"{MOST_COMPONENTS}")
    return problems


def code_words(root):
    """({top: set of words}, set of file names) of the .h and .cpp files under lib/ and tools/,
    where top is "lib/<component>", "tools" or "*" (all of them)."""
    words, files = {}, set()
    for top in ("lib", "tools"):
        for source in sorted((root / top).rglob("*")):
            if source.suffix not in {".cpp", ".h"} or not source.is_file():
                continue
            files.add(source.name)
            parts = source.relative_to(root).parts
            key = "tools" if top == "tools" else f"lib/{parts[1]}"
            found = re.findall(r"[A-Za-z_]\w*", source.read_text(errors="replace"))
            words.setdefault(key, set()).update(found)
            words.setdefault("*", set()).update(found)
    return words, files


def missing_name(root, token, names, words, files):
    """Why `token` (backticked in the walk) names nothing in the code, or None when it does or
    is no code name."""
    if (not token or " " in token or token[0] in "<-." or token in names):
        return None
    token = token[:-2] if token.endswith("()") else token
    everywhere = words.get("*", set())
    if "/" in token:
        return None if (root / token.rstrip("/")).exists() else "no such path"
    if token.endswith((".cpp", ".h")):
        return None if token in files else "no such file under lib/ or tools/"
    if "::" in token:
        parts = token.split("::")
        last = re.sub(r"<.*$", "", parts[-1])
        if parts[0] in names:
            inside = words.get(f"lib/{parts[0]}", set())
            return None if last in inside else f"{last} is not a word under lib/{parts[0]}/"
        return None if last in everywhere else f"{last} is not a word under lib/ or tools/"
    if re.fullmatch(r"\w+", token) and ("_" in token or re.search(r"[A-Z]", token[1:])):
        return None if token in everywhere else "not a word under lib/ or tools/"
    return None


def check(root):
    """(number of hops, every problem of the tree at `root`)."""
    doc = root / DOC
    found = blocks(doc.read_text()) if doc.is_file() else None
    if found is None:
        return 0, [f"{DOC}: no section \"{HEADING}\""]
    names = {p.name for p in (root / "lib").iterdir() if p.is_dir()}
    hops = [(where, text) for where, text in found if where.startswith("hop ")]
    problems = check_hops(first_paragraph(doc.read_text()), hops, names)
    words, files = code_words(root)
    for where, text in found:
        for token in re.findall(r"`([^`]+)`", text):
            why = missing_name(root, token.strip(), names, words, files)
            if why:
                problems.append(f"{DOC}: {where}: `{token}`: {why}")
    return len(hops), problems


def self_test():
    """Plants a walk whose hops skip 3, whose paragraph counts 3 hops and six components in
    another order, whose hop 4 enters b again (a parenthetical of a non-component before it
    is passed over), and that names a missing file, path, function and b::Missing; a walk of
    16 hops entering nine components, stated as such; and a sound walk of the same tree,
    which must pass."""
    intro = (f"# A\n\n{HEADING}\n\n`x`, re-counted from the code: 3 hops. Shell `core`; the "
             "walk enters {} library components, in pipeline order: {}\n(work). More.\n\n")
    first = "1. `tools/t/main.cpp` → `glint::run_tool` (core).\n"
    good = (intro.format("two", "`a` (read) and `b`") + first +
            "2. `a::load` (a, `load.cpp`): `make_inputs` and `<imagefile>`.\n"
            "3. `b::Thing::make()` (noise, ADC) (b): `Thing`, `.jsim`.\n\n## Next\n")
    bad = (intro.format("six", "`b` (read) and `a`") + first +
           "2. `a::load` (a): `make_outputs`, `tools/t/gone.cpp`, `gone.h`, `b::Missing`.\n"
           "4. `b::Thing::make()` (noise, ADC) (b).\n5. again (x, y) (b).\n\n## Next\n")
    long = (intro.format("nine", ", ".join(f"`c{i}`" for i in range(1, 10))).replace("3 hops",
            "16 hops") + "".join(f"{i}. (c{min(i, 9)}).\n" for i in range(1, 17)))
    results = []
    for doc in (bad, good, long):
        with tempfile.TemporaryDirectory() as folder:
            root = pathlib.Path(folder)
            files = {"tools/t/main.cpp": "int main() { return glint::run_tool(); }\n",
                     "lib/core/src/tool.cpp": "int run_tool();\n",
                     "lib/a/src/load.cpp": "void load(); void make_inputs();\n",
                     "lib/b/include/glint/b/thing.h": "struct Thing { static Thing make(); };\n",
                     "lib/c/src/other.cpp": "struct Missing {};\n", DOC: doc}
            files.update({f"lib/c{i}/src/c.cpp": "" for i in range(1, 10)})
            for relative, text in files.items():
                (root / relative).parent.mkdir(parents=True, exist_ok=True)
                (root / relative).write_text(text)
            results.append(check(root))
    expected = [f"{DOC}: hop 2: `b::Missing`: Missing is not a word under lib/b/",
                f"{DOC}: hop 2: `gone.h`: no such file",
                f"{DOC}: hop 2: `make_outputs`: not a word",
                f"{DOC}: hop 2: `tools/t/gone.cpp`: no such path",
                f"{DOC}: hop 5: enters b again (entered in hop 4)",
                f"{DOC}: intro: the first paragraph does not say \"enters 2 library",
                f"{DOC}: intro: the first paragraph does not say \"re-counted from the code: 4",
                f"{DOC}: intro: the pipeline order ['b', 'a'] is not the order",
                f"{DOC}: the hops are numbered [1, 2, 4, 5], not 1..4"]
    found = sorted(results[0][1])
    limits = [f"{DOC}: the walk has 16 hops, more than 15",
              f"{DOC}: hop 10: enters c9 again (entered in hop 9)",
              f"{DOC}: the hops enter 9 library components, more than 8"]
    ok = (len(found) == len(expected) and all(f.startswith(e) for f, e in zip(found, expected))
          and results[1] == (3, []) and len(results[2][1]) == 9
          and all(any(p.startswith(e) for p in results[2][1]) for e in limits))
    for problem in found:
        print(problem)
    print(f"long tree: {results[2][0]} hops, {len(results[2][1])} problems (7 repeats of c9)")
    print(f"good tree: {results[1][0]} hops, {len(results[1][1])} problems")
    for problem in results[1][1]:
        print(problem)
    print("self-test " + ("passed" if ok else "FAILED: expected " + "; ".join(expected) +
                          "; the long tree's limits; no problem in the good tree"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(runner.run(check, self_test, "hops"))
