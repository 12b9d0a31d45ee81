#!/usr/bin/env python3
"""A system chart from Python against the command line's task, on the same library build and
threads (`make bench-python`): the 300 x 300 chart of two coupled pendula (data/scenes/
system_pendula.nml's matrices, tolerance 1e-10) computed by `System.chart` and by the scene
run through the library (`hillstab.run_scene`, the `hillstab` program's own task and file
writing, binary), alternating, several rounds; prints the median times and their ratio, checks
the values are the file's to the bit, and writes build/bench/python_system.dat.

Usage: python3 scripts/bench_python_system.py [--n N] [--rounds R] [--threads T]
(run with the interpreter of the environment where the package is installed: build/venv).
"""
import argparse
import os
import statistics
import tempfile
import time

import numpy as np

import hillstab

MATRICES = dict(mass=[[1.0, 0.0], [0.0, 0.25]], b=[[2.0, -1.0], [-1.0, 1.5]], cos=[[-1.0, 0.0], [0.0, -0.5]])
GROUP = "&system n = 2, mass = 1.0, 0.0, 0.0, 0.25, b = 2.0, -1.0, -1.0, 1.5, cos = -1.0, 0.0, 0.0, -0.5 /\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=300)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--threads", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()
    os.environ["OMP_NUM_THREADS"] = str(args.threads)
    system = hillstab.System(**MATRICES)
    with tempfile.TemporaryDirectory() as work:
        scene = os.path.join(work, "pendula.nml")
        with open(scene, "w") as handle:
            handle.write("&scene task = 'chart', model = 'system', tolerance = 1e-10, format = 'binary', "
                         "output = '{}' /\n".format(os.path.join(work, "p")) + GROUP +
                         "&chart alpha_min = 0.0, alpha_max = 1.5, n_alpha = {0}, beta_min = 0.0, beta_max = 3.0, "
                         "n_beta = {0} /\n".format(args.n))
        python_times, task_times = [], []
        for _ in range(args.rounds):
            start = time.perf_counter()
            chart = system.chart((0.0, 1.5, args.n), (0.0, 3.0, args.n), tolerance=1e-10, threads=args.threads)
            python_times.append(time.perf_counter() - start)
            start = time.perf_counter()
            out = hillstab.run_scene(scene)
            task_times.append(time.perf_counter() - start)
        same = all(np.array_equal(out.data[:, k], np.ravel(chart[name])) for k, name in enumerate(out.columns))
    python_time = statistics.median(python_times)
    task_time = statistics.median(task_times)
    points = args.n * args.n
    print("system chart {0} x {0}, {1} thread(s), median of {2} rounds".format(args.n, args.threads, args.rounds))
    print("{:<34} {:>10} {:>12}".format("", "time [s]", "us / point"))
    print("{:<34} {:>10.3f} {:>12.2f}".format("Python System.chart", python_time, 1e6 * python_time / points))
    print("{:<34} {:>10.3f} {:>12.2f}".format("task chart (run_scene, binary)", task_time, 1e6 * task_time / points))
    print("ratio Python / task: {:.3f}; values the file's to the bit: {}".format(python_time / task_time, same))
    os.makedirs("build/bench", exist_ok=True)
    with open("build/bench/python_system.dat", "w") as handle:
        handle.write("# columns: n threads python_s task_s ratio same\n")
        handle.write("{} {} {:.6f} {:.6f} {:.4f} {}\n".format(args.n, args.threads, python_time, task_time,
                                                              python_time / task_time, int(same)))
    return 0 if same else 1


if __name__ == "__main__":
    raise SystemExit(main())
