#!/usr/bin/env python3
"""The layers of src/hillstab, checked (run by `make test` and CI).

The folders are layers, each using only itself and the layers before it:

    core < ffi < hill < integrate < {curves, pendulum} < batch < interop

and within batch/: output < scene < tasks < run. A module that uses one of a later layer
(an edge upward) fails the check, naming the file, the line and both layers; so does a
source file of more than 1000 lines. Prints nothing when all is well but one summary line.
"""
import os
import re
import sys

LIMIT = 1000
TOP = {"core": 0, "ffi": 1, "hill": 2, "integrate": 3, "curves": 4, "pendulum": 4, "batch": 5, "interop": 6}
BATCH = {"output": 0, "scene": 1, "tasks": 2, "run": 3}
USE = re.compile(r"^\s*use\s+hillstab_([a-z0-9]+)(?:_([a-z0-9]+))?", re.IGNORECASE)


def layers(path):
    """(top layer, batch layer or None) of a source file under src/hillstab."""
    parts = path.split(os.sep)
    top = parts[0]
    sub = parts[1] if top == "batch" and len(parts) > 2 else None
    return top, sub


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "src", "hillstab")
    problems = []
    files = 0
    for folder, _, names in os.walk(root):
        for name in sorted(names):
            if not name.endswith(".f90"):
                continue
            full = os.path.join(folder, name)
            rel = os.path.relpath(full, root)
            files += 1
            top, sub = layers(rel)
            with open(full, encoding="utf-8") as handle:
                lines = handle.readlines()
            if len(lines) > LIMIT:
                problems.append(f"src/hillstab/{rel}: {len(lines)} lines, more than {LIMIT} (split it)")
            if top not in TOP:
                problems.append(f"src/hillstab/{rel}: folder '{top}' is in no layer (add it to scripts/layer_check.py)")
                continue
            for number, line in enumerate(lines, 1):
                match = USE.match(line)
                if not match:
                    continue
                used, used_sub = match.group(1).lower(), (match.group(2) or "").lower()
                if used not in TOP:
                    continue
                if TOP[used] > TOP[top] or (TOP[used] == TOP[top] and used != top):
                    problems.append(f"src/hillstab/{rel}:{number}: {top} uses {used} (a later layer)")
                elif top == "batch" and used == "batch" and sub in BATCH and used_sub in BATCH \
                        and BATCH[used_sub] > BATCH[sub]:
                    problems.append(f"src/hillstab/{rel}:{number}: batch/{sub} uses batch/{used_sub} (a later layer)")
    for problem in problems:
        print(problem, file=sys.stderr)
    if problems:
        print(f"layer-check: {len(problems)} problems in {files} files", file=sys.stderr)
        return 1
    print(f"layer-check: {files} files in their layers, none over {LIMIT} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
