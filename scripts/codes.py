#!/usr/bin/env python3
"""Write the codes other languages copy of the models and methods, from the Fortran tables.

The registry of models (`model_names` of src/hillstab/hill/models.f90: code = position),
the table of methods (`method_table` of src/hillstab/integrate/monodromy.f90: code = index,
`systems=.true.` for the methods systems take) and the values of a point the C API returns
(the `value_<name> = <index>` constants and `value_count` of
src/hillstab/interop/capi_batch.f90) are the only lists. From them this script writes:

- the `HILLSTAB_MODEL_*`, `HILLSTAB_METHOD_*` and `HILLSTAB_VALUE_*` enums of
  include/hillstab.h (the values' enum with `HILLSTAB_VALUE_COUNT`; the enum of the files'
  names for some values, their aliases, is written by hand);
- the MODEL and METHOD argument lines of the FORTRAN 77 entry points HSTRACE and HSFLOQ
  (src/hillstab/interop/legacy.f90, legacy_external.f90: `:: model   !! ...`, `:: method  !! ...`);
- Python's `METHODS` and `VALUES` (python/hillstab/_capi.py) and `SYSTEM_METHODS`
  (python/hillstab/system.py).

A new model, method or value is its module and its row (a value: its constant and its
computation in capi_batch.f90); then `python3 scripts/codes.py` (or
`make codes`). With `--check` nothing is written: the script names each file that is not
what it would write and exits 1 (`make test` runs it so). The suite `codes` checks the same
copies against the compiled tables, independently of this script. `--root DIR` works on
another tree (its tests).
"""
import argparse
import os
import re
import sys

MODELS = "src/hillstab/hill/models.f90"
METHODS = "src/hillstab/integrate/monodromy.f90"
HEADER = "include/hillstab.h"
LEGACY = ("src/hillstab/interop/legacy.f90", "src/hillstab/interop/legacy_external.f90")
PY_CAPI = "python/hillstab/_capi.py"
PY_SYSTEM = "python/hillstab/system.py"
VALUES = "src/hillstab/interop/capi_batch.f90"
WIDTH = 116
#: what the F77 MODEL lines add after the codes
MODEL_NOTE = " (a model that carries data or texts takes them through the C API)"
#: the F77 entry points whose MODEL and METHOD take every code (HSCHAR documents its own)
TAKE_EVERY_MODEL = ("hstrace", "hsfloq")


def fortran_statement(text, start):
    """The Fortran statement that begins at `start`, its continuation lines joined."""
    out = []
    for line in text[start:].split("\n"):
        code = line.split("!")[0] if '"' not in line else line
        stripped = code.rstrip()
        if stripped.endswith("&"):
            out.append(stripped[:-1])
            continue
        out.append(stripped)
        break
    return " ".join(part.strip().lstrip("&") for part in out)


def table_statement(root, path, declaration, what):
    """The file's text, the match of the table's declaration and its whole statement."""
    with open(os.path.join(root, path), encoding="utf-8") as handle:
        text = handle.read()
    match = re.search(r"^\s*" + declaration, text, re.M)
    if not match:
        sys.exit(f"codes: {path}: no {what}")
    return text, match, fortran_statement(text, match.start())


def model_names(root):
    """The models' names in the order of their codes (1 …)."""
    _, _, statement = table_statement(root, MODELS, r"character\(len=\*\), parameter :: model_names\(\d+\)",
                                      "model_names table")
    body = statement[statement.index("::", statement.index("[")) + 2:statement.rindex("]")]
    names = re.findall(r'"([^"]*)"', body)
    declared = int(re.search(r"model_names\((\d+)\)", statement).group(1))
    if len(names) != declared or not names:
        sys.exit(f"codes: {MODELS}: model_names declares {declared} names, lists {len(names)}")
    return names


def method_rows(root):
    """The methods as (name, code, systems), in the order of their codes (from the lower bound)."""
    _, match, statement = table_statement(
        root, METHODS, r"type\(method_info_t\), parameter :: method_table\((-?\d+):(-?\d+)\)", "method_table")
    low, high = int(match.group(1)), int(match.group(2))
    rows = statement.split("method_info_t(")[1:]   # [0]: the declaration
    if len(rows) != high - low + 1:
        sys.exit(f"codes: {METHODS}: method_table({low}:{high}) has {len(rows)} rows")
    out = []
    for code, row in zip(range(low, high + 1), rows):
        name = re.match(r'\s*"([^"]*)"', row).group(1)
        systems = re.search(r"systems\s*=\s*\.true\.", row, re.I) is not None
        out.append((name, code, systems))
    return out


def value_names(root):
    """The names of the values of a point, in the order of their indices (0 …)."""
    text, _, statement = table_statement(root, VALUES, r"integer, parameter :: value_\w+ = 0\b",
                                         "value_<name> = 0 constants")
    pairs = re.findall(r"value_(\w+) = (\d+)", statement)
    count = re.search(r"^\s*integer, parameter :: value_count = (\d+)", text, re.M)
    indices = [int(index) for _, index in pairs]
    if not count or indices != list(range(len(pairs))) or int(count.group(1)) != len(pairs):
        sys.exit(f"codes: {VALUES}: the value constants are not 0 … value_count - 1 in order")
    return [name for name, _ in pairs]


def wrapped(items, first, rest=None, end=""):
    """Items joined by ", " and followed by `end`, in lines of at most WIDTH characters: the
    first starting with `first`, the others with `rest` (`first` when not given)."""
    rest = first if rest is None else rest
    lines, line, start = [], first, first
    for k, item in enumerate(items):
        piece = item + ("," if k < len(items) - 1 else end)
        if line != start and len(line) + 1 + len(piece) > WIDTH:
            lines.append(line)
            line = start = rest
        line = line + ("" if line == start else " ") + piece
    lines.append(line)
    return "\n".join(lines)


def header_text(text, models, methods, values):
    """The header with its model, method and value enums from the tables."""
    enums = {
        "HILLSTAB_MODEL_": [f"HILLSTAB_MODEL_{name.upper()} = {code}" for code, name in enumerate(models, 1)],
        "HILLSTAB_METHOD_": [f"HILLSTAB_METHOD_{name.upper()} = {code}" for name, code, _ in methods],
        # the enum that begins with the value of index 0 under the table's name (the aliases'
        # enum begins with another name)
        "HILLSTAB_VALUE_" + values[0].upper() + " = 0": [f"HILLSTAB_VALUE_{name.upper()} = {index}"
                                                       for index, name in enumerate(values)] +
        [f"HILLSTAB_VALUE_COUNT = {len(values)}"],
    }
    for prefix, items in enums.items():
        pattern = re.compile(r"enum \{\n(  " + re.escape(prefix) + r"[A-Z0-9_]* ?=? ?-?\d*[^}]*)\};")
        if not pattern.search(text):
            sys.exit(f"codes: {HEADER}: no enum of {prefix}*")
        text = pattern.sub(lambda _: "enum {\n" + wrapped(items, "  ") + "\n};", text, count=1)
    return text


def legacy_text(text, path, models, methods):
    """A FORTRAN 77 file with its MODEL and METHOD argument lines from the tables."""
    model_list = ", ".join(f"{code} {name}" for code, name in enumerate(models, 1)) + MODEL_NOTE
    method_list = ", ".join(f"{code} {name}" for name, code, _ in methods)
    count = 0
    out = []
    routine = ""
    for line in text.split("\n"):
        start = re.match(r"\s*subroutine (\w+)", line, re.I)
        if start:
            routine = start.group(1).lower()
        match = re.match(r"(\s*integer, intent\(in\) :: (model|method)\s+!! )", line)
        if match and routine in TAKE_EVERY_MODEL:
            line = match.group(1) + (model_list if match.group(2) == "model" else method_list)
            count += 1
        out.append(line)
    if count == 0:
        sys.exit(f"codes: {path}: no MODEL or METHOD argument line")
    return "\n".join(out)


def python_text(text, path, variable, pairs):
    """A Python file with its `variable = {...}` line from the pairs (name, code)."""
    line = variable + " = {" + ", ".join(f'"{name}": {code}' for name, code in pairs) + "}"
    pattern = re.compile("^" + variable + r" = \{[^}]*\}$", re.M)
    if not pattern.search(text):
        sys.exit(f"codes: {path}: no line {variable} = {{...}}")
    return pattern.sub(lambda _: line, text, count=1)


def python_tuple(text, path, variable, names):
    """A Python file with its `variable = (...)` statement (one or more lines) from the names."""
    first = variable + " = ("
    statement = wrapped([f'"{name}"' for name in names], first, " " * len(first), end=")")
    pattern = re.compile("^" + variable + r" = \([^)]*\)$", re.M)
    if not pattern.search(text):
        sys.exit(f"codes: {path}: no statement {variable} = (...)")
    return pattern.sub(lambda _: statement, text, count=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--check", action="store_true", help="write nothing; exit 1 when a file differs")
    parser.add_argument("--root", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."),
                        help="the source tree (default: this script's)")
    args = parser.parse_args()
    root = args.root
    models = model_names(root)
    methods = method_rows(root)
    values = value_names(root)
    writers = [(HEADER, lambda t: header_text(t, models, methods, values))]
    writers += [(path, lambda t, p=path: legacy_text(t, p, models, methods)) for path in LEGACY]
    writers.append((PY_CAPI, lambda t: python_text(t, PY_CAPI, "METHODS", [(n, c) for n, c, _ in methods])))
    writers.append((PY_CAPI, lambda t: python_tuple(t, PY_CAPI, "VALUES", values)))
    writers.append((PY_SYSTEM, lambda t: python_text(t, PY_SYSTEM, "SYSTEM_METHODS",
                                                      [(n, c) for n, c, s in methods if s])))
    stale = []
    for path, write in writers:
        full = os.path.join(root, path)
        with open(full, encoding="utf-8") as handle:
            old = handle.read()
        new = write(old)
        if new == old:
            continue
        stale.append(path)
        if not args.check:
            with open(full + ".tmp", "w", encoding="utf-8") as handle:
                handle.write(new)
            os.replace(full + ".tmp", full)
    if args.check:
        if stale:
            print("codes: not what the tables give: " + ", ".join(stale) +
                  " (run python3 scripts/codes.py)", file=sys.stderr)
            return 1
        print(f"codes: {len(models)} models, {len(methods)} methods and {len(values)} values in C, FORTRAN 77 and "
              "Python as in the tables")
        return 0
    print("codes: wrote " + (", ".join(stale) if stale else "nothing (every file as the tables give it)"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
