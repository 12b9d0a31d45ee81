#!/usr/bin/env python3
"""A chart of a Hill equation of the user's own against the plain C program a user would write
with GSL (`make bench-fourier`).

    python3 scripts/bench_fourier_chart.py HILLSTAB CHART_GSL_FOURIER [--n 300] [--rounds 3]
                                           [--threads 2] [--samples 120] [--out out/bench_fourier_chart.dat]

The model: Q = beta + alpha f, f = cos(pi tau) + 0.4 cos(2 pi tau) + 0.3 sin(3 pi tau) (the
`fourier` model, `&fourier cos = 1, 0.4, 0, sin = 0, 0, 0.3 /`; bench/chart_gsl_fourier.c
writes the same f out), alpha in [0, 9.8], beta in [-2, 12] on an n x n grid (the same doubles).
Timed, as whole runs interleaved in rounds, each the fastest of its rounds: hillstab's full
chart (method auto, tolerance 1e-10, text into SCRATCH) on 1 and on THREADS threads, and the C
program (one thread, writing nothing) at epsabs = epsrel = 1e-8 ... 1e-13.
Accuracy, from untimed runs: the error |S - S_ref|/max(1, |S_ref|) at SAMPLES grid points spread
over the chart, the reference S_ref by hillstab's magnus6 at tolerance 1e-13 (checked against
its rk at 1e-13: their largest difference is printed). "Equal accuracy" pairs hillstab with the
fastest C run whose worst error at those points is no larger than hillstab's.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

FOURIER = "&fourier cos = 1, 0.4, 0, sin = 0, 0, 0.3 /"


def grid_value(lo, hi, n, i):
    if n <= 1:
        return lo
    if i == n:
        return hi
    return lo + (hi - lo) * float(i - 1) / float(n - 1)


def columns_of(path):
    names, rows = None, []
    with open(path) as f:
        for line in f:
            if line.startswith("# columns:"):
                names = line.split(":", 1)[1].split()
            elif line.strip() and not line.startswith("#"):
                rows.append([float(x) for x in line.split()])
    return names, rows


def run(command, env=None):
    start = time.perf_counter()
    subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("hillstab")
    parser.add_argument("chart_gsl")
    parser.add_argument("--n", type=int, default=300)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--samples", type=int, default=120)
    parser.add_argument("--out", default="out/bench_fourier_chart.dat")
    args = parser.parse_args()
    n = args.n
    scratch = tempfile.mkdtemp(dir="/dev/shm" if os.access("/dev/shm", os.W_OK) else None)
    chart = os.path.join(scratch, "chart.nml")
    with open(chart, "w") as f:
        f.write("&scene task = 'chart', model = 'fourier', method = 'auto', tolerance = 1e-10, "
                "output = '%s/fc', columns = 'alpha beta S status' /\n" % scratch)
        f.write("&chart alpha_min = 0, alpha_max = 9.8, n_alpha = %d, beta_min = -2, beta_max = 12, n_beta = %d /\n"
                % (n, n))
        f.write(FOURIER + "\n")
    # the sample points: every k-th point of the grid, so that they spread over it
    step = max(1, (n * n) // args.samples)
    picks = list(range(step // 2, n * n, step))[:args.samples]
    points = [(grid_value(0.0, 9.8, n, 1 + p // n), grid_value(-2.0, 12.0, n, 1 + p % n)) for p in picks]
    with open(os.path.join(scratch, "pts.dat"), "w") as f:
        for a, b in points:
            f.write("%r %r\n" % (a, b))
    reference = {}
    for method in ("magnus6", "rk"):
        scene = os.path.join(scratch, "ref_%s.nml" % method)
        with open(scene, "w") as f:
            f.write("&scene task = 'points', model = 'fourier', method = '%s', tolerance = 1e-13, "
                    "output = '%s/ref_%s', columns = 'alpha beta S status' /\n" % (method, scratch, method))
            f.write("&points file = '%s/pts.dat' /\n%s\n" % (scratch, FOURIER))
        subprocess.run([args.hillstab, "--quiet", scene], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        names, rows = columns_of(os.path.join(scratch, "ref_%s_points.dat" % method))
        reference[method] = [r[names.index("S")] for r in rows]
    ref = reference["magnus6"]
    agreement = max(abs(a - b) / max(1.0, abs(a)) for a, b in zip(ref, reference["rk"]))

    def worst_error(values):
        return max(abs(v - r) / max(1.0, abs(r)) for v, r in zip(values, ref))

    # accuracy of hillstab's chart at the sample points
    subprocess.run([args.hillstab, "--quiet", chart], check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    names, rows = columns_of(os.path.join(scratch, "fc_chart.dat"))
    s_col = names.index("S")
    hillstab_error = worst_error([rows[p][s_col] for p in picks])
    tolerances = [1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13]
    c_error = {}
    for tol in tolerances:
        out = os.path.join(scratch, "c.txt")
        subprocess.run([args.chart_gsl, str(n), str(n), repr(tol), out], check=True, stdout=subprocess.DEVNULL)
        with open(out) as f:
            values = [float(line.split()[2]) for line in f]
        c_error[tol] = worst_error([values[p] for p in picks])
    # timing, interleaved rounds
    runs = {"hillstab 1 thread": ([args.hillstab, "--quiet", chart], dict(os.environ, OMP_NUM_THREADS="1")),
            "hillstab %d threads" % args.threads: ([args.hillstab, "--quiet", chart],
                                                   dict(os.environ, OMP_NUM_THREADS=str(args.threads)))}
    for tol in tolerances:
        runs["C GSL rk8pd %g" % tol] = ([args.chart_gsl, str(n), str(n), repr(tol)], None)
    best = {name: float("inf") for name in runs}
    for _ in range(args.rounds):
        for name, (command, env) in runs.items():
            best[name] = min(best[name], run(command, env))
    hill1 = best["hillstab 1 thread"]
    hilln = best["hillstab %d threads" % args.threads]
    print("fourier chart %d x %d, f = cos(pi tau) + 0.4 cos(2 pi tau) + 0.3 sin(3 pi tau); errors at %d points "
          "against magnus6 at 1e-13 (rk at 1e-13 agrees to %.1e)" % (n, n, len(picks), agreement))
    print("%-26s %10s %12s" % ("run", "time (s)", "worst error"))
    lines = []
    print("%-26s %10.3f %12.2e" % ("hillstab 1 thread", hill1, hillstab_error))
    print("%-26s %10.3f %12.2e" % ("hillstab %d threads" % args.threads, hilln, hillstab_error))
    lines.append("hillstab_1 %.6f %.3e" % (hill1, hillstab_error))
    lines.append("hillstab_%d %.6f %.3e" % (args.threads, hilln, hillstab_error))
    equal = None
    for tol in tolerances:
        t = best["C GSL rk8pd %g" % tol]
        print("%-26s %10.3f %12.2e" % ("C GSL rk8pd %g" % tol, t, c_error[tol]))
        lines.append("gsl_%g %.6f %.3e" % (tol, t, c_error[tol]))
        if c_error[tol] <= hillstab_error and (equal is None or t < best["C GSL rk8pd %g" % equal]):
            equal = tol
    if equal is None:
        print("no C run reached hillstab's accuracy %.2e" % hillstab_error)
    else:
        t = best["C GSL rk8pd %g" % equal]
        print("at equal accuracy (C at %g, worst error %.2e <= %.2e): C / hillstab = %.1f (1 thread), %.1f (%d threads)"
              % (equal, c_error[equal], hillstab_error, t / hill1, t / hilln, args.threads))
    os.makedirs(os.path.dirname(args.out) or ".", exist_ok=True)
    with open(args.out, "w") as f:
        f.write("# fourier chart %d x %d: run, time (s), worst error at %d points\n# columns: run time error\n"
                % (n, n, len(picks)))
        f.write("\n".join(lines) + "\n")
    print("wrote " + args.out)
    subprocess.run(["rm", "-rf", scratch])


if __name__ == "__main__":
    sys.exit(main())
