#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""SIGINT during glint-render: exit status 130, and no file under a final name (the
simulation-schedule output is still incomplete when the signal arrives), no temporary file
left behind, and the process gone within a few seconds.

Usage: render_interrupt_test.py --bin BIN_DIR --data TESTS_DATA_DIR --work WORK_DIR
"""
import argparse
import os
import shutil
import signal
import subprocess
import sys
import time


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    out = os.path.join(args.work, "out")
    os.makedirs(args.work)
    # 3 captures x 48 pixels x 200 000 samples: far longer than the second we wait.
    command = [os.path.join(args.bin, "glint-render"), os.path.join(args.data, "render", "one.jsim"),
               "--output-folder", out, "--convergence", "200000,200000,0", "--threads", "2"]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    time.sleep(1.0)
    assert process.poll() is None, "glint-render ended before the signal: the job is too small"
    started = time.monotonic()
    process.send_signal(signal.SIGINT)
    try:
        stdout, stderr = process.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        process.kill()
        raise AssertionError("glint-render did not stop within 30 s of SIGINT")
    stopped = time.monotonic() - started
    assert process.returncode == 130, (process.returncode, stderr.decode())
    assert stdout == b"", stdout
    assert b"interrupted" in stderr, stderr.decode()
    left = []
    for root, _, files in os.walk(args.work):
        left += [os.path.join(root, f) for f in files]
    assert left == [], "files left behind: %s" % left
    print("ok: exit 130 after %.2f s, nothing left" % stopped)


if __name__ == "__main__":
    try:
        main()
    except AssertionError as error:
        print("FAIL:", error, file=sys.stderr)
        sys.exit(1)
