#!/usr/bin/env python3
"""Say by how much the data lines of two sets of scene outputs differ.

    HILLSTAB_SCENES_KEEP=/tmp/old bash scripts/check_scenes.sh   # on the old build
    HILLSTAB_SCENES_KEEP=/tmp/new bash scripts/check_scenes.sh   # on the new build
    python3 scripts/compare_scenes.py /tmp/old /tmp/new

For every file present in both: the data lines (not starting with '#') compared token by
token. Tokens that differ as text are compared as numbers, in units of the last digit the
old text shows (a token written with 17 significant digits that moved by one in its last
place is "1 unit"). Prints per file: lines, lines that differ, tokens that differ, the
largest difference in units of the last digit and in relative terms, and the columns (by
the '# columns:' line) where they lie. Exit 0; the judgement is the reader's.
"""
import math
import os
import sys


def data_lines(path):
    with open(path, "rb") as f:
        text = f.read().decode("utf-8", "replace")
    lines = text.split("\n")
    columns = []
    for line in lines:
        if line.startswith("# columns:"):
            columns = line[len("# columns:"):].split()
    return [l for l in lines if not l.startswith("#")], columns


def last_digit_unit(token):
    """The value of one unit in the last digit shown by a numeric token."""
    t = token.lower()
    exponent = 0
    if "e" in t:
        t, e = t.split("e")
        exponent = int(e)
    if "." in t:
        decimals = len(t.split(".")[1])
    else:
        decimals = 0
    return 10.0 ** (exponent - decimals)


def main():
    if len(sys.argv) != 3:
        print("usage: compare_scenes.py OLD_DIR NEW_DIR", file=sys.stderr)
        return 2
    old_dir, new_dir = sys.argv[1], sys.argv[2]
    names = sorted(set(os.listdir(old_dir)) & set(os.listdir(new_dir)))
    print(f"{'file':40s} {'lines':>8s} {'differ':>7s} {'tokens':>7s} {'max units':>10s} {'max rel':>9s}  columns")
    for name in names:
        old, columns = data_lines(os.path.join(old_dir, name))
        new, _ = data_lines(os.path.join(new_dir, name))
        if len(old) != len(new):
            print(f"{name:40s} line counts differ: {len(old)} and {len(new)}")
            continue
        n_lines = n_tokens = 0
        worst_units = worst_rel = 0.0
        where = set()
        for a, b in zip(old, new):
            if a == b:
                continue
            n_lines += 1
            ta, tb = a.split(), b.split()
            if len(ta) != len(tb):
                where.add("(token count)")
                worst_units = math.inf
                continue
            for k, (x, y) in enumerate(zip(ta, tb)):
                if x == y:
                    continue
                n_tokens += 1
                where.add(columns[k] if k < len(columns) else str(k + 1))
                try:
                    fx, fy = float(x), float(y)
                except ValueError:
                    worst_units = math.inf
                    continue
                worst_units = max(worst_units, abs(fx - fy) / last_digit_unit(x))
                worst_rel = max(worst_rel, abs(fx - fy) / max(abs(fx), abs(fy), 1e-300))
        if n_lines:
            print(f"{name:40s} {len(old):8d} {n_lines:7d} {n_tokens:7d} {worst_units:10.3g} {worst_rel:9.2e}  "
                  + " ".join(sorted(where)))
        else:
            print(f"{name:40s} {len(old):8d} {0:7d}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
