#!/usr/bin/env python3
"""Python against the command line, side by side: the same computations through the
package hillstab (one call each, numpy arrays back) and through the program `hillstab` of
the same build (the one pip installs beside the package), in interleaved rounds.

Jobs (method auto, tolerance 1e-10, OpenMP's default threads in both):
  chart      a 300 x 300 chart over alpha in [0, 9.8], beta in [-2, 12], every value
             (the program: every column, format = 'binary')
  verdicts   the same chart, verdicts only (columns = 'alpha beta stable status')
  points     1e5 points (alpha, beta) drawn uniformly from the same box (task points,
             &points file, format = 'binary')
The program's time is its whole run (start, scene, reading the points file, computing,
writing the binary file, into /dev/shm so that the disk does not count); Python's is the
call alone (the arrays built before it). The
values of both are compared to the bit after every round.

Prints a table (median of the rounds, the ratio Python / program) and writes
out/bench_python.dat (one line a job and round). Run it with the Python of an environment
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
    times = {name: {"program": [], "python": []} for name in scenes}
    for name in scenes:  # warm both (page cache, the library's first touch)
        subprocess.run([program, "--quiet", name + ".nml"], cwd=work, check=True, capture_output=True)
        calls[name]()
    for round_ in range(args.rounds):
        for name in scenes:
            start = time.perf_counter()
            subprocess.run([program, "--quiet", name + ".nml"], cwd=work, check=True, capture_output=True)
            times[name]["program"].append(time.perf_counter() - start)
            start = time.perf_counter()
            result = calls[name]()
            times[name]["python"].append(time.perf_counter() - start)
            out = hillstab.read_output(os.path.join(work, outputs[name]))
            if not compare[name](out, result):
                sys.exit("bench_python: {}: the values of Python and of the program differ".format(name))
    shutil.rmtree(work)
    os.makedirs(os.path.dirname(args.output) or ".", exist_ok=True)
    with open(args.output, "w") as handle:
        handle.write("# Python (one call) against the program `hillstab` of the same build (whole run, binary "
                     "output), interleaved rounds; method auto, tolerance 1e-10, threads: OpenMP default ({})\n"
                     "# hillstab {}, program {}\n# columns: job round program_s python_s\n"
                     .format(os.environ.get("OMP_NUM_THREADS", "all cores"), hillstab.__version__, program))
        for name in scenes:
            for k, (p, q) in enumerate(zip(times[name]["program"], times[name]["python"])):
                handle.write("{} {} {:.6f} {:.6f}\n".format(name, k + 1, p, q))
    print("| job | program (whole run) | Python (one call) | Python / program |")
    print("|---|---|---|---|")
    labels = {"chart": "300 x 300 chart, every value", "verdicts": "300 x 300 chart, verdicts only",
              "points": "1e5 points"}
    for name in scenes:
        p = statistics.median(times[name]["program"])
        q = statistics.median(times[name]["python"])
        print("| {} | {:.1f} ms | {:.1f} ms | {:.2f} |".format(labels[name], 1e3 * p, 1e3 * q, q / p))
    print("medians of {} interleaved rounds; the values equal to the bit in every round; data: {}".format(
        args.rounds, args.output))


def same(a, b):
    a = np.ascontiguousarray(a, dtype=np.float64).ravel()
    b = np.ascontiguousarray(b, dtype=np.float64).ravel()
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


if __name__ == "__main__":
    main()
