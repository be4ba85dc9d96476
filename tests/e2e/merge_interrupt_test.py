#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""SIGINT while glint-envi merge writes a one-capture file: exit 130, nothing published, no
staging folder left. The parts of a small render are widened to 10^7 samples a line (their
data files extended sparsely to match), so the one capture takes long enough to copy that the
signal strikes inside it — where merge checked for an interrupt only before each capture, and
so published the file anyway."""
import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import time

SAMPLES = 10_000_000


def widen(part):
    header = os.path.join(part, "frame-t0000-c0000.img.hdr")
    text = open(header).read()
    lines = int(re.search(r"^lines = (\d+)$", text, re.M).group(1))
    bands = int(re.search(r"^bands = (\d+)$", text, re.M).group(1))
    open(header, "w").write(re.sub(r"^samples = \d+$", "samples = %d" % SAMPLES, text, flags=re.M))
    os.truncate(os.path.join(part, "frame-t0000-c0000.img"), SAMPLES * lines * bands * 8)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--data", required=True)
    ap.add_argument("--work", required=True)
    args = ap.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    work = args.work
    subprocess.run([sys.executable, os.path.join(args.data, "scale", "make_sim.py"), work,
                    "--schedule", "capture", "--no-detector", "--no-truth"], check=True)
    render = os.path.join(args.bin, "glint-render")
    for part, rows in (("a", "0:3"), ("b", "3:")):
        subprocess.run([render, os.path.join(work, "one.jsim"), "--output-folder",
                        os.path.join(work, part), "--convergence", "1,1,0", "--rows", rows, "-q"],
                       check=True)
        widen(os.path.join(work, part))
    out = os.path.join(work, "out")
    process = subprocess.Popen([os.path.join(args.bin, "glint-envi"), "merge",
                                os.path.join(work, "a"), os.path.join(work, "b"), "-o", out],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    deadline = time.monotonic() + 120
    staging = []
    while not staging:
        assert process.poll() is None, "merge ended before it staged anything: %s" % (
            process.communicate()[1].decode())
        assert time.monotonic() < deadline, "merge never staged a file"
        if os.path.isdir(out):
            staging = [f for f in os.listdir(out) if f.startswith(".merge.tmp-")]
        time.sleep(0.005)
    time.sleep(0.05)  # inside the copy of the one capture
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=60)
    assert process.returncode == 130, (process.returncode, stderr.decode())
    assert stdout == b"", stdout
    assert stderr == b"glint-envi: error: interrupted (SIGINT)\n", stderr.decode()
    left = sorted(os.listdir(out))
    assert left == [], "left in the output folder: %s" % left
    print("ok: SIGINT inside a one-capture merge: exit 130, nothing published, no staging")


if __name__ == "__main__":
    try:
        main()
    except AssertionError as error:
        print("FAIL:", error, file=sys.stderr)
        sys.exit(1)
