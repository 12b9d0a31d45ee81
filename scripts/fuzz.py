#!/usr/bin/env python3
"""Seeded, reproducible fuzz test of the hillstab command line.

Scenes are made by mutating the shipped scenes of data/scenes/ (their grids shrunk
first so that one run takes a fraction of a second): characters deleted, inserted or
replaced by namelist punctuation, numbers replaced by extreme values, lines dropped,
doubled or swapped, the file cut short or left without its final newline. Each scene runs
in a scratch directory holding a copy of data/ and a sentinel output file, and must

  - exit 0 (or 3: written, some points failed) with whole output files: no NaN or Inf
    in the data rows of text files, the same number of columns on every data row; or
  - exit 1 or 2 with exactly one line on stderr, starting "hillstab: ";
  (lines "hillstab: warning: ..." come besides: a group the task does not read, a spring in
  implausible units, round-off limited points; they are not counted, and at exit 0 they
  are all stderr may hold)
  - finish within the time limit;
  - leave no temporary file (*.part<pid>) and the sentinel untouched.

Two further families follow, with the same acceptance rules:

  - points files (--points-count): the scenes that read &points (task points, task lyapunov
    over points, the points template) run on a mutated copy of data/points/*.dat: malformed
    numbers, NaN/Inf text, extreme values, more lines than the limit, empty or comment-only
    files, binary junk, NUL bytes, very long lines, CRLF or CR line ends, a byte-order mark,
    UTF-16; or their `&points file =` names something else: a missing file, a directory, a
    device, a FIFO, a symbolic link, an empty or very long name. An exit 1 or 2 there must
    name `&points: file:`, unless the scene itself was also mutated;
  - templates (--template-count): `hillstab --template TASK` of every task the program lists,
    shrunk and mutated like the shipped scenes, sometimes with their optional commented
    groups (`&physical` and its alternatives) switched on.

  - systems (--system-count): the shipped system scenes (&scene model = 'system') with one
    of their &system matrices given as a matrix file, mutated: NUL bytes, empty fields
    (`5,,7`, a leading comma, a line of commas), ragged rows, rows of the wrong width,
    extreme or non-finite entries, binary junk, very long lines, CR or CRLF line ends, UTF-16,
    comments and closing commas (which are fine); or the matrix named as a FIFO, a
    directory, a device, a missing file or a dangling link; or the scene read otherwise than
    written: the quoted path across a line break, &system given twice, a variable given twice,
    a subscripted variable; or extreme numbers in the matrices' lists. A route, a line break
    or a repeat must be refused (exit 2) with a message naming `&system` and the variable (the
    group for a second &system); FIFOs and devices must not block the run.

A last family damages checkpoints (--checkpoint-count): a chart (text and binary), a points
run and a Lyapunov map, each killed with SIGKILL while the test hook HILLSTAB_TEST_PAUSE_AFTER_UNITS
holds it mid-run (--checkpoint-interval 0), leave checkpoints; a copy of one gets one to
three seeded mutations of its `data` (bytes flipped, inserted or deleted among the recorded
ones, a digit changed, a new line planted, the header edited, cut short, bytes appended
after the recorded ones) or of its `state` (a number changed, a line dropped, doubled,
swapped or cut, the checksum line edited, the file emptied or filled with junk), and
`--resume` must then exit 0 with the file of an uninterrupted run, byte for byte, or exit 2
with one message line naming the checkpoint and no output file; never exit 0 with another
file; no temporary file left, in time. A run without --resume then writes the uninterrupted
file. Then (--foreign-checkpoint-count, a seeded stream of its own) a copy of such a checkpoint,
intact, damaged, without its state, or with its `data` or `state` replaced by a FIFO, a
directory or a symbolic link, is met by the system scene of the same output (a system run
cannot continue a scalar checkpoint) or by the scalar scene, with and without --resume: a member that is not
a regular file is refused (exit 2, one message naming the checkpoint, the checkpoint kept as
planted, no output) and never blocks; a system run discards any other checkpoint with a note
(exit 0, its file whole, the checkpoint gone, so that no later --resume continues it) and
refuses it under --resume (exit 2, kept).

With --signals, a chart is first interrupted by SIGINT, SIGTERM and SIGHUP: each must
exit 128 + signal, remove its temporary file and keep the old output.

usage: scripts/fuzz.py --hillstab BUILD/app/hillstab [--count 300] [--points-count 90]
                       [--template-count 140] [--system-count 200] [--checkpoint-count 80]
                       [--foreign-checkpoint-count 48] [--seed 7]
                       [--timeout 30] [--signals]
Exit status 0 when every scene passes; the failures are listed with the scene text saved
under the report directory (default build/fuzz_failures).
"""
import argparse
import glob
import math
import os
import random
import re
import shutil
import stat
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# values a careless or hostile user might type in place of a number
EXTREME_REALS = ["1e308", "-1e308", "1.7976931348623157e308", "1e309", "-1e400", "4.9e-324", "1e-300",
                 "0", "-0.0", "-1", "nan", "inf", "-inf", "1e20", "-1e20", "9.8696044010893586",
                 "9.869604401089358", "1e200", "3*", "-", "+", "1d5", ".", "1e", "0x10"]
# counts: small ones, or ones the limits refuse (a valid count in the millions would be a
# legitimate long run, not a fault)
EXTREME_COUNTS = ["0", "-1", "1", "2", "3", "2147483647", "2147483648", "-2147483648", "100000001",
                  "99999999999", "1.5", "1e3", "'7'"]
PUNCTUATION = list("/,'\"&=*!#()-+.e \t\n$%:;") + ["&scene", "&chart", "/ &", "''", "=="]
COUNT_NAMES = re.compile(r"\b(n_[a-z_]+|periods|samples_per_period|samples)\b", re.I)
NUMBER = re.compile(r"(?<![A-Za-z_0-9.])[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?")

# shrink the shipped grids so that each run is quick
SHRINK = [(re.compile(r"\b(n_alpha|n_beta)\s*=\s*\d+", re.I), lambda m: m.group(1) + " = 7"),
          (re.compile(r"\b(n_tau)\s*=\s*\d+", re.I), lambda m: m.group(1) + " = 41"),
          (re.compile(r"\b(periods)\s*=\s*\d+", re.I), lambda m: m.group(1) + " = 2"),
          (re.compile(r"\b(samples_per_period)\s*=\s*\d+", re.I), lambda m: m.group(1) + " = 10"),
          # the regions and their edges: order 1, 3 levels
          (re.compile(r"\b(levels)\s*=\s*\d+", re.I), lambda m: m.group(1) + " = 3"),
          (re.compile(r"(&regions\b[^/]*\border)\s*=\s*\d+", re.I), lambda m: m.group(1) + " = 1")]


def shrink(text):
    for pattern, repl in SHRINK:
        text = pattern.sub(repl, text)
    # charts without an explicit count use the default 200 x 200: make them small too
    if re.search(r"&chart\b", text, re.I):
        for name in ("n_alpha", "n_beta"):
            if not re.search(r"\b%s\s*=" % name, text, re.I):
                text = re.sub(r"(&chart\b)", r"\1 %s = 6," % name, text, count=1, flags=re.I)
    return text


def mutate(text, rng):
    """One to three random mutations of a scene text."""
    for _ in range(rng.randint(1, 3)):
        kind = rng.randrange(10)
        if kind == 0 and text:  # delete a character
            i = rng.randrange(len(text))
            text = text[:i] + text[i + 1:]
        elif kind == 1:  # insert punctuation
            i = rng.randrange(len(text) + 1)
            text = text[:i] + rng.choice(PUNCTUATION) + text[i:]
        elif kind in (2, 3, 4):  # replace a number by an extreme value
            numbers = list(NUMBER.finditer(text))
            if numbers:
                m = rng.choice(numbers)
                before = text[:m.start()]
                names = COUNT_NAMES.findall(before[-40:])
                value = rng.choice(EXTREME_COUNTS if names and before.rstrip().endswith("=") else EXTREME_REALS)
                text = before + value + text[m.end():]
        elif kind == 5:  # drop a line
            lines = text.split("\n")
            del lines[rng.randrange(len(lines))]
            text = "\n".join(lines)
        elif kind == 6:  # double a line
            lines = text.split("\n")
            i = rng.randrange(len(lines))
            lines.insert(i, lines[i])
            text = "\n".join(lines)
        elif kind == 7:  # swap two lines
            lines = text.split("\n")
            i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
            lines[i], lines[j] = lines[j], lines[i]
            text = "\n".join(lines)
        elif kind == 8:  # cut short
            text = text[:rng.randrange(len(text) + 1)]
        else:  # no final newline, or a string made long
            if rng.random() < 0.5:
                text = text.rstrip("\n")
            else:
                quotes = [m.start() for m in re.finditer("'", text)]
                if quotes:
                    i = rng.choice(quotes) + 1
                    text = text[:i] + "x" * rng.choice([10, 4100, 70000]) + text[i:]
    return text


# points files: what a careless or hostile points file may hold in place of a number
MALFORMED_NUMBERS = ["1.2.3", "1e", "--1", "+-2", "+", "-", ".", "1d", "0x10", "3*1", "3*", "1,", ",", "/", "1e99999",
                     "1e-99999", "1_8", "1..5", "e5", "1e+", "(1)", "'1'", "\"2\"", "1 .5", "T", ".true.", "1/2",
                     "\u0663", "\u22122", "1\u00a0000", "9" * 400, "0." + "0" * 400 + "1"]
NONFINITE_TEXTS = ["nan", "NaN", "-nan", "inf", "-inf", "+Inf", "Infinity", "-infinity", "nan(0x1)", "infinit", "NAN()"]
EXTREME_POINT_VALUES = ["1e308", "-1e308", "1e309", "4.9e-324", "1e-320", "0", "-0.0", "-1", "9.8696044010893586",
                        "9.869604401089358", "9.87", "1e15", "1e16", "-1e15", "1e6", "123456789012345678901234567890"]
MAX_POINTS = 1000000          # hillstab_batch_scene_checks: max_points
MAX_LINE_LENGTH = 65536       # hillstab_batch_scene_file: max_line_length
# what `&points file =` may name instead of the mutated file (fixtures made in the work directory)
POINTS_ROUTES = ["missing_points.dat", "", " ", "data", "data/", "/dev/zero", "/dev/null", "fuzz.fifo",
                 "link_points.dat", "dangling_link.dat", "data/points/fig4.dat", "./fuzz_points.dat",
                 "fuzz_points.dat/", "x" * 300 + ".dat", "x" * 5000, "fuzz.nml", "out"]


# what a &system matrix may be named as instead of a file of its rows
MATRIX_ROUTES = ["no_such_matrix.txt", "fuzz.fifo", "data", "data/", "/dev/null", "/dev/zero", "dangling_link.dat",
                 "out", "fuzz_matrix.txt/"]
SYSTEM_MATRICES = ("mass", "damping", "gyroscopic", "k0", "b", "cos", "sin")
# entries a matrix file or list might carry
EXTREME_ENTRIES = ["1e308", "-1e308", "1e309", "4.9e-324", "1e-300", "1e154", "1e200", "-1e15", "1e15", "nan",
                   "inf", "-inf", "0", "1d5", "3*1", "-", "1e"]


def system_group(text):
    """The match of a scene's &system group: group(1) is its body (up to the closing '/')."""
    return re.search(r"(?im)^\s*&system\b([^/]*)/", text)


def system_items(body):
    """The (name, value) items of a &system body, names lower case."""
    parts = re.split(r"\b([A-Za-z_][A-Za-z_0-9]*)\s*=", body)
    return [(parts[i].lower(), parts[i + 1].strip().rstrip(",").strip()) for i in range(1, len(parts) - 1, 2)]


def matrix_rows(items, name):
    """The rows of matrix `name` of a &system group (the default when it is not given), as
    lists of number texts; the dimension n."""
    values = dict(items)
    n = int(float(values.get("n", "1")))
    if name in values:
        numbers = [x for x in re.split(r"[,\s]+", values[name]) if x]
    else:
        identity = name in ("mass", "b")
        numbers = [("1.0" if identity and i == j else "0.0") for i in range(n) for j in range(n)]
    rows = [numbers[k:k + n] for k in range(0, len(numbers), n)] or [["1.0"]]
    return rows, n


def mutate_matrix(rows, rng):
    """One to three mutations of a matrix file given as its rows; returns bytes and whether
    the result is still the rows as written (comments, closing commas, tabs)."""
    lines = [" ".join(row) for row in rows]
    data = None
    for _ in range(rng.randint(1, 3)):
        if data is not None:
            break
        kind = rng.randrange(14)
        i = rng.randrange(len(lines))
        if kind == 0:  # NUL bytes
            raw = "\n".join(lines).encode()
            at = rng.randrange(len(raw) + 1)
            data = raw[:at] + b"\0" * rng.choice([1, 2]) + raw[at:] + b"\n"
        elif kind == 1:  # empty fields
            lines[i] = rng.choice([lines[i].replace(" ", ",,", 1), "," + lines[i], lines[i].replace(" ", ", ,", 1)])
        elif kind == 2:  # ragged: a number dropped, moved to the next row, or added
            fields = lines[i].split()
            action = rng.randrange(3)
            if action == 0 and len(fields) > 1:
                lines[i] = " ".join(fields[:-1])
            elif action == 1 and i + 1 < len(lines):
                lines[i + 1] = fields[-1] + " " + lines[i + 1]
                lines[i] = " ".join(fields[:-1])
            else:
                lines[i] = lines[i] + " 0.5"
        elif kind == 3:  # a line of commas or blanks and commas
            lines.insert(i, rng.choice([",", ",,", " , ", "\t,"]))
        elif kind == 4:  # line ends
            data = ("\r\n" if rng.random() < 0.5 else "\r").join(lines).encode() + b"\r\n"
        elif kind == 5:  # an extreme or non-finite entry
            fields = lines[i].split()
            fields[rng.randrange(len(fields))] = rng.choice(EXTREME_ENTRIES)
            lines[i] = " ".join(fields)
        elif kind == 6:  # binary junk
            junk = bytes(rng.randrange(256) for _ in range(rng.choice([1, 16, 512])))
            data = "\n".join(lines).encode() + b"\n" + junk
        elif kind == 7:  # a very long line
            n = rng.choice([MAX_LINE_LENGTH, MAX_LINE_LENGTH + 1, 70000])
            lines.insert(i, rng.choice(["1" * n, " " * n + "1", "#" * n]))
        elif kind == 8:  # comments and blank lines (fine)
            lines.insert(i, rng.choice(["# a comment", "", "   ", "\t"]))
            lines[i] = lines[i] + rng.choice(["", "  # row"])
        elif kind == 9:  # all rows on one line (the wrong width unless n = 1)
            lines = [" ".join(lines)]
        elif kind == 10:  # closing commas, commas between, tabs (fine)
            lines = [rng.choice([l.replace(" ", ", ") + ",", l.replace(" ", "\t"), l.replace(" ", " , ")])
                     for l in lines]
        elif kind == 11:  # cut short
            text = "\n".join(lines)
            lines = [text[:rng.randrange(len(text) + 1)]]
        elif kind == 12:  # UTF-16, a byte-order mark
            data = ("\n".join(lines) + "\n").encode("utf-16") if rng.random() < 0.5 else \
                b"\xef\xbb\xbf" + ("\n".join(lines) + "\n").encode()
        else:  # a row dropped or doubled (the wrong count of rows)
            if rng.random() < 0.5 and len(lines) > 1:
                del lines[i]
            else:
                lines.insert(i, lines[i])
    return data if data is not None else ("\n".join(lines) + "\n").encode()


def system_cases(texts, count, rng):
    """`count` cases of (name, scene text, files, message_names, must_refuse) from the shipped
    system scenes: a matrix given as a mutated file, as a route to something else, or the
    scene read otherwise than written (see the module's text)."""
    bases = [(name, text) for name, text in texts if system_group(text)]
    for k in range(count):
        name, scene = bases[k % len(bases)]
        m = system_group(scene)
        items = system_items(m.group(1))
        given = [n for n, _ in items if n in SYSTEM_MATRICES]
        variable = rng.choice(given) if given and rng.random() < 0.7 else rng.choice(SYSTEM_MATRICES)
        rows, n = matrix_rows(items, variable)
        body = m.group(1)
        # the group without `variable`, then the variable added at its start
        others = ", ".join("%s = %s" % (a, v) for a, v in items if a != variable)
        kind = rng.randrange(10)
        files = {}
        names, must = None, False
        if kind <= 3:
            path = "fuzz_matrix.txt"
            files = {path: mutate_matrix(rows, rng)}
            new_body = " %s = '%s', %s\n" % (variable, path, others)
            label = "matrix file"
        elif kind == 4:
            route = rng.choice(MATRIX_ROUTES)
            new_body = " %s = '%s', %s\n" % (variable, route, others)
            label = "route " + route
            names, must = "&system: %s:" % variable, True
        elif kind == 5:  # the path across a line break
            path = "fuzz_matrix.txt"
            files = {path: ("\n".join(" ".join(r) for r in rows) + "\n").encode()}
            cut = rng.randrange(1, len(path))
            new_body = " %s = '%s\n%s', %s\n" % (variable, path[:cut], path[cut:], others)
            label = "path across lines"
            names, must = "&system: %s: a quoted string runs on" % variable, True
        elif kind == 6:  # a variable given twice
            twice = rng.choice([a for a, _ in items])
            value = dict(items)[twice]
            new_body = body.rstrip() + ",\n   %s = %s\n" % (twice, value)
            label = "%s twice" % twice
            names, must = "&system: %s: given twice" % twice, True
        elif kind == 7:  # a subscripted variable
            new_body = body.rstrip() + ",\n   %s(1) = 2.0\n" % variable
            label = "%s(1)" % variable
            names, must = "&system: %s:" % variable, True
        elif kind == 8:  # &system given twice
            new_body = body
            label = "second &system"
            names, must = "&system: the group is given 2 times", True
        else:  # extreme entries in the list
            numbers = [x for row in rows for x in row]
            numbers[rng.randrange(len(numbers))] = rng.choice(EXTREME_ENTRIES)
            new_body = " %s = %s, %s\n" % (variable, ", ".join(numbers), others)
            label = "extreme %s" % variable
        text = scene[:m.start(1)] + new_body + scene[m.end(1):]
        if kind == 8:
            text = text + "&system" + body + "/\n"
        yield "%s (%s)" % (name, label), text, files, names, must


def mutate_points(text, rng):
    """One to three random mutations of a points file; returns bytes."""
    data = None  # set when a mutation leaves text for bytes
    for _ in range(rng.randint(1, 3)):
        if data is not None:
            break
        kind = rng.randrange(14)
        numbers = list(NUMBER.finditer(text))
        if kind in (0, 1, 2) and numbers:  # a number replaced: malformed, non-finite, extreme
            m = rng.choice(numbers)
            value = rng.choice([MALFORMED_NUMBERS, NONFINITE_TEXTS, EXTREME_POINT_VALUES][kind])
            text = text[:m.start()] + value + text[m.end():]
        elif kind == 3:  # more lines than the limit (refused after reading them), rarely
            if rng.random() < 0.15:
                text = "1.48 2.47\n" * (MAX_POINTS + 1)
            else:
                text = text + "3.70 2.47\n" * rng.choice([50, 200])
        elif kind == 4 and rng.random() < 0.4:  # empty, comments only, blanks only (now and then)
            text = rng.choice(["", "\n", "# nothing\n", "   \n\t\n", "#", "# " + "c" * 1000 + "\n"])
        elif kind == 5:  # binary junk: a whole file of it, or some inserted
            junk = bytes(rng.randrange(256) for _ in range(rng.choice([1, 16, 512, 4096])))
            raw = text.encode()
            where = rng.randrange(3)
            if where == 0:
                data = junk
            elif where == 1:
                i = rng.randrange(len(raw) + 1)
                data = raw[:i] + junk + raw[i:]
            else:
                data = raw + junk
        elif kind == 6:  # NUL bytes in a line
            raw = text.encode()
            i = rng.randrange(len(raw) + 1)
            data = raw[:i] + b"\0" * rng.choice([1, 3]) + raw[i:]
        elif kind == 7:  # a very long line: at the limit, beyond it; digits, blanks or a comment
            n = rng.choice([MAX_LINE_LENGTH - 1, MAX_LINE_LENGTH, MAX_LINE_LENGTH + 1, 70000, 300000])
            line = rng.choice(["1.48 2.47 " + "x" * n, "1.48 " + "0" * n + "2.47", " " * n + "1.48 2.47",
                               "#" * n, "1" * n])
            lines = text.split("\n")
            lines.insert(rng.randrange(len(lines) + 1), line[:n])
            text = "\n".join(lines)
        elif kind == 8:  # line ends: CRLF, CR only, mixed
            choice = rng.randrange(3)
            if choice == 0:
                text = text.replace("\n", "\r\n")
            elif choice == 1:
                text = text.replace("\n", "\r")
            else:
                text = "".join(c + ("\r" if c == "\n" and rng.random() < 0.5 else "") for c in text)
        elif kind == 9:  # separators: commas, tabs, a byte-order mark, UTF-16
            choice = rng.randrange(5)
            if choice == 0:
                text = re.sub(r"(\d) +(\d)", r"\1,\2", text)
            elif choice == 1:
                text = re.sub(r"(\d) +(\d)", r"\1 ,, \2", text)
            elif choice == 2:
                text = text.replace(" ", "\t")
            elif choice == 3:
                text = "\ufeff" + text
            else:
                data = text.encode("utf-16")
        elif kind == 10:  # drop, double or swap lines
            lines = text.split("\n")
            i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
            action = rng.randrange(3)
            if action == 0:
                del lines[i]
            elif action == 1:
                lines.insert(i, lines[i])
            else:
                lines[i], lines[j] = lines[j], lines[i]
            text = "\n".join(lines)
        elif kind == 11:  # cut short, no final newline
            text = text[:rng.randrange(len(text) + 1)] if rng.random() < 0.5 else text.rstrip("\n")
        elif kind == 12:  # one field per line, or three numbers, or the label first
            text = re.sub(r"^(\S+)\s+(\S+)", rng.choice([r"\1", r"\1 \2 \2", r"(x) \1 \2", r"\1 \2 /"]), text,
                          count=rng.randint(1, 3), flags=re.M)
        else:  # list-directed shortcuts a namelist reader would take
            text = re.sub(r"^(\S+)\s+(\S+)", rng.choice([r"\1 /", r",\2", r"2*\1", r"\1,,\2", r"/"]), text,
                          count=1, flags=re.M)
    return data if data is not None else text.encode("utf-8")


def points_file_value(text):
    """The `file = '...'` of a scene's &points group, or None."""
    return re.search(r"^\s*(&points\b[^/]*?\bfile\s*=\s*)'([^']*)'", text, re.I | re.S | re.M)


def with_points_file(text, name):
    """The scene with its &points file set to `name` (quoted as a namelist string)."""
    m = points_file_value(text)
    quoted = "'" + name.replace("'", "''") + "'"
    return text[:m.start(2) - 1] + quoted + text[m.end(2) + 1:]


def delete_group(text, name):
    """The text without its group &name (from `&name` at the start of a line to its `/` line)."""
    return re.sub(r"^&%s\b[^\n]*\n(?:[^\n]*\n)*?/[^\n]*(?:\n|$)" % name, "", text, count=1, flags=re.M | re.I)


def delete_variable(text, group, name):
    """The text without the line `name = ...` inside group &group."""
    m = re.search(r"^&%s\b.*?^/" % group, text, re.M | re.S | re.I)
    if not m:
        return text
    body = re.sub(r"^\s*%s\s*=[^\n]*\n" % name, "", m.group(0), count=1, flags=re.M | re.I)
    return text[:m.start()] + body + text[m.end():]


def uncomment_optional(text, rng):
    """A template with its optional commented groups (&physical, a commented &points)
    switched on: the lines from `! &group` to `! /` lose their first two characters; then
    mostly as its comment says (the groups and variables it names deleted, sometimes an
    alternative taken: k and m for omega, a range of amplitudes or of omega), else with
    a group deleted at random."""
    prose = " ".join(line[2:] for line in text.split("\n") if line.startswith("! "))
    lines = text.split("\n")
    inside = False
    for i, line in enumerate(lines):
        if re.match(r"^! &\w+", line):
            inside = True
        if inside and line.startswith("! "):
            lines[i] = line[2:]
            if line.startswith("! /"):
                inside = False
    text = "\n".join(lines)
    if rng.random() < 0.8:  # as the template says
        for m in re.finditer(r"delete (?:the )?&(\w+)(?: \(or &(\w+)\))?", prose):
            for name in m.groups():
                if name:
                    text = delete_group(text, name)
        for m in re.finditer(r"delete ((?:\w+, )*\w+(?: and \w+)?) from &(\w+)|and ((?:\w+, )*\w+) from &(\w+)", prose):
            names, group = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
            for name in re.split(r", | and ", names):
                text = delete_variable(text, group, name)
    else:
        groups = re.findall(r"^&(\w+)", text, re.M)
        groups = [g for g in groups if g.lower() != "scene"]
        if groups:
            text = delete_group(text, rng.choice(groups))
    alternatives = [(("k", "m"), ("omega",)), (("a_min", "a_max", "n_a"), ("a",)),
                    (("omega_min", "omega_max", "n_omega"), ("omega",))]
    for switched_on, switched_off in alternatives:
        if rng.random() < 0.35 and re.search(r"^! %s =" % switched_on[0], text, re.M):
            for name in switched_on:
                text = re.sub(r"^! (%s) =" % name, r"\1 =", text, count=1, flags=re.M)
            for name in switched_off:
                text = delete_variable(text, "physical", name)
    return text


def task_names(hillstab):
    """The tasks the program lists in --help ("Tasks: chart, points, ...")."""
    out = subprocess.run([hillstab, "--help"], stdout=subprocess.PIPE, check=True).stdout.decode()
    m = re.search(r"Tasks:\s*([a-z_]+(?:,\s*[a-z_]+)*)", out)
    if not m:
        sys.exit("fuzz: no task list in hillstab --help")
    return [t.strip() for t in m.group(1).split(",")]


def template_texts(hillstab):
    """Every task's template, shrunk (physical counts too)."""
    texts = []
    for task in task_names(hillstab):
        proc = subprocess.run([hillstab, "--template", task], stdout=subprocess.PIPE, check=True)
        text = shrink(proc.stdout.decode())
        text = re.sub(r"\b(n_a|n_omega)(\s*=\s*)\d+", r"\1\g<2>3", text)
        texts.append(("template_" + task, text))
    return texts


def data_rows_ok(path):
    """Whether a text output file has whole numeric rows: no NaN/Inf, equal column counts."""
    with open(path, "rb") as f:
        raw = f.read()
    if b"format: binary" in raw[:20000]:
        return True, ""  # binary records: the writer's byte count is checked by its tests
    text = raw.decode("utf-8", "replace")
    if text and not text.endswith("\n"):
        return False, "no final newline (cut short?)"
    n_columns = None
    for number, line in enumerate(text.split("\n"), 1):
        fields = line.split()
        if not fields or line.startswith("#"):
            continue
        if not re.match(r"^[-+0-9.]", fields[0]):
            continue  # a names line
        for field in fields:
            low = field.lower()
            if "nan" in low or "inf" in low:
                return False, "line %d: non-finite value '%s'" % (number, field)
            try:
                if not math.isfinite(float(field)):
                    return False, "line %d: '%s'" % (number, field)
            except ValueError:
                return False, "line %d: not a number '%s'" % (number, field)
        if n_columns is None:
            n_columns = len(fields)
        elif len(fields) != n_columns:
            return False, "line %d: %d columns, %d before" % (number, len(fields), n_columns)
    return True, ""


def snapshot(directory):
    files = {}
    for path in glob.glob(os.path.join(directory, "**", "*"), recursive=True):
        if os.path.isfile(path):
            st = os.stat(path)
            files[path] = (st.st_size, st.st_mtime_ns)
    return files


def run_one(hillstab, text, work, timeout, files=None, message_names=None, must_refuse=False):
    """Run one scene (with `files`, name -> bytes, written beside it); return a list of
    problems (empty: pass) and the exit status. With `message_names`, an exit 1 or 2 must
    name it (e.g. "&points: file:"); with `must_refuse`, the run must exit 2."""
    scene = os.path.join(work, "fuzz.nml")
    with open(scene, "w", encoding="utf-8", errors="replace") as f:
        f.write(text)
    for name, data in (files or {}).items():
        with open(os.path.join(work, name), "wb") as f:
            f.write(data)
    sentinel = os.path.join(work, "out", "sentinel.dat")
    before = snapshot(work)
    start = time.monotonic()
    try:
        proc = subprocess.run([hillstab, "--quiet", "fuzz.nml"], cwd=work, stdin=subprocess.DEVNULL,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout)
    except subprocess.TimeoutExpired:
        return ["no answer within %g s" % timeout], None, timeout
    elapsed = time.monotonic() - start
    problems = []
    status = proc.returncode
    err_lines = proc.stderr.decode("utf-8", "replace").splitlines()
    err_lines = [l for l in err_lines if not l.startswith("hillstab: warning:")]
    if status in (0, 3):
        after = snapshot(work)
        written = [p for p in after if p != scene and before.get(p) != after[p]]
        for path in written:
            if path.endswith(".dat") or ".dat" in os.path.basename(path):
                ok, why = data_rows_ok(path)
                if not ok:
                    problems.append("%s: %s" % (os.path.relpath(path, work), why))
        if status == 3 and len(err_lines) != 1:
            problems.append("exit 3 with %d stderr lines" % len(err_lines))
        if status == 0 and err_lines:
            problems.append("exit 0 with stderr: " + " | ".join(err_lines[:3]))
    elif status in (1, 2):
        if len(err_lines) != 1 or not err_lines[0].startswith("hillstab: "):
            problems.append("exit %d with %d stderr lines: %s" % (status, len(err_lines), " | ".join(err_lines[:4])))
        elif message_names and message_names not in err_lines[0]:
            problems.append("exit %d, the message does not name %s: %s" % (status, message_names, err_lines[0][:300]))
    else:
        problems.append("exit status %d: %s" % (status, " | ".join(err_lines[:4])))
    if must_refuse and status != 2:
        problems.append("exit %d where the scene must be refused (exit 2)" % status)
    leftovers = [p for p in glob.glob(os.path.join(work, "**", "*.part*"), recursive=True)]
    if leftovers:
        problems.append("temporary files left: " + ", ".join(os.path.relpath(p, work) for p in leftovers))
    with open(sentinel) as f:
        if f.read() != "sentinel\n":
            problems.append("the sentinel output was changed")
    return problems, status, elapsed


def check_signals(hillstab, work):
    """SIGINT, SIGTERM, SIGHUP during a chart: exit 128 + signal, no temporary file, the
    old output kept. Returns a list of problems."""
    import signal
    problems = []
    scene = os.path.join(work, "signal.nml")
    with open(scene, "w") as f:
        f.write("&scene method='magnus6', tolerance=1e-12, output='out/signal' /\n"
                "&chart n_alpha=200, n_beta=200 /\n")
    old = os.path.join(work, "out", "signal_chart.dat")
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        with open(old, "w") as f:
            f.write("old\n")
        # the chart waits after its first row (the test hook), so that the signal lands
        # mid-run whatever the machine's speed
        err_path = os.path.join(work, "signal.err")
        env = dict(os.environ, HILLSTAB_TEST_PAUSE_AFTER_UNITS="1")
        with open(err_path, "w") as err:
            proc = subprocess.Popen([hillstab, "--quiet", "signal.nml"], cwd=work, stdin=subprocess.DEVNULL,
                                    stdout=subprocess.DEVNULL, stderr=err, env=env)
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and proc.poll() is None:
            with open(err_path) as f:
                if "test hook: paused" in f.read():
                    break
            time.sleep(0.05)
        with open(err_path) as f:
            paused = "test hook: paused" in f.read()
        os.remove(err_path)
        if not paused:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
            problems.append("signal %d: precondition not reached: the chart ended (status %s) or ran a minute "
                            "before it paused after its first row; nothing was tested" % (sig, proc.returncode))
            continue
        proc.send_signal(sig)
        try:
            status = proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            problems.append("signal %d: still running 20 s later" % sig)
            continue
        if status != 128 + sig:
            problems.append("signal %d: exit status %d, expected %d" % (sig, status, 128 + sig))
        if glob.glob(old + ".part*"):
            problems.append("signal %d: temporary file left" % sig)
        with open(old) as f:
            if f.read() != "old\n":
                problems.append("signal %d: the old output was changed" % sig)
    os.remove(old)
    os.remove(scene)
    return problems


def check_signal_timing(hillstab, work, runs=60, seed=11):
    """SIGTERM at random moments of a short chart, the end (rename) included: the exit
    status must tell what is on disk. Exit 0: the new, complete file (with, when the
    signal came after it was written, the message saying so); 143: the old file,
    untouched. Never a temporary file left. Returns a list of problems."""
    import signal
    problems = []
    rng = random.Random(seed)
    scene = os.path.join(work, "timing.nml")
    with open(scene, "w") as f:
        f.write("&scene method='formula', output='out/timing' /\n&chart n_alpha=150, n_beta=150 /\n")
    out = os.path.join(work, "out", "timing_chart.dat")
    start = time.monotonic()
    subprocess.run([hillstab, "--quiet", "timing.nml"], cwd=work, check=True)
    duration = time.monotonic() - start
    with open(out) as f:
        complete = f.read()
    counts = {0: 0, 143: 0}
    for _ in range(runs):
        with open(out, "w") as f:
            f.write("old\n")
        proc = subprocess.Popen([hillstab, "--quiet", "timing.nml"], cwd=work, stdin=subprocess.DEVNULL,
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        time.sleep(rng.uniform(0.5, 1.3) * duration)
        if proc.poll() is None:
            proc.send_signal(signal.SIGTERM)
        try:
            _, err = proc.communicate(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            problems.append("timing: still running 20 s after the signal")
            continue
        status = proc.returncode
        with open(out) as f:
            now = f.read()
        counts[status] = counts.get(status, 0) + 1
        if status == 0:
            if now != complete:
                problems.append("timing: exit 0 but the file is not the complete new one")
        elif status == 143:
            if now != "old\n":
                problems.append("timing: exit 143 but the old file was replaced")
        else:
            problems.append("timing: exit status %d" % status)
        if glob.glob(out + ".part*"):
            problems.append("timing: temporary file left")
    print("fuzz: SIGTERM at random moments of a %.2f s chart: %d runs ended written (exit 0), %d interrupted "
          "(exit 143)" % (duration, counts.get(0, 0), counts.get(143, 0)))
    os.remove(out)
    os.remove(scene)
    return problems


# checkpoint fixtures: (name, scene text with OUT for the output prefix, the unit to kill after)
CHECKPOINT_SCENES = [
    ("chart", "&scene method='formula', output='OUT' /\n&chart n_alpha=24, n_beta=40 /\n", 9),
    ("points", "&scene task='points', method='magnus6', output='OUT' /\n&points file='data/points/fig4.dat' /\n", 2),
    ("lyapunov", "&scene task='lyapunov', output='OUT' /\n&series phi0=0.017, periods=3 /\n"
     "&lyapunov lanes=1, early_stop=.false. /\n&chart n_alpha=6, n_beta=12 /\n", 3),
    ("binary", "&scene method='formula', format='binary', output='OUT' /\n&chart n_alpha=24, n_beta=40 /\n", 9),
]


def checkpoint_file(name):
    """The output of the checkpoint scene `name`, under ck/ (a binary chart's is .bin)."""
    return "binary_chart.bin" if name == "binary" else "%s_%s.dat" % (name, name)

#: system scenes writing the output of the checkpoint fixture of the same name (a system run
#: meets the checkpoint of another kind of problem)
SYSTEM_PAIR = ("&system n = 2, mass = 1.0, 0.0, 0.0, 0.25, b = 2.0, -1.0, -1.0, 1.5, "
               "cos = -1.0, 0.0, 0.0, -0.5 /\n")
CHECKPOINT_SYSTEM_SCENES = {
    "chart": "&scene model='system', method='magnus4', tolerance=1e-6, output='OUT' /\n" + SYSTEM_PAIR +
             "&chart n_alpha=3, n_beta=4 /\n",
    "points": "&scene model='system', task='points', method='magnus4', tolerance=1e-6, output='OUT' /\n" +
              SYSTEM_PAIR + "&points file='data/points/fig4.dat' /\n",
}
#: what `plant_member` puts in place of a checkpoint's data or state
MEMBER_PLANTS = ("data: a FIFO", "state: a FIFO", "state: a directory", "data: a directory",
                 "state: a symbolic link to data", "data: a symbolic link to state")


def plant_member(directory, plant):
    """Replace the member of a checkpoint that `plant` names by a FIFO, a directory or a link."""
    member, what = plant.split(": ")
    path = os.path.join(directory, member)
    os.remove(path)
    if what == "a FIFO":
        os.mkfifo(path)
    elif what == "a directory":
        os.mkdir(path)
        with open(os.path.join(path, "x"), "w") as f:
            f.write("precious\n")
    else:
        os.symlink("state" if member == "data" else "data", path)


def mutate_checkpoint(directory, rng):
    """One to three seeded mutations of a checkpoint's data or state; returns their names."""
    names = []
    data_path = os.path.join(directory, "data")
    state_path = os.path.join(directory, "state")
    with open(state_path, "rb") as f:
        state = f.read()
    m = re.search(rb"^bytes = (\d+)$", state, re.M)
    recorded = int(m.group(1)) if m else 0
    for _ in range(rng.randint(1, 3)):
        with open(data_path, "rb") as f:
            data = f.read()
        with open(state_path, "rb") as f:
            state = f.read()
        kind = rng.randrange(14)
        inside = rng.randrange(max(1, min(recorded, len(data))))
        if kind == 0 and data:  # a byte flipped among the recorded ones
            data = data[:inside] + bytes([data[inside] ^ (1 << rng.randrange(8))]) + data[inside + 1:]
            names.append("data: byte %d flipped" % inside)
        elif kind == 1:  # a digit changed in a data row
            digits = [k.start() for k in re.finditer(rb"[0-9]", data[:recorded]) if data.rfind(b"#", 0, k.start()) <
                      data.rfind(b"\n", 0, k.start())]
            if digits:
                k = rng.choice(digits)
                data = data[:k] + str((int(data[k:k + 1]) + rng.randint(1, 9)) % 10).encode() + data[k + 1:]
                names.append("data: digit %d changed" % k)
        elif kind == 2:  # a new line planted, or a byte inserted or deleted
            what = rng.choice([b"\n", b" ", b"7", b""])
            if what:
                data = data[:inside] + what + data[inside:]
                names.append("data: %r inserted at %d" % (what, inside))
            else:
                data = data[:inside] + data[inside + 1:]
                names.append("data: byte %d deleted" % inside)
        elif kind == 3:  # the header edited (the scene it states)
            data, n = re.subn(rb"(n_[a-z]+ = )(\d+)", lambda x: x.group(1) + str(int(x.group(2)) + 1).encode(), data,
                              count=1)
            names.append("data: header edited" if n else "data: header unchanged")
        elif kind == 4:  # cut short, or bytes after the recorded ones (a write the kill cut short)
            if rng.random() < 0.5:
                data = data[:rng.randrange(len(data) + 1)]
                names.append("data: cut to %d bytes" % len(data))
            else:
                data = data + rng.choice([b"1.0 2.0 partial", b"\n\n", bytes(rng.randrange(256) for _ in range(40))])
                names.append("data: bytes appended")
        elif kind in (5, 6, 7):  # a number of the state changed
            numbers = list(re.finditer(rb"(?<=[ =])(\d+)(?=[ \n])", state))
            if numbers:
                k = rng.choice(numbers)
                value = int(k.group(1))
                new = rng.choice([value + 1, max(0, value - 1), 0, value * 2, value + 1000])
                state = state[:k.start()] + str(new).encode() + state[k.end():]
                names.append("state: %d -> %d" % (value, new))
        elif kind == 8:  # a line dropped, doubled or swapped
            lines = state.split(b"\n")
            i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
            action = rng.randrange(3)
            if action == 0:
                del lines[i]
            elif action == 1:
                lines.insert(i, lines[i])
            else:
                lines[i], lines[j] = lines[j], lines[i]
            state = b"\n".join(lines)
            names.append("state: lines %d/%d %s" % (i, j, ["dropped", "doubled", "swapped"][action]))
        elif kind == 9:  # the checksum line edited
            state = re.sub(rb"check = (\w)", lambda x: b"check = " + (b"0" if x.group(1) != b"0" else b"1"), state)
            names.append("state: checksum edited")
        elif kind == 10:  # cut short
            state = state[:rng.randrange(len(state) + 1)]
            names.append("state: cut to %d bytes" % len(state))
        elif kind == 11:  # emptied, junk, the other format
            state = rng.choice([b"", bytes(rng.randrange(256) for _ in range(300)),
                                state.replace(b"hillstab checkpoint 3", b"hillstab checkpoint 2")])
            names.append("state: replaced")
        elif kind == 12:  # the scene lines of the state edited
            state, n = re.subn(rb"(scene = &chart [^\n]*?n_beta = )(\d+)", lambda x: x.group(1) + b"41", state)
            names.append("state: scene edited" if n else "state: scene unchanged")
        else:  # a digit changed in the state's recorded counts line
            state, n = re.subn(rb"^(failed|inaccurate) = (\d+)", lambda x: x.group(1) + b" = " +
                               str(int(x.group(2)) + 1).encode(), state, count=1, flags=re.M)
            names.append("state: counts edited" if n else "state: counts unchanged")
        with open(data_path, "wb") as f:
            f.write(data)
        with open(state_path, "wb") as f:
            f.write(state)
    return names


def check_checkpoints(hillstab, work, count, seed, timeout, system_count=0):
    """Damaged checkpoints (`mutate_checkpoint`) resumed: exit 0 with the uninterrupted file
    or exit 2 with one message naming the checkpoint and no file. Returns (problems, counts)."""
    rng = random.Random(seed * 1000 + 3)
    problems = []
    counts = {}
    base = os.path.join(work, "ck")
    os.makedirs(base, exist_ok=True)
    fixtures = []
    for name, text, unit in CHECKPOINT_SCENES:
        scene = os.path.join(base, name + ".nml")
        with open(scene, "w") as f:
            f.write(text.replace("OUT", "ck/" + name))
        output = os.path.join(work, "ck", checkpoint_file(name))
        subprocess.run([hillstab, "--quiet", scene], cwd=work, check=True, stderr=subprocess.DEVNULL)
        with open(output, "rb") as f:
            reference = f.read()
        os.remove(output)
        # killed while the test hook holds it after `unit` units
        env = dict(os.environ, HILLSTAB_TEST_PAUSE_AFTER_UNITS=str(unit))
        err_path = scene + ".err"
        with open(err_path, "w") as err:
            proc = subprocess.Popen([hillstab, "--quiet", "--checkpoint-interval", "0", scene], cwd=work, env=env,
                                    stdout=subprocess.DEVNULL, stderr=err)
        deadline = time.monotonic() + 60
        paused = False
        while time.monotonic() < deadline and proc.poll() is None:
            with open(err_path) as f:
                if "test hook: paused" in f.read():
                    paused = True
                    break
            time.sleep(0.02)
        proc.kill()
        proc.wait()
        if not paused:
            problems.append("checkpoint %s: precondition not reached: the run ended before it paused after unit %d"
                            % (name, unit))
            continue
        saved = output + ".saved"
        shutil.copytree(output + ".checkpoint", saved)
        shutil.rmtree(output + ".checkpoint")
        for leftover in glob.glob(output + ".part*"):
            os.remove(leftover)
        fixtures.append((name, scene, output, reference, saved))
    if not fixtures:
        return problems, counts
    for k in range(count):
        name, scene, output, reference, saved = fixtures[k % len(fixtures)]
        directory = output + ".checkpoint"
        shutil.copytree(saved, directory)
        damage = mutate_checkpoint(directory, rng)
        label = "checkpoint case %d (%s: %s)" % (k, name, "; ".join(damage))
        try:
            proc = subprocess.run([hillstab, "--quiet", "--resume", scene], cwd=work, stdin=subprocess.DEVNULL,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout)
        except subprocess.TimeoutExpired:
            problems.append(label + ": no answer within %g s" % timeout)
            continue
        status = proc.returncode
        counts[status] = counts.get(status, 0) + 1
        lines = [l for l in proc.stderr.decode("utf-8", "replace").splitlines()
                 if not l.startswith("hillstab: warning:") and "resuming" not in l and
                 "cannot be resumed: its state is not one" not in l and "no checkpoint of" not in l]
        if status == 0:
            with open(output, "rb") as f:
                if f.read() != reference:
                    problems.append(label + ": exit 0 with a file that differs from the uninterrupted run's")
        elif status == 2:
            if len(lines) != 1 or "checkpoint 'ck/%s.checkpoint'" % checkpoint_file(name) not in lines[0]:
                problems.append(label + ": exit 2 without one message naming the checkpoint: " + " | ".join(lines[:3]))
            if os.path.exists(output):
                problems.append(label + ": exit 2 with an output file")
        else:
            problems.append(label + ": exit status %d: %s" % (status, " | ".join(lines[:3])))
        if glob.glob(output + ".part*"):
            problems.append(label + ": temporary file left")
        if status == 2 and k % 5 == 0:
            # without --resume: discarded, the uninterrupted file
            again = subprocess.run([hillstab, "--quiet", scene], cwd=work, stdin=subprocess.DEVNULL,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=timeout)
            with open(output, "rb") as f:
                if again.returncode != 0 or f.read() != reference:
                    problems.append(label + ": a run without --resume did not write the uninterrupted file")
            if os.path.exists(directory):
                problems.append(label + ": the checkpoint survived a run without --resume")
        for path in (output, directory):
            if os.path.isdir(path):
                shutil.rmtree(path)
            elif os.path.exists(path):
                os.remove(path)
    if system_count > 0:
        system_problems, system_counts = check_foreign_checkpoints(hillstab, work, fixtures, system_count, seed,
                                                                   timeout)
        problems += system_problems
        for status, n in system_counts.items():
            counts[status] = counts.get(status, 0) + n
    shutil.rmtree(base, ignore_errors=True)
    return problems, counts


def check_foreign_checkpoints(hillstab, work, fixtures, count, seed, timeout):
    """Checkpoints meeting runs that cannot resume them, or members that are not regular
    files: a scalar checkpoint, intact, damaged (`mutate_checkpoint`), incomplete (no state)
    or with a member that is a FIFO, a directory or a symbolic link (`plant_member`), met by
    the system scene of the same output or by the scalar scene itself, with and without
    --resume. A member that is not a regular file: exit 2 with one message naming the
    checkpoint, the checkpoint kept with the member as planted, no output, in time (a FIFO
    never blocks). Otherwise the system scene discards the checkpoint with a note without
    --resume (exit 0, its file whole) and refuses it with --resume (exit 2 naming the
    checkpoint, kept) unless it was incomplete (discarded, exit 0). Returns (problems,
    counts)."""
    rng = random.Random(seed * 1000 + 4)
    problems = []
    counts = {}
    for k in range(count):
        name, scene, output, reference, saved = fixtures[k % len(fixtures)]
        system_text = CHECKPOINT_SYSTEM_SCENES.get(name)
        use_system = system_text is not None and rng.random() < 0.7
        resume = rng.random() < 0.5
        if use_system and rng.random() < 0.5:
            damage = rng.choice(("intact", "damaged", "incomplete"))
        else:
            damage = rng.choice(MEMBER_PLANTS)
        directory = output + ".checkpoint"
        shutil.copytree(saved, directory)
        names = []
        if damage == "damaged":
            names = mutate_checkpoint(directory, rng)
        elif damage == "incomplete":
            os.remove(os.path.join(directory, "state"))
        elif damage != "intact":
            plant_member(directory, damage)
        run_scene = scene
        if use_system:
            run_scene = scene[:-len(".nml")] + "_system.nml"
            with open(run_scene, "w") as f:
                f.write(system_text.replace("OUT", "ck/" + name))
        label = "foreign checkpoint case %d (%s, %s scene%s: %s%s)" % (
            k, name, "system" if use_system else "scalar", " --resume" if resume else "", damage,
            (": " + "; ".join(names)) if names else "")
        command = [hillstab, "--quiet"] + (["--resume"] if resume else []) + [run_scene]
        try:
            proc = subprocess.run(command, cwd=work, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE, timeout=timeout)
        except subprocess.TimeoutExpired:
            problems.append(label + ": no answer within %g s (blocked?)" % timeout)
            shutil.rmtree(directory, ignore_errors=True)
            continue
        status = proc.returncode
        counts[status] = counts.get(status, 0) + 1
        notes = [l for l in proc.stderr.decode("utf-8", "replace").splitlines()
                 if not l.startswith("hillstab: warning:")]
        lines = [l for l in notes if not l.startswith("hillstab: discarded ") and "no checkpoint of" not in l and
                 ": this run keeps no checkpoint (only" not in l and "cannot be resumed: its state is not one" not in l
                 and not l.startswith("hillstab: resuming ")]
        named = "checkpoint 'ck/%s.checkpoint'" % checkpoint_file(name)
        member_planted = damage in MEMBER_PLANTS
        if status == 2:
            if len(lines) != 1 or named not in lines[0]:
                problems.append(label + ": exit 2 without one message naming the checkpoint: " + " | ".join(lines[:3]))
            if os.path.exists(output):
                problems.append(label + ": exit 2 with an output file")
            if not os.path.isdir(directory):
                problems.append(label + ": exit 2 but the checkpoint is gone")
            elif member_planted:
                member, what = damage.split(": ")
                path = os.path.join(directory, member)
                if what == "a FIFO":
                    planted_kept = os.path.lexists(path) and stat.S_ISFIFO(os.lstat(path).st_mode)
                elif what == "a directory":
                    planted_kept = os.path.isdir(path) and not os.path.islink(path)
                else:
                    planted_kept = os.path.islink(path)
                if not planted_kept:
                    problems.append(label + ": the planted member was not kept as it was")
                other = os.path.join(directory, "state" if member == "data" else "data")
                if not os.path.lexists(other):
                    problems.append(label + ": the other member of the checkpoint was removed")
            if not member_planted and not (use_system and resume and damage in ("intact", "damaged")):
                problems.append(label + ": refused where the run should discard the checkpoint: " +
                                " | ".join(lines[:2]))
        elif status == 0:
            if member_planted:
                problems.append(label + ": exit 0 over a checkpoint member that is not a regular file")
            if use_system and resume and damage == "intact":
                problems.append(label + ": exit 0: a system run took a scalar checkpoint under --resume")
            if not os.path.exists(output):
                problems.append(label + ": exit 0 without an output file")
            else:
                ok, why = data_rows_ok(output)
                if not ok:
                    problems.append(label + ": output: " + why)
            if os.path.exists(directory):
                problems.append(label + ": exit 0 and the checkpoint left in place (a later --resume would take it)")
            if not any(l.startswith("hillstab: discarded ") for l in notes) and not resume:
                problems.append(label + ": the checkpoint discarded without a note")
        else:
            problems.append(label + ": exit status %d: %s" % (status, " | ".join(lines[:3])))
        if glob.glob(output + ".part*"):
            problems.append(label + ": temporary file left")
        if use_system:
            os.remove(run_scene)
        for path in (output, directory):
            if os.path.isdir(path) and not os.path.islink(path):
                shutil.rmtree(path)
            elif os.path.lexists(path):
                os.remove(path)
    return problems, counts


FIXTURES = ("data", "out", "fuzz.nml", "points.dat", "fuzz.fifo", "link_points.dat", "dangling_link.dat")


def make_work_directory():
    """A scratch directory: a copy of data/, out/ with the sentinel, points.dat (the points
    templates name it), a FIFO without a writer, a link to a points file and a dangling one."""
    work = tempfile.mkdtemp(prefix="hillstab_fuzz_")
    shutil.copytree(os.path.join(ROOT, "data"), os.path.join(work, "data"))
    os.makedirs(os.path.join(work, "out"))
    with open(os.path.join(work, "out", "sentinel.dat"), "w") as f:
        f.write("sentinel\n")
    shutil.copy(os.path.join(ROOT, "data", "points", "fig4.dat"), os.path.join(work, "points.dat"))
    os.mkfifo(os.path.join(work, "fuzz.fifo"))
    os.symlink(os.path.join("data", "points", "fig4.dat"), os.path.join(work, "link_points.dat"))
    os.symlink("no_such_points.dat", os.path.join(work, "dangling_link.dat"))
    return work


def clean_work_directory(work):
    """Remove what a case wrote: outputs of this case must not mask the next one's."""
    for path in glob.glob(os.path.join(work, "out", "*")):
        if not path.endswith("sentinel.dat"):
            if os.path.isdir(path) and not os.path.islink(path):
                shutil.rmtree(path, ignore_errors=True)
            else:
                os.remove(path)
    for path in glob.glob(os.path.join(work, "*")):
        if os.path.basename(path) not in FIXTURES:
            if os.path.isdir(path) and not os.path.islink(path):
                shutil.rmtree(path, ignore_errors=True)
            else:
                os.remove(path)


def points_cases(texts, templates, count, rng):
    """`count` cases of (name, scene text, files, message_names): a mutated points file under
    a scene that reads &points, or that scene's &points file pointed elsewhere; now and then
    the scene mutated as well."""
    bases = [(name, text) for name, text in texts + templates if points_file_value(text)]
    point_files = sorted(glob.glob(os.path.join(ROOT, "data", "points", "*.dat")))
    originals = []
    for path in point_files:
        with open(path) as f:
            originals.append(f.read())
    for k in range(count):
        name, scene = bases[k % len(bases)]
        if rng.random() < 0.2:
            route = rng.choice(POINTS_ROUTES)
            scene = with_points_file(scene, route)
            files = {}
            label = "route " + (route if len(route) < 40 else route[:20] + "...(%d)" % len(route))
        else:
            scene = with_points_file(scene, "fuzz_points.dat")
            files = {"fuzz_points.dat": mutate_points(rng.choice(originals), rng)}
            label = "points file"
        names = "&points: file:"
        if rng.random() < 0.15:
            scene = mutate(scene, rng)
            names = None  # the scene's own fault may come first
        yield "%s (%s)" % (name, label), scene, files, names


def template_cases(templates, count, rng):
    """`count` mutated templates, every task in turn; a third with the optional groups on."""
    for k in range(count):
        name, text = templates[k % len(templates)]
        if rng.random() < 1.0 / 3.0:
            text = uncomment_optional(text, rng)
            name += " (optional groups on)"
        yield name, mutate(text, rng)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--hillstab", required=True, help="the hillstab executable")
    parser.add_argument("--count", type=int, default=300, help="number of mutated scenes")
    parser.add_argument("--points-count", type=int, default=90, help="number of mutated points files or routes")
    parser.add_argument("--template-count", type=int, default=140, help="number of mutated templates")
    parser.add_argument("--system-count", type=int, default=200,
                        help="number of system scenes with mutated matrix files, routes or repeats")
    parser.add_argument("--checkpoint-count", type=int, default=80, help="number of damaged checkpoints resumed")
    parser.add_argument("--foreign-checkpoint-count", type=int, default=48,
                        help="number of checkpoints met by a system scene or with a member that is not a file")
    parser.add_argument("--seed", type=int, default=7, help="random seed (same seed, same scenes)")
    # a hang is caught at any limit; the slowest honest case (seed 7: own_pivot_chart with a
    # Fourier drive of 2^31, where auto runs to its step limit at 49 points and reports 21 of
    # them failed) takes 25-30 s on the trap build, 8 s on the release build
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds allowed per scene")
    parser.add_argument("--signals", action="store_true",
                        help="also interrupt a chart with SIGINT, SIGTERM, SIGHUP")
    parser.add_argument("--report", default=os.path.join(ROOT, "build", "fuzz_failures"),
                        help="directory for the scenes that fail")
    args = parser.parse_args()
    hillstab = os.path.abspath(args.hillstab)
    bases = sorted(glob.glob(os.path.join(ROOT, "data", "scenes", "*.nml")))
    if not bases:
        sys.exit("fuzz: no scenes in data/scenes")
    texts = []
    for path in bases:
        with open(path) as f:
            texts.append((os.path.basename(path), shrink(f.read())))
    templates = template_texts(hillstab)
    work = make_work_directory()
    if os.path.isdir(args.report):
        shutil.rmtree(args.report)
    failures = 0
    counts = {}
    slowest = 0.0
    family_seconds = {}

    def scene_cases():
        rng = random.Random(args.seed)  # the stream of the scenes alone: their cases stay as they were
        for k in range(args.count):
            name, base = texts[k % len(texts)]
            yield name, mutate(base, rng), None, None

    # each family draws from its own stream, so that one family's count leaves the others' cases as they are
    families = [("scenes", scene_cases()),
                ("points", points_cases(texts, templates, args.points_count, random.Random(args.seed * 1000 + 1))),
                ("templates", ((n, t, None, None) for n, t in
                               template_cases(templates, args.template_count, random.Random(args.seed * 1000 + 2)))),
                ("systems", system_cases(texts, args.system_count, random.Random(args.seed * 1000 + 4)))]
    try:
        if args.signals:
            problems = check_signals(hillstab, work)
            for p in problems:
                print("FAIL signals: " + p)
            failures += 1 if problems else 0
            print("fuzz: signals %s" % ("failed" if problems else "ok (exit 128 + signal, no temporary file, old file kept)"))
            problems = check_signal_timing(hillstab, work)
            for p in problems:
                print("FAIL signal timing: " + p)
            failures += 1 if problems else 0
        for family, cases in families:
            started = time.monotonic()
            n_cases = 0
            family_counts = {}
            for k, case in enumerate(cases):
                name, text, files, names = case[:4]
                must = case[4] if len(case) > 4 else False
                n_cases += 1
                problems, status, elapsed = run_one(hillstab, text, work, args.timeout, files, names, must)
                slowest = max(slowest, elapsed)
                counts[status] = counts.get(status, 0) + 1
                family_counts[status] = family_counts.get(status, 0) + 1
                if problems:
                    failures += 1
                    os.makedirs(args.report, exist_ok=True)
                    stem = "%s%03d_%s" % ("case" if family == "scenes" else family + "_", k,
                                          re.sub(r"[^A-Za-z0-9_.]+", "_", name)[:60])
                    saved = os.path.join(args.report, stem)
                    with open(saved, "w", encoding="utf-8", errors="replace") as f:
                        f.write(text)
                    for file_name, data in (files or {}).items():
                        with open(saved + "." + file_name, "wb") as f:
                            f.write(data[:1 << 20])
                    print("FAIL %s case %d (from %s, saved as %s):" % (family, k, name, os.path.relpath(saved, ROOT)))
                    for p in problems:
                        print("    " + p[:400])
                clean_work_directory(work)
            family_seconds[family] = (n_cases, time.monotonic() - started)
            print("fuzz: %s: %d cases in %.0f s; %s" % (family, n_cases, time.monotonic() - started, ", ".join(
                "exit %s: %d" % (s, n) for s, n in sorted(family_counts.items(), key=lambda x: str(x[0])))))
        if args.checkpoint_count > 0:
            started = time.monotonic()
            problems, family_counts = check_checkpoints(hillstab, work, args.checkpoint_count, args.seed, args.timeout,
                                                        args.foreign_checkpoint_count)
            for p in problems:
                print("FAIL " + p[:400])
            failures += len(problems)
            for status, n in family_counts.items():
                counts[status] = counts.get(status, 0) + n
            family_seconds["checkpoints"] = (args.checkpoint_count + args.foreign_checkpoint_count,
                                             time.monotonic() - started)
            print("fuzz: checkpoints: %d damaged checkpoints resumed and %d met by system scenes or with planted "
                  "members in %.0f s; %s" % (args.checkpoint_count, args.foreign_checkpoint_count,
                                             time.monotonic() - started, ", ".join(
                    "exit %s: %d" % (s, n) for s, n in sorted(family_counts.items(), key=lambda x: str(x[0])))))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    summary = ", ".join("exit %s: %d" % (s, n) for s, n in sorted(counts.items(), key=lambda x: str(x[0])))
    times = ", ".join("%d %s in %.0f s" % (n, family, t) for family, (n, t) in family_seconds.items())
    print("fuzz: %d cases (seed %d: %s), %d failed; %s; slowest %.1f s" % (sum(counts.values()), args.seed, times,
                                                                          failures, summary, slowest))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
