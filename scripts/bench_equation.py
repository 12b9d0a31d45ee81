#!/usr/bin/env python3
"""Equations in physical time against the built-in model, a scipy loop and a plain C GSL program
(`make bench-equation`).

    python scripts/bench_equation.py HILLSTAB CHART_GSL_KAPITZA [--rounds 7] [--subset 20]
                                     [--scratch DIR] [--reference FILE] [--out out/bench_equation.dat]

HILLSTAB is the hillstab program (release build), CHART_GSL_KAPITZA the compiled
bench/chart_gsl_kapitza.c. Everything runs on one thread (OMP_NUM_THREADS=1), the jobs
interleaved in rounds; hillstab and the C program are timed as whole processes (start, scene,
computing, and for hillstab its text file, written into SCRATCH, default /dev/shm, a tmpfs; the
C program writes nothing while timed), the scipy loop in this process (the loop alone).

1. Mathieu, 300 x 300, alpha in [0, 20], beta in [-5, 40], method auto, tolerance 1e-10: the chart
   written as an equation (model 'equation', stiffness 'b - a*cos(pi*t)', frequency 'pi', axes a
   and b) against the built-in model 'mathieu' (Q = beta - alpha cos(pi tau), the same chart). The
   two files must have the same grid and agree within 2e-10 max(1, |S|) at every point. Both also
   as verdict-only charts (columns 'a b stable'), where the computing is not diluted by the
   writing of the text file.
   The Kapitza chart of 2. written as a system of one equation (model 'equations', n = 1) against
   its chart as an equation: a system that is one equation takes the scalar path, the bar is 2.
   The two pendula on a shaken support (a 2-DOF system, 151 x 301) written as equations (model
   'equations', stiffness 'b*B + a*C*cos(pi*t)', frequency 'pi') against the built-in model
   'system': the two files agree within 1e-10 max(1, |trace|) at every point.
2. The Kapitza chart of data/scenes/kapitza_chart.nml (300 x 300 over (w, A), auto at 1e-10) by
   hillstab against
   (a) a plain scipy loop: per point, solve_ivp(method='DOP853') on the 2 x 2 fundamental matrix of
       the physical equation theta'' + kappa theta' + (-g/l + A w^2/l cos(w t)) theta = 0 over one
       period 2 pi/w, run on a SUBSET x SUBSET sub-grid of the chart's points spread over the whole
       box (every ~(n-1)/(SUBSET-1)-th row and column, the edges included); its time per point is
       extrapolated to the chart;
   (b) the C program (GSL rk8pd, epsabs = epsrel = tol, the whole period), on the whole chart.
   Equal accuracy: the reference is hillstab's magnus6 at tolerance 1e-13 on the same chart
   (computed once, one thread, ~30 s, kept in --reference and reused while the scene is the same:
   delete it after a change of the library); errors are |S - S_ref|/max(1, |S_ref|)
   of S1 = exp(kappa T/2) trace(monodromy), hillstab's S of a damped equation. GSL's tolerance is
   the cheapest (fewest evaluations) of a half-decade ladder 1e-9 ... 1e-13 whose worst error over
   the whole chart is no larger than hillstab's over the whole chart; scipy's rtol/atol the cheapest
   of rtol in 1e-9 ... 3e-14 (half decades) times atol in {rtol, 1e-3 rtol} whose worst error over
   the sub-grid is no larger than hillstab's over the same points. Both also run at the tolerance
   hillstab was given (1e-10). Independent check: the 30 damped points of
   data/reference/physical_set.dat (45-digit Taylor monodromies of the same physical equation, all
   inside the chart's box) computed by every contender (hillstab by its points task) and by the
   magnus6 reference.
Prints the tables and writes OUT (one line per job and round, a '# columns:' line).
"""
import argparse
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

try:
    from scipy.integrate import solve_ivp
    import scipy
except ImportError:          # the rest runs without it
    solve_ivp = None

G, L, KAPPA = 9.81, 0.2, 0.2                       # those of kapitza_chart.nml and chart_gsl_kapitza.c
KAPITZA_SCENE = "data/scenes/kapitza_chart.nml"
KAPITZA_PARAMETERS = "parameters = 'g = 9.81, l = 0.2, kappa = 0.2, A = 0.005, w = 314.16'"
KAPITZA_BOX = "alpha_min=60.0, alpha_max=700.0, n_alpha=300, beta_min=0.0, beta_max=0.1, n_beta=300"
MATHIEU_BOX = "&chart alpha_min = 0, alpha_max = 20, n_alpha = 300, beta_min = -5, beta_max = 40, n_beta = 300 /\n"
MATHIEU_AGREEMENT = 2e-10
# the two pendula on a shaken support (data/scenes/system_pendula.nml) built in and written as equations
PENDULA_BOX = "&chart alpha_min = 0.0, alpha_max = 1.5, n_alpha = 151, beta_min = 0.0, beta_max = 3.0, n_beta = 301 /\n"
PENDULA_SYSTEM = ("&system n = 2, mass = 1.0, 0.0, 0.0, 0.25, b = 2.0, -1.0, -1.0, 1.5, "
                  "cos = -1.0, 0.0, 0.0, -0.5 /\n")
PENDULA_EQUATIONS = ("&equations n = 2, parameters = 'a = 0, b = 1', matrices = 'M = [1, 0; 0, 0.25], "
                     "B = [2, -1; -1, 1.5], C = [-1, 0; 0, -0.5]', mass = 'M', stiffness = 'b*B + a*C*cos(pi*t)', "
                     "frequency = 'pi', alpha = 'a', beta = 'b' /\n")
PENDULA_AGREEMENT = 1e-10
GSL_LADDER = [1e-9, 3e-10, 1e-10, 3e-11, 1e-11, 3e-12, 1e-12, 3e-13, 1e-13]
SCIPY_RTOLS = [1e-9, 3e-10, 1e-10, 3e-11, 1e-11, 3e-12, 1e-12, 3e-13, 1e-13, 3e-14]
SCIPY_ATOL_FACTORS = [1.0, 1e-3]
SAME_TOLERANCE = 1e-10


def read_rows(path, wanted):
    """The wanted columns of a hillstab text file (by its '# columns:' line), as lists of floats."""
    names = None
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("# columns:"):
                names = line.split()[2:]
                index = [names.index(c) for c in wanted]
                continue
            if line.startswith("#") or not line.strip():
                continue
            v = line.split()
            rows.append([float(v[k]) for k in index])
    return rows


def relative_error(s, s_ref):
    return abs(s - s_ref) / max(1.0, abs(s_ref))


def s1_of_trace(w, trace):
    """hillstab's S of the damped equation: exp(kappa T/2) times the physical monodromy's trace."""
    return math.exp(0.5 * KAPPA * 2.0 * math.pi / w) * trace


def scipy_traces(points, rtol, atol):
    """The loop a user writes: solve_ivp on the fundamental matrix, point after point."""
    traces = []
    evaluations = 0
    for w, amplitude in points:
        def rhs(t, y):
            k = -G / L + amplitude * w ** 2 / L * math.cos(w * t)
            return [y[1], -KAPPA * y[1] - k * y[0], y[3], -KAPPA * y[3] - k * y[2]]
        solution = solve_ivp(rhs, (0.0, 2.0 * math.pi / w), [1.0, 0.0, 0.0, 1.0], method="DOP853",
                             rtol=rtol, atol=atol)
        if solution.status != 0:
            sys.exit("bench_equation: solve_ivp failed at w = %r, A = %r: %s" % (w, amplitude, solution.message))
        traces.append(solution.y[0, -1] + solution.y[3, -1])
        evaluations += solution.nfev
    return traces, evaluations


def run(command, env):
    start = time.perf_counter()
    done = subprocess.run(command, env=env, check=True, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                          universal_newlines=True)
    return time.perf_counter() - start, done.stdout


def gsl_evaluations(stdout):
    fields = stdout.split()
    return int(fields[fields.index("evaluations") + 1]), int(fields[fields.index("failed") + 1])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("hillstab")
    parser.add_argument("chart_gsl")
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--subset", type=int, default=20, help="the scipy loop's sub-grid: SUBSET x SUBSET points")
    parser.add_argument("--scratch", default="/dev/shm" if os.access("/dev/shm", os.W_OK) else None)
    parser.add_argument("--reference", default="build/bench/kapitza_magnus6_1e-13_chart.dat")
    parser.add_argument("--out", default="out/bench_equation.dat")
    args = parser.parse_args()
    hillstab = os.path.abspath(args.hillstab)
    chart_gsl = os.path.abspath(args.chart_gsl)
    env = dict(os.environ, OMP_NUM_THREADS="1")
    os.environ["OMP_NUM_THREADS"] = "1"
    work = tempfile.mkdtemp(prefix="hillstab_bench_equation.", dir=args.scratch)

    with open(KAPITZA_SCENE) as f:
        kapitza = f.read()
    if KAPITZA_PARAMETERS not in kapitza or KAPITZA_BOX not in kapitza or "tolerance=1e-10" not in kapitza:
        sys.exit("bench_equation: %s is not the scene bench/chart_gsl_kapitza.c computes (its parameters, "
                 "box or tolerance changed): change both" % KAPITZA_SCENE)
    n = 300

    def scene(name, text):
        path = os.path.join(work, name + ".nml")
        with open(path, "w") as f:
            f.write(text)
        return path

    def kapitza_scene(name, method, tolerance, task="chart"):
        text = re.sub(r"method='auto', tolerance=1e-10, output='[^']*'",
                      "method='%s', tolerance=%s, output='%s'" % (method, tolerance, os.path.join(work, name)),
                      kapitza)
        if task == "points":
            text = text.replace("task='chart'", "task='points'")
            text = re.sub(r"&chart[^/]*/", "&points file = '%s' /" % os.path.join(work, "physical_points.txt"), text)
        return scene(name, text)

    mathieu_equation = scene("mathieu_equation",
                             "&scene task = 'chart', model = 'equation', method = 'auto', tolerance = 1e-10, "
                             "output = '%s' /\n&equation parameters = 'a = 1, b = 1', stiffness = 'b - a*cos(pi*t)', "
                             "frequency = 'pi', alpha = 'a', beta = 'b' /\n" % os.path.join(work, "mathieu_equation")
                             + MATHIEU_BOX)
    pendula_builtin = scene("pendula_builtin",
                            "&scene task = 'chart', model = 'system', method = 'auto', tolerance = 1e-10, "
                            "output = '%s' /\n" % os.path.join(work, "pendula_builtin") + PENDULA_SYSTEM + PENDULA_BOX)
    pendula_equations = scene("pendula_equations",
                              "&scene task = 'chart', model = 'equations', method = 'auto', tolerance = 1e-10, "
                              "output = '%s' /\n" % os.path.join(work, "pendula_equations") + PENDULA_EQUATIONS
                              + PENDULA_BOX)
    mathieu_builtin = scene("mathieu_builtin",
                            "&scene task = 'chart', model = 'mathieu', method = 'auto', tolerance = 1e-10, "
                            "output = '%s' /\n" % os.path.join(work, "mathieu_builtin") + MATHIEU_BOX)
    mathieu_equation_verdicts = scene("mathieu_equation_verdicts",
                                      open(mathieu_equation).read().replace(
                                          "output = '%s'" % os.path.join(work, "mathieu_equation"),
                                          "output = '%s', columns = 'a b stable'"
                                          % os.path.join(work, "mathieu_equation_verdicts")))
    mathieu_builtin_verdicts = scene("mathieu_builtin_verdicts",
                                     open(mathieu_builtin).read().replace(
                                         "output = '%s'" % os.path.join(work, "mathieu_builtin"),
                                         "output = '%s', columns = 'alpha beta stable'"
                                         % os.path.join(work, "mathieu_builtin_verdicts")))
    kapitza_auto = kapitza_scene("kapitza", "auto", "1e-10")
    # the same chart with its axes swapped: the frequency (and the damping kappa pi/w) along beta, each point alone
    kapitza_swapped = scene("kapitza_swapped", open(kapitza_scene("kapitza_swapped", "auto", "1e-10")).read()
                            .replace("alpha = 'w', beta = 'A'", "alpha = 'A', beta = 'w'")
                            .replace(KAPITZA_BOX, "alpha_min=0.0, alpha_max=0.1, n_alpha=300, beta_min=60.0, "
                                     "beta_max=700.0, n_beta=300"))
    # the same chart as one equation of a system (model 'equations', n = 1): the scalar path
    kapitza_one = scene("kapitza_one", open(kapitza_scene("kapitza_one", "auto", "1e-10")).read()
                        .replace("model='equation'", "model='equations'").replace("&equation ", "&equations n = 1, "))

    # ------------------------------------------------------------------ the reference
    os.makedirs(os.path.dirname(args.reference) or ".", exist_ok=True)
    reference_scene_text = re.sub(r"output='[^']*'", "output='REFERENCE'", open(kapitza_scene("ref", "magnus6", "1e-13")).read())
    stamp = args.reference + ".scene"
    if not (os.path.exists(args.reference) and os.path.exists(stamp) and open(stamp).read() == reference_scene_text):
        print("computing the reference: the Kapitza chart by magnus6 at tolerance 1e-13 (one thread, ~30 s)",
              file=sys.stderr)
        started = time.perf_counter()
        subprocess.run([hillstab, "--quiet", os.path.join(work, "ref.nml")], env=env, check=True)
        shutil.move(os.path.join(work, "ref_chart.dat"), args.reference)
        with open(stamp, "w") as f:
            f.write(reference_scene_text)
        print("  %.1f s" % (time.perf_counter() - started), file=sys.stderr)
    reference = read_rows(args.reference, ["w", "A", "S", "status"])
    if len(reference) != n * n or any(r[3] != 0 for r in reference):
        sys.exit("bench_equation: the reference %s is not %d points at status 0" % (args.reference, n * n))
    grid = [(r[0], r[1]) for r in reference]
    s_ref = [r[2] for r in reference]
    step = (n - 1) / (args.subset - 1)
    rows = sorted({int(round(k * step)) for k in range(args.subset)})
    subset = [i * n + j for i in rows for j in rows]
    subset_points = [grid[k] for k in subset]

    # the physical set: its damped points (kappa = 0.2), 45-digit traces of the physical monodromy
    physical = []
    with open("data/reference/physical_set.dat") as f:
        for line in f:
            v = line.split()
            if line.startswith("#") or not v or v[0] != "1" or float(v[1]) != KAPPA:
                continue
            w, amplitude, trace = float(v[2]), float(v[3]), float(v[4])
            physical.append((w, amplitude, s1_of_trace(w, trace)))
    with open(os.path.join(work, "physical_points.txt"), "w") as f:
        f.write("".join("%r %r\n" % (w, a) for w, a, _ in physical))
    physical_points = [(w, a) for w, a, _ in physical]

    def physical_error(values):
        return max(relative_error(s, p[2]) for s, p in zip(values, physical))

    # ------------------------------------------------------------------ accuracy, untimed
    run([hillstab, "--quiet", mathieu_equation], env)
    run([hillstab, "--quiet", mathieu_builtin], env)
    run([hillstab, "--quiet", kapitza_auto], env)
    eq_rows = read_rows(os.path.join(work, "mathieu_equation_chart.dat"), ["a", "b", "S", "stable", "status"])
    mb_rows = read_rows(os.path.join(work, "mathieu_builtin_chart.dat"), ["alpha", "beta", "S", "stable", "status"])
    if len(eq_rows) != n * n or len(mb_rows) != n * n or any(e[:2] != m[:2] for e, m in zip(eq_rows, mb_rows)):
        sys.exit("bench_equation: the Mathieu charts are not on the same grid")
    agreement = max(relative_error(e[2], m[2]) for e, m in zip(eq_rows, mb_rows))
    verdicts_differ = sum(1 for e, m in zip(eq_rows, mb_rows) if e[3] != m[3])
    run([hillstab, "--quiet", mathieu_equation_verdicts], env)
    run([hillstab, "--quiet", mathieu_builtin_verdicts], env)
    ev_rows = read_rows(os.path.join(work, "mathieu_equation_verdicts_chart.dat"), ["a", "b", "stable"])
    mv_rows = read_rows(os.path.join(work, "mathieu_builtin_verdicts_chart.dat"), ["alpha", "beta", "stable"])
    if len(ev_rows) != n * n or any(e[:2] != m[:2] for e, m in zip(ev_rows, mv_rows)):
        sys.exit("bench_equation: the Mathieu verdict charts are not on the same grid")
    verdict_charts_differ = sum(1 for e, m in zip(ev_rows, mv_rows) if e[2] != m[2])
    verdicts_off_full = sum(1 for e, m in zip(ev_rows, eq_rows) if e[2] != m[3])
    mathieu_status = sum(1 for r in eq_rows + mb_rows if r[4] != 0)
    run([hillstab, "--quiet", pendula_builtin], env)
    run([hillstab, "--quiet", pendula_equations], env)
    pb_rows = read_rows(os.path.join(work, "pendula_builtin_chart.dat"), ["alpha", "beta", "trace", "stable"])
    pe_rows = read_rows(os.path.join(work, "pendula_equations_chart.dat"), ["a", "b", "trace", "stable"])
    if len(pb_rows) != 151 * 301 or any(e[:2] != m[:2] for e, m in zip(pe_rows, pb_rows)):
        sys.exit("bench_equation: the pendula charts are not on the same grid")
    pendula_agreement = max(relative_error(e[2], m[2]) for e, m in zip(pe_rows, pb_rows))
    pendula_verdicts_differ = sum(1 for e, m in zip(pe_rows, pb_rows) if e[3] != m[3])
    hs_rows = read_rows(os.path.join(work, "kapitza_chart.dat"), ["w", "A", "S", "status"])
    if [(r[0], r[1]) for r in hs_rows] != grid:
        sys.exit("bench_equation: hillstab's Kapitza chart is not on the reference's grid")
    hs_s = [r[2] for r in hs_rows]
    kapitza_status = sum(1 for r in hs_rows if r[3] != 0)
    hs_error_chart = max(relative_error(s, r) for s, r in zip(hs_s, s_ref))
    hs_error_subset = max(relative_error(hs_s[k], s_ref[k]) for k in subset)
    run([hillstab, "--quiet", kapitza_one], env)
    one_rows = read_rows(os.path.join(work, "kapitza_one_chart.dat"), ["w", "A", "trace", "stable", "status"])
    if [(r[0], r[1]) for r in one_rows] != grid:
        sys.exit("bench_equation: the one-equation system's Kapitza chart is not on the reference's grid")
    one_error_chart = max(relative_error(s1_of_trace(r[0], r[2]), s) for r, s in zip(one_rows, s_ref))
    one_status = sum(1 for r in one_rows if r[4] != 0)
    run([hillstab, "--quiet", kapitza_swapped], env)
    swapped_rows = read_rows(os.path.join(work, "kapitza_swapped_chart.dat"), ["w", "A", "S", "status"])
    swapped_s = {(r[0], r[1]): r[2] for r in swapped_rows}
    if len(swapped_rows) != n * n or any(p not in swapped_s for p in grid):
        sys.exit("bench_equation: the swapped Kapitza chart is not on the reference's grid")
    swapped_error_chart = max(relative_error(swapped_s[p], s) for p, s in zip(grid, s_ref))
    swapped_agreement = max(relative_error(swapped_s[p], s) for p, s in zip(grid, hs_s))
    swapped_status = sum(1 for r in swapped_rows if r[3] != 0)
    subprocess.run([hillstab, "--quiet", kapitza_scene("phys_auto", "auto", "1e-10", "points")], env=env, check=True)
    subprocess.run([hillstab, "--quiet", kapitza_scene("phys_ref", "magnus6", "1e-13", "points")], env=env, check=True)
    hs_error_physical = physical_error([r[0] for r in read_rows(os.path.join(work, "phys_auto_points.dat"), ["S"])])
    ref_error_physical = physical_error([r[0] for r in read_rows(os.path.join(work, "phys_ref_points.dat"), ["S"])])

    # GSL's ladder on the whole chart
    gsl_search = []            # (tol, evaluations per point, whole-chart error, sub-grid error, seconds)
    for tol in GSL_LADDER:
        path = os.path.join(work, "gsl.dat")
        seconds, out = run([chart_gsl, str(n), str(n), repr(tol), path], env)
        evaluations, failed = gsl_evaluations(out)
        values = []
        with open(path) as f:
            for k, line in enumerate(f):
                v = line.split()
                if (float(v[0]), float(v[1])) != grid[k]:
                    sys.exit("bench_equation: the C program's grid differs from hillstab's at point %d" % k)
                values.append(float(v[3]))
        errors = [relative_error(s, r) for s, r in zip(values, s_ref)]
        gsl_search.append((tol, evaluations / (n * n), max(errors), max(errors[k] for k in subset), seconds, failed))
        print("GSL rk8pd tol %g: %.0f evaluations a point, error %.2e" % (tol, evaluations / (n * n), max(errors)),
              file=sys.stderr)
    fits = [g for g in gsl_search if g[2] <= hs_error_chart and g[5] == 0]
    gsl_equal = min(fits, key=lambda g: g[1]) if fits else None

    def gsl_physical(tol):
        path = os.path.join(work, "gsl_physical.dat")
        run([chart_gsl, "--points", os.path.join(work, "physical_points.txt"), repr(tol), path], env)
        with open(path) as f:
            return physical_error([float(line.split()[3]) for line in f])

    # scipy's search on the sub-grid
    scipy_search = []          # (rtol, atol, evaluations per point, sub-grid error, seconds per point)
    scipy_equal = None
    if solve_ivp is not None:
        for rtol in SCIPY_RTOLS:
            for factor in SCIPY_ATOL_FACTORS:
                atol = rtol * factor
                start = time.perf_counter()
                traces, evaluations = scipy_traces(subset_points, rtol, atol)
                seconds = time.perf_counter() - start
                error = max(relative_error(s1_of_trace(w, t), s_ref[k])
                            for (w, _), t, k in zip(subset_points, traces, subset))
                scipy_search.append((rtol, atol, evaluations / len(subset), error, seconds / len(subset)))
                print("scipy DOP853 rtol %g atol %g: %.0f evaluations a point, error %.2e, %.0f us a point"
                      % (rtol, atol, evaluations / len(subset), error, 1e6 * seconds / len(subset)), file=sys.stderr)
        fits = [s for s in scipy_search if s[3] <= hs_error_subset]
        scipy_equal = min(fits, key=lambda s: s[2]) if fits else None

    def scipy_physical(rtol, atol):
        traces, _ = scipy_traces(physical_points, rtol, atol)
        return physical_error([s1_of_trace(w, t) for (w, _), t in zip(physical_points, traces)])

    # ------------------------------------------------------------------ the timed rounds
    # job: (name, label, kind, command or scipy settings, points, setting, error, error's points, physical error)
    jobs = [
        ("mathieu_equation", "Mathieu as an equation (auto 1e-10)", "process", [hillstab, "--quiet", mathieu_equation],
         n * n, "tol=1e-10", agreement, "agreement with mathieu", -1.0),
        ("mathieu_builtin", "Mathieu, built-in model (auto 1e-10)", "process", [hillstab, "--quiet", mathieu_builtin],
         n * n, "tol=1e-10", -1.0, "-", -1.0),
        ("mathieu_equation_verdicts", "Mathieu as an equation, verdicts only (columns 'a b stable')", "process",
         [hillstab, "--quiet", mathieu_equation_verdicts], n * n, "tol=1e-10", -1.0, "-", -1.0),
        ("mathieu_builtin_verdicts", "Mathieu, built-in model, verdicts only", "process",
         [hillstab, "--quiet", mathieu_builtin_verdicts], n * n, "tol=1e-10", -1.0, "-", -1.0),
        ("pendula_equations", "2-DOF pendula as equations (auto 1e-10)", "process",
         [hillstab, "--quiet", pendula_equations], 151 * 301, "tol=1e-10", pendula_agreement,
         "agreement with the system model", -1.0),
        ("pendula_builtin", "2-DOF pendula, built-in system model (auto 1e-10)", "process",
         [hillstab, "--quiet", pendula_builtin], 151 * 301, "tol=1e-10", -1.0, "-", -1.0),
        ("kapitza_hillstab", "Kapitza, hillstab (auto 1e-10)", "process", [hillstab, "--quiet", kapitza_auto],
         n * n, "tol=1e-10", hs_error_chart, "chart", hs_error_physical),
        ("kapitza_one_system", "Kapitza as a system of one equation (equations, n = 1, auto 1e-10)", "process",
         [hillstab, "--quiet", kapitza_one], n * n, "tol=1e-10", one_error_chart, "chart", -1.0),
        ("kapitza_swapped", "Kapitza over (A, w): frequency and damping along beta, each point alone (auto 1e-10)",
         "process", [hillstab, "--quiet", kapitza_swapped], n * n, "tol=1e-10", swapped_error_chart, "chart", -1.0),
    ]
    same_gsl = [g for g in gsl_search if g[0] == SAME_TOLERANCE][0]
    if gsl_equal is not None:
        jobs.append(("kapitza_gsl_equal", "Kapitza, GSL rk8pd at equal accuracy (tol %g)" % gsl_equal[0], "process",
                     [chart_gsl, str(n), str(n), repr(gsl_equal[0])], n * n, "tol=%g" % gsl_equal[0], gsl_equal[2],
                     "chart", gsl_physical(gsl_equal[0])))
    jobs.append(("kapitza_gsl_same", "Kapitza, GSL rk8pd at the same tolerance (1e-10)", "process",
                 [chart_gsl, str(n), str(n), repr(SAME_TOLERANCE)], n * n, "tol=1e-10", same_gsl[2], "chart",
                 gsl_physical(SAME_TOLERANCE)))
    if solve_ivp is not None:
        same_scipy = [s for s in scipy_search if s[0] == SAME_TOLERANCE and s[1] == SAME_TOLERANCE][0]
        if scipy_equal is not None:
            jobs.append(("kapitza_scipy_equal", "Kapitza, scipy DOP853 at equal accuracy (rtol %g, atol %g)"
                         % scipy_equal[:2], "scipy", scipy_equal[:2], len(subset),
                         "rtol=%g,atol=%g" % scipy_equal[:2], scipy_equal[3], "sub-grid", scipy_physical(*scipy_equal[:2])))
        jobs.append(("kapitza_scipy_same", "Kapitza, scipy DOP853 at the same tolerance (rtol = atol = 1e-10)", "scipy",
                     (SAME_TOLERANCE, SAME_TOLERANCE), len(subset), "rtol=1e-10,atol=1e-10", same_scipy[3], "sub-grid",
                     scipy_physical(SAME_TOLERANCE, SAME_TOLERANCE)))

    times = {job[0]: [] for job in jobs}
    for r in range(args.rounds):
        for name, label, kind, what, points, *_ in jobs:
            if kind == "process":
                seconds, _ = run(what, env)
            else:
                start = time.perf_counter()
                scipy_traces(subset_points, *what)
                seconds = time.perf_counter() - start
            times[name].append(seconds)
        print("round %d of %d done" % (r + 1, args.rounds), file=sys.stderr)

    def per_point(name, k):
        job = [j for j in jobs if j[0] == name][0]
        return times[name][k] / job[4]

    def ratios(name):
        base = ("mathieu_builtin_verdicts" if name.endswith("_verdicts") else
                "mathieu_builtin" if name.startswith("mathieu") else
                "pendula_builtin" if name.startswith("pendula") else "kapitza_hillstab")
        return [per_point(name, k) / per_point(base, k) for k in range(args.rounds)]

    # ------------------------------------------------------------------ report
    print()
    print("One thread (OMP_NUM_THREADS=1), release build, %d interleaved rounds, medians; hillstab and the C "
          "program as whole processes (hillstab writing its text file into %s), scipy the loop alone, on a %d x %d "
          "sub-grid (%d points) of the chart, extrapolated per point" % (args.rounds, args.scratch, len(rows),
                                                                          len(rows), len(subset)))
    print()
    print("| job | points | time | per point | per 300 x 300 chart | ratio to hillstab (range) | worst error (where) "
          "| error, 30 points of physical_set |")
    print("|---|---|---|---|---|---|---|---|")
    for name, label, kind, what, points, setting, error, where, error_physical in jobs:
        t = statistics.median(times[name])
        q = ratios(name)
        print("| %s | %d | %.4g s | %.3g us | %.3g s%s | %.3g (%.3g-%.3g) | %s | %s |" % (
            label, points, t, 1e6 * t / points, t / points * n * n, " (extrapolated)" if kind == "scipy" else "",
            statistics.median(q), min(q), max(q),
            "-" if error < 0 else "%.2e (%s)" % (error, where),
            "-" if error_physical < 0 else "%.2e" % error_physical))
    print()
    print("Mathieu: the equation's chart against the built-in model's: same grid, worst |S_eq - S|/max(1, |S|) = "
          "%.2e (bound %.0e), verdicts differing at %d points, %d points at a status other than 0"
          % (agreement, MATHIEU_AGREEMENT, verdicts_differ, mathieu_status))
    print("Mathieu, verdicts only: the two verdict charts differ at %d points; the equation's verdict chart and its "
          "full chart's verdicts at %d" % (verdict_charts_differ, verdicts_off_full))
    print("Pendula: the equations' chart against the built-in system's (151 x 301, (alpha, beta) in [0, 1.5] x "
          "[0, 3]): worst |d trace|/max(1, |trace|) = %.2e, verdicts differing at %d points"
          % (pendula_agreement, pendula_verdicts_differ))
    print("Kapitza: hillstab auto 1e-10 against magnus6 1e-13: worst %.2e over the chart, %.2e over the sub-grid, %d "
          "points at a status other than 0; magnus6 1e-13 itself at the 30 points of physical_set: %.2e"
          % (hs_error_chart, hs_error_subset, kapitza_status, ref_error_physical))
    print("Kapitza as a system of one equation (model 'equations', n = 1; its ratio is to the equation's chart, the "
          "bar 2): worst error %.2e over the chart, %d points at a status other than 0"
          % (one_error_chart, one_status))
    swapped_to_gsl = ""
    if gsl_equal is not None:
        q = [per_point("kapitza_swapped", k) / per_point("kapitza_gsl_equal", k) for k in range(args.rounds)]
        swapped_to_gsl = "; its time %.3g (%.3g-%.3g) of GSL's at equal accuracy" % (statistics.median(q), min(q),
                                                                                   max(q))
    print("Kapitza over (A, w) (the frequency and the damping along beta: each point alone; its ratio is to the chart "
          "over (w, A)): worst error %.2e over the chart, within %.2e of the chart over (w, A), %d points at a status "
          "other than 0%s" % (swapped_error_chart, swapped_agreement, swapped_status, swapped_to_gsl))
    print()
    print("GSL rk8pd (epsabs = epsrel = tol), the whole chart: the ladder")
    print("| tol | evaluations/point | worst error, chart | worst error, sub-grid | seconds (one run) |")
    print("|---|---|---|---|---|")
    for tol, ev, e_chart, e_sub, seconds, failed in gsl_search:
        print("| %g | %.0f | %.2e | %.2e | %.3f%s |" % (tol, ev, e_chart, e_sub, seconds,
                                                       " (%d failed)" % failed if failed else ""))
    print("equal accuracy: %s" % ("GSL at tol %g (error %.2e <= hillstab's %.2e)" % (gsl_equal[0], gsl_equal[2],
                                                                                 hs_error_chart)
                                   if gsl_equal else "no tolerance of the ladder reaches hillstab's %.2e" % hs_error_chart))
    if solve_ivp is not None:
        print()
        print("scipy %s solve_ivp DOP853 on the sub-grid: the search" % scipy.__version__)
        print("| rtol | atol | evaluations/point | worst error, sub-grid | us/point (one run) |")
        print("|---|---|---|---|---|")
        for rtol, atol, ev, error, seconds in scipy_search:
            print("| %g | %g | %.0f | %.2e | %.0f |" % (rtol, atol, ev, error, 1e6 * seconds))
        print("equal accuracy: %s" % ("rtol %g, atol %g (error %.2e <= hillstab's %.2e on the same points)"
                                      % (scipy_equal[0], scipy_equal[1], scipy_equal[3], hs_error_subset)
                                      if scipy_equal else "no setting reaches hillstab's %.2e" % hs_error_subset))
    else:
        print("scipy is not installed here: the scipy loop was not run")

    os.makedirs(os.path.dirname(args.out) or ".", exist_ok=True)
    with open(args.out + ".part", "w") as f:
        f.write("# hillstab equation benchmark (scripts/bench_equation.py): one thread (OMP_NUM_THREADS=1), release "
                "build, %d interleaved rounds\n" % args.rounds)
        f.write("# mathieu_*: 300 x 300 chart, alpha in [0, 20], beta in [-5, 40], auto 1e-10, whole runs: model "
                "'equation' (stiffness 'b - a*cos(pi*t)', frequency 'pi') and the built-in 'mathieu'; agreement of "
                "the two files: worst |dS|/max(1, |S|) = %.3e, verdicts differing at %d points\n"
                % (agreement, verdicts_differ))
        f.write("# mathieu_*_verdicts: the same charts with columns 'a b stable' / 'alpha beta stable' (the verdicts "
                "only); the two verdict charts differ at %d points\n" % verdict_charts_differ)
        f.write("# pendula_*: the two pendula on a shaken support (data/scenes/system_pendula.nml), 151 x 301, auto "
                "1e-10, whole runs: model 'equations' (stiffness 'b*B + a*C*cos(pi*t)', frequency 'pi') and the "
                "built-in 'system'; worst |d trace|/max(1, |trace|) = %.3e, verdicts differing at %d points\n"
                % (pendula_agreement, pendula_verdicts_differ))
        f.write("# kapitza_*: %s (300 x 300 over (w, A), auto 1e-10) by hillstab (whole run), by bench/chart_gsl_"
                "kapitza.c (GSL rk8pd on the physical equation over one period 2 pi/w, whole chart, whole run) and by "
                "a scipy loop (solve_ivp DOP853 on the fundamental matrix of the physical equation, point after point, "
                "on a %d x %d sub-grid, time per point extrapolated)\n" % (KAPITZA_SCENE, len(rows), len(rows)))
        f.write("# errors: |S - S_ref|/max(1, |S_ref|) of S1 = exp(kappa T/2) trace, against hillstab's magnus6 at "
                "1e-13 at the points given by error_points (chart: all 90000; sub-grid: the %d scipy points); "
                "error_physical: the 30 damped points of data/reference/physical_set.dat (45 digits), where magnus6 "
                "1e-13 is off by %.2e; -1: not measured\n" % (len(subset), ref_error_physical))
        f.write("# hillstab's worst error over the sub-grid: %.3e\n" % hs_error_subset)
        f.write("# kapitza_one_system: the Kapitza scene as model 'equations' with n = 1 (the scalar path of a "
                "system of one equation), its ratio to kapitza_hillstab; error of exp(kappa T/2) trace; %d points at "
                "a status other than 0\n" % one_status)
        f.write("# kapitza_swapped: the Kapitza scene over (A, w) (alpha = 'A', beta = 'w': the frequency and the "
                "damping along beta, each point alone), its ratio to kapitza_hillstab; within %.3e of that chart; %d "
                "points at a status other than 0\n" % (swapped_agreement, swapped_status))
        for tol, ev, e_chart, e_sub, seconds, failed in gsl_search:
            f.write("# search gsl tol %g evaluations_per_point %.1f error_chart %.3e error_subgrid %.3e\n"
                    % (tol, ev, e_chart, e_sub))
        for rtol, atol, ev, error, seconds in scipy_search:
            f.write("# search scipy rtol %g atol %g evaluations_per_point %.1f error_subgrid %.3e us_per_point %.1f\n"
                    % (rtol, atol, ev, error, 1e6 * seconds))
        if solve_ivp is None:
            f.write("# scipy not installed: the scipy loop was not run\n")
        f.write("# columns: job round points seconds seconds_per_point ratio_to_hillstab setting error error_points "
                "error_physical\n")
        for name, label, kind, what, points, setting, error, where, error_physical in jobs:
            q = ratios(name)
            for k in range(args.rounds):
                f.write("%s %d %d %.6f %.6e %.4f %s %.3e %s %.3e\n" % (name, k + 1, points, times[name][k],
                                                                       per_point(name, k), q[k], setting, error,
                                                                       where.replace(" ", "_"), error_physical))
    os.replace(args.out + ".part", args.out)
    print("wrote " + args.out)
    for name in os.listdir(work):
        os.remove(os.path.join(work, name))
    os.rmdir(work)
    return 0 if agreement <= MATHIEU_AGREEMENT and pendula_agreement <= PENDULA_AGREEMENT else 1


if __name__ == "__main__":
    sys.exit(main())
