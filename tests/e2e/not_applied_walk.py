#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Walks every .platform fixture under tests/data and, for each element glint reads but does
not apply (docs/formats.md, "Read, not applied"), asserts that `glint-platform2jsim --check`
gives exactly one warning naming it at its file:line. The rules below say which elements those
are and what their warning says; a fixture whose check has errors is skipped (errors can stop
a reader before it reaches an element). Fails when no element was found at all, so that it
cannot pass by walking nothing."""
import argparse
import pathlib
import subprocess
import sys
import xml.parsers.expat


def elements_with_lines(path):
    """(line, tag, attributes, text, children's tags) for every element of an XML file."""
    found, stack = [], []
    parser = xml.parsers.expat.ParserCreate()

    def start(tag, attributes):
        item = {"line": parser.CurrentLineNumber, "tag": tag, "attrs": attributes,
                "text": "", "children": []}
        if stack:
            stack[-1]["children"].append(item)
        stack.append(item)
        found.append(item)

    def end(tag):
        stack.pop()

    def data(text):
        if stack:
            stack[-1]["text"] += text

    parser.StartElementHandler, parser.EndElementHandler = start, end
    parser.CharacterDataHandler = data
    parser.Parse(pathlib.Path(path).read_bytes(), True)
    return found


def child(item, tag):
    return next((c for c in item["children"] if c["tag"] == tag), None)


def expected_warnings(items):
    """(line, text) of each warning the rules expect."""
    out = []
    for e in items:
        tag, attrs = e["tag"], e["attrs"]
        kind = attrs.get("type", "").strip().lower()
        if tag == "spatialresponse":
            out.append((e["line"], "<spatialresponse> is a DIRSIG4 setting"))
        elif tag == "capturemethod" and kind == "lidar":
            detector = child(e, "detectormodel")
            if detector and any(child(detector, t) for t in (
                    "readnoise", "darkcurrentdensity", "minelectrons", "maxelectrons", "bitdepth")):
                out.append((detector["line"], "a lidar capture applies only the detector model's"))
            strategy = child(e, "samplestrategy")
            multiplier = strategy and child(strategy, "hypersamplingmultiplier")
            if multiplier and float(multiplier["text"].strip() or "1") > 1:
                out.append((e["line"], "<hypersamplingmultiplier> is read, not applied on a lidar"))
            integration = child(e, "temporalintegration")
            time = integration and child(integration, "time")
            if time and float(time["text"].strip() or "0") > 0:
                out.append((integration["line"], "does not apply to a lidar capture"))
        elif tag == "capturemethod" and kind == "raw":
            response = child(e, "spectralresponse")
            channels = response and child(response, "channellist")
            first = channels and child(channels, "channel")
            if first:
                out.append((first["line"], "the <channel>s of a raw capture are read"))
        elif tag == "samplestrategy" and kind not in ("", "central"):
            out.append((e["line"], "samplestrategy type"))
        elif (tag == "instrument" and kind == "datarecorder" and child(e, "clock") is None
              and child(e, "focalplane") is None):
            out.append((e["line"], "has no <clock> (nor an enabled focal plane's): it records"))
        elif tag == "polarizer" and kind not in ("", "none"):
            out.append((e["line"], "polarization is not modelled"))
        elif tag == "temporalintegration" and child(e, "samples") is not None:
            samples = child(e, "samples")
            if int(samples["text"].strip() or "1") > 1:
                out.append((samples["line"], "DIRSIG5-style sampling ignores"))
    return out


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", required=True)
    parser.add_argument("--data", required=True)
    args = parser.parse_args()
    tool = pathlib.Path(args.bin) / "glint-platform2jsim"
    problems, walked, checked = [], 0, 0
    for platform in sorted(pathlib.Path(args.data).rglob("*.platform")):
        try:
            expected = expected_warnings(elements_with_lines(platform))
        except xml.parsers.expat.ExpatError:
            continue  # a fixture that is broken on purpose
        if not expected:
            continue
        run = subprocess.run([str(tool), "--check", str(platform)], capture_output=True,
                             text=True, check=False)
        if "check: 0 errors" not in run.stdout:
            continue
        walked += 1
        warnings = [line for line in run.stderr.splitlines() if ": warning: " in line]
        for line, text in expected:
            checked += 1
            located = f"{platform}:{line}: "
            hits = [w for w in warnings if located in w and text in w]
            if len(hits) != 1:
                problems.append(f"{platform}:{line}: expected one warning containing {text!r}, "
                                f"got {len(hits)}")
    print(f"{walked} fixtures, {checked} read-but-not-applied elements checked")
    if checked == 0:
        problems.append("no fixture holds an element the rules look for")
    for p in problems:
        print("not_applied_walk:", p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
