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
  - finish within the time limit;
  - leave no temporary file (*.part<pid>) and the sentinel untouched.

With --signals, a chart is first interrupted by SIGINT, SIGTERM and SIGHUP: each must
exit 128 + signal, remove its temporary file and keep the old output.

usage: scripts/fuzz.py --hillstab BUILD/app/hillstab [--count 300] [--seed 7] [--timeout 30] [--signals]
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
          (re.compile(r"\b(samples_per_period)\s*=\s*\d+", re.I), lambda m: m.group(1) + " = 10")]


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


def run_one(hillstab, text, work, timeout):
    """Run one scene; return a list of problems (empty: pass) and the exit status."""
    scene = os.path.join(work, "fuzz.nml")
    with open(scene, "w", encoding="utf-8", errors="replace") as f:
        f.write(text)
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
        if status == 0 and err_lines and not all(l.startswith("hillstab: warning:") for l in err_lines):
            problems.append("exit 0 with stderr: " + " | ".join(err_lines[:3]))
    elif status in (1, 2):
        if len(err_lines) != 1 or not err_lines[0].startswith("hillstab: "):
            problems.append("exit %d with %d stderr lines: %s" % (status, len(err_lines), " | ".join(err_lines[:4])))
    else:
        problems.append("exit status %d: %s" % (status, " | ".join(err_lines[:4])))
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
                "&chart n_alpha=2000, n_beta=2000 /\n")
    old = os.path.join(work, "out", "signal_chart.dat")
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        with open(old, "w") as f:
            f.write("old\n")
        proc = subprocess.Popen([hillstab, "--quiet", "signal.nml"], cwd=work, stdin=subprocess.DEVNULL,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        # wait until the temporary file exists (the chart has started writing)
        deadline = time.monotonic() + 20
        while time.monotonic() < deadline and not glob.glob(old + ".part*") and proc.poll() is None:
            time.sleep(0.05)
        time.sleep(0.3)
        if proc.poll() is not None:
            problems.append("signal %d: the chart ended before the signal (status %d)" % (sig, proc.returncode))
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


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--hillstab", required=True, help="the hillstab executable")
    parser.add_argument("--count", type=int, default=300, help="number of mutated scenes")
    parser.add_argument("--seed", type=int, default=7, help="random seed (same seed, same scenes)")
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds allowed per scene")
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
    rng = random.Random(args.seed)
    work = tempfile.mkdtemp(prefix="hillstab_fuzz_")
    shutil.copytree(os.path.join(ROOT, "data"), os.path.join(work, "data"))
    os.makedirs(os.path.join(work, "out"))
    with open(os.path.join(work, "out", "sentinel.dat"), "w") as f:
        f.write("sentinel\n")
    if os.path.isdir(args.report):
        shutil.rmtree(args.report)
    failures = 0
    counts = {}
    slowest = 0.0
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
        for k in range(args.count):
            name, base = texts[k % len(texts)]
            text = mutate(base, rng)
            problems, status, elapsed = run_one(hillstab, text, work, args.timeout)
            slowest = max(slowest, elapsed)
            counts[status] = counts.get(status, 0) + 1
            if problems:
                failures += 1
                os.makedirs(args.report, exist_ok=True)
                saved = os.path.join(args.report, "case%03d_%s" % (k, name))
                with open(saved, "w", encoding="utf-8", errors="replace") as f:
                    f.write(text)
                print("FAIL case %d (from %s, saved as %s):" % (k, name, os.path.relpath(saved, ROOT)))
                for p in problems:
                    print("    " + p[:400])
            # outputs of this case must not mask the next one's
            for path in glob.glob(os.path.join(work, "out", "*")):
                if not path.endswith("sentinel.dat"):
                    if os.path.isdir(path):
                        shutil.rmtree(path, ignore_errors=True)
                    else:
                        os.remove(path)
            for path in glob.glob(os.path.join(work, "*")):
                if os.path.basename(path) not in ("data", "out", "fuzz.nml"):
                    if os.path.isdir(path):
                        shutil.rmtree(path, ignore_errors=True)
                    else:
                        os.remove(path)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    summary = ", ".join("exit %s: %d" % (s, n) for s, n in sorted(counts.items(), key=lambda x: str(x[0])))
    print("fuzz: %d scenes (seed %d), %d failed; %s; slowest %.1f s" % (args.count, args.seed, failures, summary,
                                                                       slowest))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
