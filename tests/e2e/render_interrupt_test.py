#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Stop signals during glint-render: SIGINT, SIGHUP and SIGTERM each end it with 128 + the
signal's number, no file under a final name (the simulation-schedule output is still
incomplete when the signal arrives), no temporary file left behind, and the process gone
within a few seconds. Then a file-size limit (`ulimit -f`, SIGXFSZ): the write fails,
exit 1 with the reason, nothing left behind. Last, SIGINT while a processing task runs
(tests/data/processing/hang.jsim): exit 130, and the task's process group is gone.

Usage: render_interrupt_test.py --bin BIN_DIR --data TESTS_DATA_DIR --work WORK_DIR
"""
import argparse
import os
import resource
import shutil
import signal
import subprocess
import sys
import time


def files_under(folder):
    left = []
    for root, _, files in os.walk(folder):
        left += [os.path.join(root, f) for f in files]
    return left


def wait_for_handler(process, sig, timeout_s=300.0):
    """Waits until the process has a handler for `sig` (its SigCgt mask in /proc), so the
    signal cannot strike before the tool installs its handlers (a slow start under ASan)."""
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline and process.poll() is None:
        try:
            with open("/proc/%d/status" % process.pid) as status:
                for line in status:
                    if line.startswith("SigCgt:") and (int(line.split()[1], 16) >> (sig - 1)) & 1:
                        return
        except FileNotFoundError:
            break
        time.sleep(0.02)
    raise AssertionError("glint-render never installed a handler for %s" % sig.name)


def stop_with(args, sig):
    work = os.path.join(args.work, sig.name)
    out = os.path.join(work, "out")
    os.makedirs(work)
    # 3 captures x 48 pixels x 200 000 samples: far longer than the wait before the signal.
    command = [os.path.join(args.bin, "glint-render"), os.path.join(args.data, "render", "one.jsim"),
               "--output-folder", out, "--convergence", "200000,200000,0", "--threads", "2"]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    # Signal once the tool handles it, and a moment later (it is at work then): a fixed delay
    # could strike before the handlers are installed on a slow start (ASan, a loaded machine).
    wait_for_handler(process, sig)
    time.sleep(0.5)
    assert process.poll() is None, "glint-render ended before the signal: the job is too small"
    started = time.monotonic()
    process.send_signal(sig)
    try:
        stdout, stderr = process.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        process.kill()
        raise AssertionError("glint-render did not stop within 30 s of %s" % sig.name)
    stopped = time.monotonic() - started
    assert process.returncode == 128 + sig.value, (sig.name, process.returncode, stderr.decode())
    assert stdout == b"", stdout
    expected = ("glint-render: error: interrupted (%s)\n" % sig.name).encode()
    assert stderr == expected, (sig.name, stderr.decode())
    left = files_under(work)
    assert left == [], "files left behind after %s: %s" % (sig.name, left)
    print("ok: %s: exit %d after %.2f s, nothing left" % (sig.name, process.returncode, stopped))


def second_signal(args):
    """A second SIGINT ends glint-render at once — and first removes the temporary file of
    the image it was writing, which the unwinding of the first would have removed."""
    work = os.path.join(args.work, "second")
    out = os.path.join(work, "out")
    os.makedirs(work)
    command = [os.path.join(args.bin, "glint-render"), os.path.join(args.data, "render", "one.jsim"),
               "--output-folder", out, "--convergence", "60000,60000,0", "--threads", "2"]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    wait_for_handler(process, signal.SIGINT)
    deadline = time.monotonic() + 60
    while not any(".tmp-" in f for f in files_under(work)):
        assert process.poll() is None, "glint-render ended before writing its image"
        assert time.monotonic() < deadline, "no temporary image file appeared"
        time.sleep(0.02)
    process.send_signal(signal.SIGINT)
    process.send_signal(signal.SIGINT)
    try:
        process.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        process.kill()
        raise AssertionError("glint-render did not stop within 30 s of two SIGINTs")
    # Killed by the second (-2), or, had the first finished unwinding before it came, 130.
    assert process.returncode in (-signal.SIGINT, 130), process.returncode
    left = [f for f in files_under(work) if ".tmp-" in f]
    assert left == [], "temporary files left behind after two SIGINTs: %s" % left
    print("ok: two SIGINTs: exit %d, no temporary file left" % process.returncode)


def file_size_limit(args):
    work = os.path.join(args.work, "fsize")
    out = os.path.join(work, "out")
    os.makedirs(work)
    command = [os.path.join(args.bin, "glint-render"), os.path.join(args.data, "render", "one.jsim"),
               "--output-folder", out, "--convergence", "1,1,0", "--threads", "1"]

    def limit():  # 100 bytes: less than any output file
        resource.setrlimit(resource.RLIMIT_FSIZE, (100, 100))

    result = subprocess.run(command, capture_output=True, timeout=60, preexec_fn=limit)
    stderr = result.stderr.decode()
    assert result.returncode == 1, ("file-size limit", result.returncode, stderr)
    assert "File too large" in stderr, stderr
    left = files_under(work)
    assert left == [], "files left behind after the file-size limit: %s" % left
    print("ok: file-size limit: exit 1 (%s), nothing left" % stderr.strip().splitlines()[-1])


def interrupt_processing_task(args):
    work = os.path.join(args.work, "processing")
    out = os.path.join(work, "out")
    os.makedirs(work)
    command = [os.path.join(args.bin, "glint-render"),
               os.path.join(args.data, "processing", "hang.jsim"),
               "--output-folder", out, "--convergence", "1,1,0", "--allow-processing"]
    env = dict(os.environ)
    env["PATH"] = os.path.join(args.data, "processing", "bin") + ":/usr/bin:/bin"
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
    # bin/hang writes its process id (its group's id too: a task leads its own group), then
    # sleeps for 47 s.
    pid_file = os.path.join(out, "hang.pid")
    deadline = time.monotonic() + 300
    while not os.path.exists(pid_file) or os.path.getsize(pid_file) == 0:
        assert process.poll() is None, ("glint-render ended before its task ran",
                                        process.stderr.read().decode())
        assert time.monotonic() < deadline, "the processing task never started"
        time.sleep(0.02)
    task = int(open(pid_file).read())
    process.send_signal(signal.SIGINT)
    try:
        stdout, stderr = process.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        process.kill()
        raise AssertionError("glint-render did not stop within 30 s of SIGINT during a task")
    assert process.returncode == 130, (process.returncode, stderr.decode())
    hang = os.path.join(args.data, "processing", "bin", "hang")
    assert stderr.decode().endswith(
        "glint-render: error: interrupted while running %s (SIGINT)\n" % hang), stderr.decode()
    time.sleep(0.1)
    try:
        os.killpg(task, 0)
        raise AssertionError("the task's process group %d is still there" % task)
    except ProcessLookupError:
        pass
    left = [f for f in files_under(work) if ".tmp-" in os.path.basename(f)]
    assert left == [], "temporary files left behind: %s" % left
    print("ok: SIGINT during a processing task: exit 130, its process group %d gone" % task)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bin", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    os.makedirs(args.work)
    for sig in (signal.SIGINT, signal.SIGHUP, signal.SIGTERM):
        stop_with(args, sig)
    second_signal(args)
    file_size_limit(args)
    interrupt_processing_task(args)


if __name__ == "__main__":
    try:
        main()
    except AssertionError as error:
        print("FAIL:", error, file=sys.stderr)
        sys.exit(1)
