#!/usr/bin/env python3
"""Python against the command line, side by side: the same computations through the
package hillstab (one call each, numpy arrays back) and through the program `hillstab` of
the same build (the one pip installs beside the package), in interleaved rounds.

Jobs (method auto, tolerance 1e-10, OpenMP's default threads in both):
  chart      a 300 x 300 chart over alpha in [0, 9.8], beta in [-2, 12], every value
             (the program: every column, format = 'binary')
  verdicts   the same chart, verdicts only (columns = 'alpha beta stable status')
  points     1e5 points (alpha, beta) drawn uniformly from the same box (task points,
             &points file, format = 'binary'); the program also runs the scene with
             columns = 'alpha beta' (no trace computed: start, reading the 1e5 points,
             writing), and the table gives its computing as the difference
The program's time is its whole run (start, scene, reading the points file, computing,
writing the binary file, into /dev/shm so that the disk does not count); Python's is the
call alone (the arrays built before it). The
values of both are compared to the bit after every round.

Prints a table (median of the rounds, the ratio Python / program) and writes
out/bench_python.dat (one line a job and round). On a machine shared with other work the
times scatter; `--instructions` adds counts that do not (valgrind's callgrind, one thread):
the instructions of the computing alone, for the program its run less the same run without
computing (columns 'alpha beta'), for Python its call less the same call on one point (10^4 points
there instead of 10^5, to keep callgrind's time short), written to out/bench_python_instructions.dat. Run it with the Python of an environment
where `pip install .` put hillstab:  venv/bin/python scripts/bench_python.py [--rounds N]
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import hillstab

GRID = ((0.0, 9.8, 300), (-2.0, 12.0, 300))
N_POINTS = 100000


def program_path(given):
    if given:
        return given
    candidate = os.path.join(os.path.dirname(sys.executable), "hillstab")
    return candidate if os.path.exists(candidate) else shutil.which("hillstab")


def chart_scene(name, columns):
    (a0, a1, na), (b0, b1, nb) = GRID
    return ("&scene task = 'chart', method = 'auto', tolerance = 1e-10, output = '{}', format = 'binary', "
            "columns = '{}' /\n&chart alpha_min = {}, alpha_max = {}, n_alpha = {}, beta_min = {}, beta_max = {}, "
            "n_beta = {} /\n".format(name, columns, a0, a1, na, b0, b1, nb))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--program", help="the hillstab program (default: beside this python)")
    parser.add_argument("--output", default="out/bench_python.dat")
    parser.add_argument("--workdir", default="/dev/shm" if os.path.isdir("/dev/shm") else None,
                        help="where the program writes (default: /dev/shm, memory, so that the program's "
                             "time is its computing more than the disk's)")
    parser.add_argument("--instructions", action="store_true",
                        help="also count the computing's instructions with valgrind (one thread)")
    args = parser.parse_args()
    program = program_path(args.program)
    if not program:
        sys.exit("bench_python: no hillstab program beside {} (pip install . puts it there)".format(sys.executable))
    work = tempfile.mkdtemp(prefix="hillstab_bench_", dir=args.workdir)
    rng = np.random.default_rng(2024)
    alpha = rng.uniform(0.0, 9.8, N_POINTS)
    beta = rng.uniform(-2.0, 12.0, N_POINTS)
    with open(os.path.join(work, "points.txt"), "w") as handle:
        handle.write("".join("{!r} {!r}\n".format(float(a), float(b)) for a, b in zip(alpha, beta)))
    scenes = {
        "chart": chart_scene("chart", ""),
        "verdicts": chart_scene("verdicts", "alpha beta stable status"),
        "points": "&scene task = 'points', method = 'auto', tolerance = 1e-10, output = 'points', "
                  "format = 'binary' /\n&points file = 'points.txt' /\n",
    }
    with open(os.path.join(work, "points_io.nml"), "w") as handle:
        handle.write(scenes["points"].replace("format = 'binary'", "format = 'binary', columns = 'alpha beta'")
                     .replace("output = 'points'", "output = 'points_io'"))
    io_times = []
    outputs = {"chart": "chart_chart.bin", "verdicts": "verdicts_chart.bin", "points": "points_points.bin"}
    for name, text in scenes.items():
        with open(os.path.join(work, name + ".nml"), "w") as handle:
            handle.write(text)
    calls = {
        "chart": lambda: hillstab.chart(*GRID),
        "verdicts": lambda: hillstab.chart(*GRID, values=("stable",)),
        "points": lambda: hillstab.floquet(alpha, beta),
    }
    compare = {
        "chart": lambda out, r: same(out["S"], r.trace) and same(out["mu"], r.exponent) and same(out["stable"], r.stable),
        "verdicts": lambda out, r: same(out["stable"], r.stable),
        "points": lambda out, r: same(out["S"], r.trace) and same(out["mu"], r.exponent),
    }
    times = {name: {"program": [], "python": [], "in_process": []} for name in scenes}
    for name in scenes:  # warm both (page cache, the library's first touch)
        subprocess.run([program, "--quiet", name + ".nml"], cwd=work, check=True, capture_output=True)
        calls[name]()
    for round_ in range(args.rounds):
        for name in scenes:
            start = time.perf_counter()
            subprocess.run([program, "--quiet", name + ".nml"], cwd=work, check=True, capture_output=True)
            times[name]["program"].append(time.perf_counter() - start)
            if name == "points":
                start = time.perf_counter()
                subprocess.run([program, "--quiet", "points_io.nml"], cwd=work, check=True, capture_output=True)
                io_times.append(time.perf_counter() - start)
            start = time.perf_counter()
            result = calls[name]()
            times[name]["python"].append(time.perf_counter() - start)
            here = os.getcwd()
            os.chdir(work)
            try:
                start = time.perf_counter()
                hillstab.scenes._run(name + ".nml", True)
                times[name]["in_process"].append(time.perf_counter() - start)
            finally:
                os.chdir(here)
            out = hillstab.read_output(os.path.join(work, outputs[name]))
            if not compare[name](out, result):
                sys.exit("bench_python: {}: the values of Python and of the program differ".format(name))
    shutil.rmtree(work)
    os.makedirs(os.path.dirname(args.output) or ".", exist_ok=True)
    with open(args.output, "w") as handle:
        handle.write("# Python (one call) against the program `hillstab` of the same build (whole run, binary "
                     "output), interleaved rounds; method auto, tolerance 1e-10, threads: OpenMP default ({})\n"
                     "# hillstab {}, program {}\n# columns: job round program_s python_s scene_in_process_s "
                     "program_without_computing_s (points: columns 'alpha beta'; else 0)\n"
                     .format(os.environ.get("OMP_NUM_THREADS", "all cores"), hillstab.__version__, program))
        for name in scenes:
            for k, (p, q, r) in enumerate(zip(times[name]["program"], times[name]["python"],
                                              times[name]["in_process"])):
                handle.write("{} {} {:.6f} {:.6f} {:.6f} {:.6f}\n".format(
                    name, k + 1, p, q, r, io_times[k] if name == "points" else 0.0))
    print("| job | program (whole run) | its scene in this process | Python (one call) | Python / program |")
    print("|---|---|---|---|---|")
    labels = {"chart": "300 x 300 chart, every value", "verdicts": "300 x 300 chart, verdicts only",
              "points": "1e5 points"}
    for name in scenes:
        p = statistics.median(times[name]["program"])
        q = statistics.median(times[name]["python"])
        r = statistics.median(times[name]["in_process"])
        print("| {} | {:.1f} ms | {:.1f} ms | {:.1f} ms | {:.2f} |".format(labels[name], 1e3 * p, 1e3 * r, 1e3 * q,
                                                                        q / p))
    io = statistics.median(io_times)
    p = statistics.median(times["points"]["program"])
    q = statistics.median(times["points"]["python"])
    print("1e5 points, the program without computing (columns 'alpha beta': start, reading, writing): {:.1f} ms; "
          "its computing {:.1f} ms against Python's {:.1f} ms: {:.2f}".format(1e3 * io, 1e3 * (p - io), 1e3 * q,
                                                                            q / (p - io)))
    if args.instructions:
        instructions(program, args)
    print("medians of {} interleaved rounds; the values equal to the bit in every round; data: {}".format(
        args.rounds, args.output))


def callgrind(command, cwd):
    """Instructions executed by a command under valgrind's callgrind (one OpenMP thread)."""
    env = dict(os.environ, OMP_NUM_THREADS="1")
    done = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"] + command, cwd=cwd,
                          env=env, capture_output=True, text=True, check=True)
    for line in done.stderr.splitlines():
        if "Collected :" in line:
            return int(line.split()[-1])
    raise RuntimeError("no callgrind count: " + done.stderr[-500:])


def instructions(program, args):
    """The instruction counts of the computing, program against Python (see the module doc)."""
    if not shutil.which("valgrind"):
        print("bench_python: valgrind not found: no instruction counts")
        return
    work = tempfile.mkdtemp(prefix="hillstab_count_", dir=args.workdir)
    rng = np.random.default_rng(2024)
    n = 10000
    alpha, beta = rng.uniform(0.0, 9.8, n), rng.uniform(-2.0, 12.0, n)
    np.save(os.path.join(work, "points.npy"), np.stack([alpha, beta]))
    with open(os.path.join(work, "points.txt"), "w") as handle:
        handle.write("".join("{!r} {!r}\n".format(float(a), float(b)) for a, b in zip(alpha, beta)))
    points = "&scene task = 'points', output = 'p', format = 'binary', columns = '{}' /\n&points file = 'points.txt' /\n"
    scenes = {"chart": chart_scene("c", ""), "verdicts": chart_scene("v", "alpha beta stable status"),
              "points": points.format(""), "chart_none": chart_scene("n", "alpha beta"),
              "points_none": points.format("alpha beta")}
    for name, text in scenes.items():
        with open(os.path.join(work, name + ".nml"), "w") as handle:
            handle.write(text)
    calls = {"chart": "hillstab.chart(*GRID)", "verdicts": "hillstab.chart(*GRID, values=('stable',))",
             "points": "hillstab.floquet(*np.load('points.npy'))",
             "chart_none": "hillstab.chart((0.0, 9.8, 1), (-2.0, 12.0, 1))",
             "verdicts_none": "hillstab.chart((0.0, 9.8, 1), (-2.0, 12.0, 1), values=('stable',))",
             "points_none": "hillstab.floquet(*np.load('points.npy')[:, :1])"}
    script = ("import sys, numpy as np, hillstab\nGRID = ((0.0, 9.8, 300), (-2.0, 12.0, 300))\n"
              "exec(sys.argv[1])\n")
    with open(os.path.join(work, "call.py"), "w") as handle:
        handle.write(script)
    count = {}
    for name in scenes:
        count["program " + name] = callgrind([program, "--quiet", name + ".nml"], work)
    for name, call in calls.items():
        count["python " + name] = callgrind([sys.executable, "call.py", call], work)
    shutil.rmtree(work)
    rows = []
    for name, none in (("chart", "chart_none"), ("verdicts", "chart_none"), ("points", "points_none")):
        p = count["program " + name] - count["program " + none]
        q = count["python " + name] - count["python " + name + "_none"]
        rows.append((name, p, q))
    output = os.path.splitext(args.output)[0] + "_instructions.dat"
    with open(output, "w") as handle:
        handle.write("# instructions of the computing (valgrind callgrind, one thread): program run less the run "
                     "without computing, Python call less the same call on one point; points: 1e4\n"
                     "# columns: job program python\n")
        for name, p, q in rows:
            handle.write("{} {} {}\n".format(name, p, q))
    print("| job (instructions of the computing) | program | Python | Python / program |")
    print("|---|---|---|---|")
    labels = {"chart": "300 x 300 chart, every value", "verdicts": "300 x 300 chart, verdicts only",
              "points": "1e4 points"}
    for name, p, q in rows:
        print("| {} | {:.1f} M | {:.1f} M | {:.2f} |".format(labels[name], p / 1e6, q / 1e6, q / p))
    print("instruction counts: " + output)


def same(a, b):
    a = np.ascontiguousarray(a, dtype=np.float64).ravel()
    b = np.ascontiguousarray(b, dtype=np.float64).ravel()
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


if __name__ == "__main__":
    main()
