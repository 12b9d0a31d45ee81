#!/usr/bin/env python3
"""Charts against the plain C program a user would write with GSL (`make bench`).

    python3 scripts/bench_chart.py HILLSTAB CHART_GSL [--n 300] [--rounds 5] [--threads 2]
                                   [--scratch DIR] [--disk DIR] [--out out/bench_chart_gsl.dat]

HILLSTAB is the hillstab program (release build), CHART_GSL the compiled bench/chart_gsl.c.
Both chart alpha in [0, 9.8], beta in [-2, 12] on an n x n grid (the same doubles). Timed,
as whole runs (process start, scene, computing, file), interleaved in rounds and each the
fastest of its rounds:
  - hillstab, method auto, tolerance 1e-10, on THREADS threads: the full chart (every column,
    text), the same in binary, the verdict chart (columns 'alpha beta stable'), the growth chart
    (columns 'alpha beta mu');
  - the same full chart at tolerances 1e-8 and 1e-12 (work against precision);
  - the C program on one thread at epsabs = epsrel = 1e-8 ... 1e-14, writing nothing.
hillstab writes its files into SCRATCH (default /dev/shm, a tmpfs, when it is writable): there
the fsync before the file takes its name costs nothing, so the comparison measures computing
and writing; the full and the verdict chart are also timed writing to DISK (default build/),
where that fsync waits for the disk (about 20 ms for the 4.5 MB verdict file on the project's
machine).
Accuracy, from untimed runs: the error of S, |S - S_ref|/max(1, |S_ref|), at the 40 points of
data/reference/chart_set.dat (50-digit references, data/reference/make_reference.py --chart)
for hillstab and for the C program at each tolerance; "equal accuracy" pairs hillstab with the
fastest C run whose worst error at those points is no larger than hillstab's. The verdict
chart's verdicts are compared with those of a reference chart (the C program at 1e-13) at every
point where the reference's |S| is farther than 1e-7 from 2.
Prints the table and writes OUT (gnuplot-ready, one line per run) for plots/bench_chart_gsl.gp.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time


def grid_value(lo, hi, n, i):
    if n <= 1:
        return lo
    if i == n:
        return hi
    return lo + (hi - lo) * float(i - 1) / float(n - 1)


def read_chart(path, columns_wanted):
    """Rows of a text chart file as dicts of the wanted columns (by the '# columns:' line)."""
    names = None
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("# columns:"):
                names = line.split()[2:]
                continue
            if line.startswith("#") or not line.strip():
                continue
            values = line.split()
            rows.append({c: float(values[names.index(c)]) for c in columns_wanted})
    return rows


def read_reference(path):
    points = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            v = line.split("#")[0].split()
            model, alpha, beta, sign, ln_abs, s = int(v[0]), float(v[1]), float(v[2]), int(v[3]), float(v[4]), float(v[5])
            points.append((alpha, beta, s if abs(s) > 0 or ln_abs < 690 else sign * 1e300))
    return points


def error_at_points(values, reference, n):
    """Worst |S - S_ref|/max(1, |S_ref|) at the reference points; values[(i, j)] = S."""
    index_alpha = {grid_value(0.0, 9.8, n, i): i for i in range(1, n + 1)}
    index_beta = {grid_value(-2.0, 12.0, n, j): j for j in range(1, n + 1)}
    worst = 0.0
    for alpha, beta, s_ref in reference:
        s = values[(index_alpha[alpha], index_beta[beta])]
        worst = max(worst, abs(s - s_ref) / max(1.0, abs(s_ref)))
    return worst


def chart_values(rows, n, key):
    return {((k // n) + 1, (k % n) + 1): r[key] for k, r in enumerate(rows)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("hillstab")
    parser.add_argument("chart_gsl")
    parser.add_argument("--n", type=int, default=300)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--tolerance", type=float, default=1e-10)
    parser.add_argument("--out", default="out/bench_chart_gsl.dat")
    parser.add_argument("--scratch", default="/dev/shm" if os.access("/dev/shm", os.W_OK) else None)
    parser.add_argument("--disk", default="build")
    args = parser.parse_args()
    n = args.n
    reference_points = read_reference("data/reference/chart_set.dat") if n == 300 else []
    work = tempfile.mkdtemp(prefix="hillstab_bench_chart.", dir=args.scratch)
    os.makedirs(args.disk, exist_ok=True)
    disk = tempfile.mkdtemp(prefix="hillstab_bench_chart.", dir=args.disk)
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))
    env1 = dict(os.environ, OMP_NUM_THREADS="1")

    def scene(name, extra, where=None, tolerance=None):
        where = where or work
        path = os.path.join(where, name + ".nml")
        with open(path, "w") as f:
            f.write("&scene task = 'chart', method = 'auto', tolerance = %g, output = '%s'%s /\n"
                    % (tolerance or args.tolerance, os.path.join(where, name), extra))
            f.write("&chart alpha_min = 0, alpha_max = 9.8, n_alpha = %d, beta_min = -2, beta_max = 12, n_beta = %d /\n"
                    % (n, n))
        return path

    # (program, run, command, environment, tolerance, key of its error in `errors`: None
    # for the runs that write no S)
    jobs = [
        ("hillstab", "full chart, text", [args.hillstab, "--quiet", scene("full", "")], env,
         args.tolerance, "hillstab"),
        ("hillstab", "full chart, binary", [args.hillstab, "--quiet", scene("binary", ", format = 'binary'")], env,
         args.tolerance, "hillstab"),
        ("hillstab", "verdict chart (alpha beta stable)",
         [args.hillstab, "--quiet", scene("verdict", ", columns = 'alpha beta stable'")], env, args.tolerance, None),
        ("hillstab", "growth chart (alpha beta mu)",
         [args.hillstab, "--quiet", scene("growth", ", columns = 'alpha beta mu'")], env, args.tolerance, None),
        ("hillstab", "full chart, text, on disk", [args.hillstab, "--quiet", scene("full", "", disk)], env,
         args.tolerance, "hillstab"),
        ("hillstab", "verdict chart, on disk",
         [args.hillstab, "--quiet", scene("verdict", ", columns = 'alpha beta stable'", disk)], env,
         args.tolerance, None),
        ("hillstab", "full chart, text, tolerance 1e-8",
         [args.hillstab, "--quiet", scene("full8", "", tolerance=1e-8)], env, 1e-8, "hillstab 1e-8"),
        ("hillstab", "full chart, text, tolerance 1e-12",
         [args.hillstab, "--quiet", scene("full12", "", tolerance=1e-12)], env, 1e-12, "hillstab 1e-12"),
    ]
    n_hillstab = 8
    gsl_tolerances = [1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14]
    for tol in gsl_tolerances:
        jobs.append(("gsl", "%.0e" % tol, [args.chart_gsl, str(n), str(n), repr(tol)], env1, tol, tol))

    best = [float("inf")] * len(jobs)
    for r in range(args.rounds):
        for k, (who, label, command, e, tol, key) in enumerate(jobs):
            start = time.perf_counter()
            subprocess.run(command, env=e, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            best[k] = min(best[k], time.perf_counter() - start)
        print("round %d of %d done" % (r + 1, args.rounds), file=sys.stderr)

    # accuracy: hillstab's files of the last round; the C program once more with output
    full = read_chart(os.path.join(work, "full_chart.dat"), ["S", "stable"])
    verdict = read_chart(os.path.join(work, "verdict_chart.dat"), ["stable"])
    gsl_values = {}
    for tol in gsl_tolerances:
        path = os.path.join(work, "gsl_%g.dat" % tol)
        subprocess.run([args.chart_gsl, str(n), str(n), repr(tol), path], env=env1, check=True,
                       stdout=subprocess.DEVNULL)
        values = {}
        with open(path) as f:
            for k, line in enumerate(f):
                values[((k // n) + 1, (k % n) + 1)] = float(line.split()[2])
        gsl_values[tol] = values
    hillstab_s = chart_values(full, n, "S")
    errors = {}
    if reference_points:
        errors["hillstab"] = error_at_points(hillstab_s, reference_points, n)
        for name, key in (("full8", "hillstab 1e-8"), ("full12", "hillstab 1e-12")):
            rows = read_chart(os.path.join(work, name + "_chart.dat"), ["S"])
            errors[key] = error_at_points(chart_values(rows, n, "S"), reference_points, n)
        for tol in gsl_tolerances:
            errors[tol] = error_at_points(gsl_values[tol], reference_points, n)
    # the whole chart against the C program at 1e-13
    ref = gsl_values[1e-13]
    chart_worst = max(abs(hillstab_s[key] - ref[key]) / max(1.0, abs(ref[key])) for key in ref)
    # verdicts against the reference chart, where it is farther than 1e-7 from |S| = 2
    verdict_values = chart_values(verdict, n, "stable")
    compared = wrong = marginal = 0
    for key, s in ref.items():
        if abs(abs(s) - 2.0) <= 1e-7:
            continue
        compared += 1
        v = verdict_values[key]
        if v == 0.5:
            marginal += 1
        elif (v == 1.0) != (abs(s) < 2.0):
            wrong += 1

    t_full, _, t_verdict, t_growth, t_full_disk, t_verdict_disk, t_full8, t_full12 = best[0:n_hillstab]
    t_gsl = dict(zip(gsl_tolerances, best[n_hillstab:]))
    same_tolerance = min(gsl_tolerances, key=lambda t: abs(t - args.tolerance))
    equal = None
    if errors:
        candidates = [t for t in gsl_tolerances if errors[t] <= errors["hillstab"]]
        if candidates:
            equal = min(candidates, key=lambda t: t_gsl[t])

    print()
    print("Chart %d x %d, alpha in [0, 9.8], beta in [-2, 12]; hillstab auto tolerance %g on %d threads, "
          "GSL rk8pd on 1 thread" % (n, n, args.tolerance, args.threads))
    print("hillstab's files in %s (disk runs: %s)" % (work, disk))
    print("%-10s %-36s %10s %14s" % ("program", "run", "seconds", "error (40 pts)"))
    for k, (who, label, command, e, tol, key) in enumerate(jobs):
        err = ""
        if errors:
            err = "-" if key is None else "%.2e" % errors[key]
        print("%-10s %-36s %10.4f %14s" % (who, label, best[k], err))
    print()
    print("worst error of hillstab's S over the whole chart against GSL at 1e-13: %.2e" % chart_worst)
    print("verdicts against GSL at 1e-13 where its |S| is farther than 1e-7 from 2: %d compared, %d wrong, "
          "%d marginal" % (compared, wrong, marginal))
    print("full chart vs GSL at the same tolerance (%g): %.1f x" % (same_tolerance, t_gsl[same_tolerance] / t_full))
    if equal is not None:
        print("full chart vs GSL at equal accuracy (GSL %g, error %.2e <= %.2e): %.1f x"
              % (equal, errors[equal], errors["hillstab"], t_gsl[equal] / t_full))
    elif errors:
        print("full chart vs GSL at equal accuracy: no GSL tolerance reaches hillstab's error %.2e" % errors["hillstab"])
    for key, t_run in (("hillstab 1e-8", t_full8), ("hillstab 1e-12", t_full12)):
        if errors:
            fits = [t for t in gsl_tolerances if errors[t] <= errors[key]]
            if fits:
                g = min(fits, key=lambda t: t_gsl[t])
                print("full chart at %s vs GSL at equal accuracy (GSL %g, error %.2e <= %.2e): %.1f x"
                      % (key[9:], g, errors[g], errors[key], t_gsl[g] / t_run))
            else:
                print("full chart at %s: no GSL tolerance down to 1e-14 reaches its error %.2e (GSL 1e-14: %.2e, "
                      "%.1f x its time)" % (key[9:], errors[key], errors[1e-14], t_gsl[1e-14] / t_run))
    print("verdict chart vs GSL at the same tolerance: %.1f x" % (t_gsl[same_tolerance] / t_verdict))
    print("growth chart vs GSL at the same tolerance: %.1f x" % (t_gsl[same_tolerance] / t_growth))
    print("on disk (the fsync of the file before its rename waits for the disk): full chart %.1f x at the same "
          "tolerance%s, verdict chart %.1f x" % (
              t_gsl[same_tolerance] / t_full_disk,
              "" if equal is None else ", %.1f x at equal accuracy" % (t_gsl[equal] / t_full_disk),
              t_gsl[same_tolerance] / t_verdict_disk))

    os.makedirs(os.path.dirname(args.out) or ".", exist_ok=True)
    with open(args.out + ".part", "w") as f:
        f.write("# hillstab chart benchmark (scripts/bench_chart.py): %d x %d chart, alpha in [0, 9.8], beta in "
                "[-2, 12]\n" % (n, n))
        f.write("# hillstab auto at tolerance %g on %d threads (whole runs); GSL rk8pd (bench/chart_gsl.c) on 1 "
                "thread; seconds: fastest of %d interleaved rounds\n" % (args.tolerance, args.threads, args.rounds))
        f.write("# error: worst |S - S_ref|/max(1, |S_ref|) at the 40 points of data/reference/chart_set.dat "
                "(-1: not measured)\n")
        f.write("# verdicts: %d compared, %d wrong, %d marginal; whole-chart error of hillstab vs GSL 1e-13: %.3e\n"
                % (compared, wrong, marginal, chart_worst))
        f.write("# columns: program run tolerance seconds error ratio_to_hillstab_full\n")
        for k, (who, label, command, e, tol, key) in enumerate(jobs):
            err = errors.get(key, -1.0) if key is not None else -1.0
            f.write('%s "%s" %g %.6f %.3e %.3f\n' % (who, label, tol, best[k], err, best[k] / t_full))
    os.replace(args.out + ".part", args.out)
    print("wrote " + args.out)
    for directory in (work, disk):
        for name in os.listdir(directory):
            os.remove(os.path.join(directory, name))
        os.rmdir(directory)
    return 0 if wrong == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
