# SPDX-License-Identifier: Apache-2.0
"""The command line the architecture tests share: SCRIPT SOURCE_DIR runs the check on a tree
(exit 0 when it holds, 1 with every problem listed), SCRIPT --self-test runs the check on
planted trees (exit 0 when it finds what they break)."""
import pathlib
import sys


def run(check, self_test, counted):
    """Runs `check(root) -> (count, problems)` or `self_test() -> status` as sys.argv says;
    `counted` names what count counts ("sources", "hops")."""
    if len(sys.argv) != 2:
        print(f"usage: {pathlib.Path(sys.argv[0]).name} SOURCE_DIR | --self-test",
              file=sys.stderr)
        return 2
    if sys.argv[1] == "--self-test":
        return self_test()
    count, problems = check(pathlib.Path(sys.argv[1]))
    for problem in problems:
        print(problem)
    print(f"{count} {counted} checked, {len(problems)} problems")
    return 1 if problems else 0
