#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Runs one declarative CLI test case (a TOML file) against the built glint tools.

A case names the command, its stdin and environment, the exit status it must end with,
what stdout and stderr must (not) contain, which files must (not) exist afterwards, and
post-checks (other programs run on the outputs). See tests/cli/README.md for the keys.
Exit status: 0 pass, 1 fail, 77 skipped (a required program is missing).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tomllib

SKIP = 77
KNOWN_KEYS = {
    "description", "requires", "setup", "args", "stdin", "env", "exit", "timeout",
    "stdout_contains", "stdout_not_contains", "stdout_regex", "stdout_empty", "stdout_equals",
    "stderr_contains", "stderr_not_contains", "stderr_regex", "stderr_empty", "stderr_equals",
    "files_exist", "files_absent", "check", "limits_address_space", "measures_memory",
}
CHECK_KEYS = KNOWN_KEYS - {"description", "requires", "setup", "files_exist", "files_absent",
                           "check", "limits_address_space", "measures_memory"}


class CaseFailure(Exception):
    pass


def expand(value, places):
    if isinstance(value, str):
        for key, replacement in places.items():
            value = value.replace("{" + key + "}", replacement)
        return value
    if isinstance(value, list):
        return [expand(v, places) for v in value]
    if isinstance(value, dict):
        return {k: expand(v, places) for k, v in value.items()}
    return value


def resolve_program(argv, bin_dir):
    if argv and argv[0].startswith("glint-"):
        return [os.path.join(bin_dir, argv[0])] + argv[1:]
    return argv


def run_command(spec, places, bin_dir, work, base_env):
    argv = resolve_program(expand(spec["args"], places), bin_dir)
    env = dict(base_env)
    env.update({k: str(v) for k, v in expand(spec.get("env", {}), places).items()})
    stdin = expand(spec.get("stdin", ""), places)
    try:
        done = subprocess.run(argv, input=stdin.encode(), capture_output=True, cwd=work, env=env,
                              timeout=spec.get("timeout", 100))
    except FileNotFoundError as e:
        raise CaseFailure(f"cannot run {argv[0]}: {e}")
    except subprocess.TimeoutExpired:
        raise CaseFailure(f"timed out: {' '.join(argv)}")
    return argv, done.returncode, done.stdout.decode(errors="replace"), \
        done.stderr.decode(errors="replace")


def check_stream(name, text, spec, places):
    problems = []
    for needle in expand(spec.get(f"{name}_contains", []), places):
        if needle not in text:
            problems.append(f"{name} lacks {needle!r}")
    for needle in expand(spec.get(f"{name}_not_contains", []), places):
        if needle in text:
            problems.append(f"{name} contains {needle!r}")
    for pattern in expand(spec.get(f"{name}_regex", []), places):
        if not re.search(pattern, text, re.MULTILINE):
            problems.append(f"{name} does not match /{pattern}/")
    if spec.get(f"{name}_empty") and text:
        problems.append(f"{name} is not empty")
    if f"{name}_equals" in spec and text != expand(spec[f"{name}_equals"], places):
        problems.append(f"{name} is not exactly {expand(spec[f'{name}_equals'], places)!r}")
    return problems


def verify(spec, outcome, places, what):
    argv, status, out, err = outcome
    problems = []
    expected = spec.get("exit", 0)
    if status != expected:
        problems.append(f"exit status {status}, expected {expected}")
    problems += check_stream("stdout", out, spec, places)
    problems += check_stream("stderr", err, spec, places)
    if problems:
        raise CaseFailure(f"{what}: {' '.join(argv)}\n  - " + "\n  - ".join(problems) +
                          f"\n--- stdout ---\n{out[-4000:]}\n--- stderr ---\n{err[-4000:]}")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--bin", required=True, help="folder of the built glint-* tools")
    parser.add_argument("--data", required=True, help="tests/data")
    parser.add_argument("--work", required=True, help="scratch folder, emptied first")
    parser.add_argument("--sanitized", action="store_true",
                        help="the tools are built with AddressSanitizer (GLINT_SANITIZE)")
    parser.add_argument("case", help="the .toml case file")
    args = parser.parse_args()

    with open(args.case, "rb") as f:
        case = tomllib.load(f)
    unknown = set(case) - KNOWN_KEYS
    if unknown:
        print(f"{args.case}: unknown keys {sorted(unknown)}", file=sys.stderr)
        return 1
    for check in case.get("check", []):
        if set(check) - CHECK_KEYS:
            print(f"{args.case}: unknown check keys {sorted(set(check) - CHECK_KEYS)}",
                  file=sys.stderr)
            return 1
    if "args" not in case or "exit" not in case:
        print(f"{args.case}: a case needs 'args' and 'exit'", file=sys.stderr)
        return 1

    if case.get("limits_address_space", False) and args.sanitized:
        print("SKIP: the case limits the address space (ulimit -v), which AddressSanitizer's "
              "shadow memory cannot run under")
        return SKIP
    if case.get("measures_memory", False) and args.sanitized:
        print("SKIP: the case measures peak memory, which AddressSanitizer's shadow memory and "
              "quarantine inflate")
        return SKIP
    for program in case.get("requires", []):
        if shutil.which(program) is None:
            print(f"SKIP: {program} is not installed (scripts/install-deps.sh installs it)")
            return SKIP

    work = os.path.abspath(args.work)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    places = {"work": work, "data": os.path.abspath(args.data), "bin": os.path.abspath(args.bin),
              "python": "/usr/bin/python3"}
    base_env = dict(os.environ)
    base_env.pop("NO_COLOR", None)
    # The processing allow-list of whoever runs the tests must not change what a case sees:
    # none exists unless the case makes one (and names it in its env).
    base_env["GLINT_ALLOWED_PROGRAMS"] = os.path.join(work, ".no-allowed-programs")

    try:
        for step in case.get("setup", []):
            outcome = run_command({"args": step}, places, args.bin, work, base_env)
            verify({"exit": 0}, outcome, places, "setup step failed")
        verify(case, run_command(case, places, args.bin, work, base_env), places, "case failed")
        for path in expand(case.get("files_exist", []), places):
            if not os.path.exists(path):
                raise CaseFailure(f"expected file missing: {path}")
        for path in expand(case.get("files_absent", []), places):
            if os.path.exists(path):
                raise CaseFailure(f"file must not exist: {path}")
        leftovers = []
        for root, _, files in os.walk(work):
            leftovers += [os.path.join(root, f) for f in files if re.match(r"^\..*\.tmp-", f)]
        if leftovers:
            raise CaseFailure(f"temporary files left behind: {leftovers}")
        for check in case.get("check", []):
            verify(check, run_command(check, places, args.bin, work, base_env), places,
                   "check failed")
    except CaseFailure as failure:
        print(f"FAIL {args.case}: {case.get('description', '')}\n{failure}", file=sys.stderr)
        return 1
    print(f"PASS {os.path.basename(args.case)}: {case.get('description', '')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
