#!/usr/bin/env python3
"""High-precision reference traces S of x'' + Q(tau) x = 0 at hillstab's hard points.

Independent of hillstab's code: Taylor-series integration in mpmath (40+ digits)
of the even and odd solutions u, v on [0, 1] (Q is even and 2-periodic, so
S = 2 (u v' + u' v) at tau = 1, Floquet theory), with the Taylor coefficients of
Q from the series of cos(pi tau) and a series division, and each step's length
chosen so that the series tail is below the working precision (and at most a
fraction of the distance to the nearest complex pole of Q, 1 - k cos(pi tau) = 0).

Every point is computed twice, with (order, tail, digits) = (50, 1e-30, 40) and
(64, 1e-38, 50); the table keeps the second and, as `ref_error`, the difference of
the two relative to max(1, |S|): the reference's own error bound. The Wronskian
u v' - u' v = 1 is checked too.

Points: the hard set alpha in {9.8, 9.85, 9.869} x beta in {-1e4, -1e3, 0, 1e3,
1e4, 1e5}; points where earlier versions failed or missed their tolerance; the
Mathieu model q(tau) = beta - nu cos(pi tau) at q = 2 nu/pi^2 = 20 on its a0 and
b1 transition curves, beta = (pi^2/4) a0(20), (pi^2/4) b1(20) (S = +2 and -2 up to
the rounding of beta to a double; the reference is computed at that double).

Run from the repository root (installs mpmath and gmpy2 from PyPI if missing):
    bash data/reference/make_reference.sh
writes data/reference/hard_set.dat. Takes a few minutes on 2 cores. With --check
(`python3 data/reference/make_reference.py --check`) it writes
data/reference/check_set.dat instead: points of the same kind that no method was
tuned on (see `check_points`). With --chart it writes data/reference/chart_set.dat: 40 points of the
300 x 300 chart of the chart benchmark (see `chart_points`). With --curves it writes data/reference/curve_set.dat: points of the
elastic transition curves (see `curve_points`). With --band it writes data/reference/band_set.dat: the
band beta in +-[1e-5, 1e-2] and {0}, alpha in [9.3, pi^2 - 1e-6], where S is close to 2
and the solution x ~ r(tau) of beta = 0 is nearly periodic (see `band_points`). With --pivot it writes
data/reference/pivot_set.dat: alpha = pi^2 - 10^-k (k = 3 ... 6) against |beta| = 1e2 ... 1e5 of both signs,
where the dip of Q at tau = 0 is deepest (see `pivot_points`).
"""
import sys
import multiprocessing as mproc
import random

import mpmath as mp

ELASTIC, MATHIEU = 0, 1


def mathieu_values(q, n_terms=80):
    """a0(q) and b1(q) of y'' + (a - 2q cos 2z) y = 0 from the tridiagonal
    eigenproblems of the Fourier coefficients (truncated at n_terms)."""
    # ce_{2n}: basis cos(2nz), n >= 0, with the sqrt(2) symmetrisation of the first row
    a = mp.zeros(n_terms, n_terms)
    for n in range(n_terms):
        a[n, n] = (2 * n) ** 2
        if n + 1 < n_terms:
            off = q * (mp.sqrt(2) if n == 0 else 1)
            a[n, n + 1] = off
            a[n + 1, n] = off
    # se_{2n+1}: basis sin((2n+1)z), first diagonal entry 1 - q
    b = mp.zeros(n_terms, n_terms)
    for n in range(n_terms):
        b[n, n] = (2 * n + 1) ** 2 - (q if n == 0 else 0)
        if n + 1 < n_terms:
            b[n, n + 1] = q
            b[n + 1, n] = q
    ea = mp.eigsy(a, eigvals_only=True)
    eb = mp.eigsy(b, eigvals_only=True)
    return min(ea), min(eb)


def trace(model, alpha, beta, order, tail, dps, solutions=False):
    """S, the Wronskian defect and the number of steps at (model, alpha, beta); with
    solutions, (u, u', v, v') at tau = 1 instead."""
    with mp.workdps(dps):
        pi = mp.pi
        alpha = mp.mpf(alpha)
        beta = mp.mpf(beta) if not isinstance(beta, mp.mpf) else +beta
        k = alpha / pi**2
        # Taylor coefficients of cos(pi h) and sin(pi h)
        pc = [mp.mpf(0)] * (order + 1)
        ps = [mp.mpf(0)] * (order + 1)
        term = mp.mpf(1)
        for j in range(order + 1):
            if j > 0:
                term = term * pi / j
            if j % 4 == 0:
                pc[j] = term
            elif j % 4 == 1:
                ps[j] = term
            elif j % 4 == 2:
                pc[j] = -term
            else:
                ps[j] = -term
        if model == ELASTIC:
            # poles of Q at cos(pi tau) = 1/k: tau = +-i acosh(1/k)/pi (+ even integers)
            t_pole = mp.acosh(1 / k) / pi if k > 0 else mp.inf
        else:
            t_pole = mp.inf

        def q_series(tau0):
            c0, s0 = mp.cos(pi * tau0), mp.sin(pi * tau0)
            cs = [c0 * pc[j] - s0 * ps[j] for j in range(order + 1)]
            if model == MATHIEU:
                qs = [-alpha * c for c in cs]
                qs[0] += beta
                return qs
            d = [-k * c for c in cs]
            d[0] += 1
            r = [mp.mpf(0)] * (order + 1)
            r[0] = 1 / d[0]
            for n in range(1, order + 1):
                acc = mp.mpf(0)
                for j in range(1, n + 1):
                    acc += d[j] * r[n - j]
                r[n] = -acc * r[0]
            qs = [(beta - pi**2) * x for x in r]
            qs[0] += pi**2
            return qs

        def taylor(qs, x0, x1):
            x = [mp.mpf(0)] * (order + 1)
            x[0], x[1] = x0, x1
            for n in range(order - 1):
                acc = mp.mpf(0)
                for j in range(n + 1):
                    acc += qs[j] * x[n - j]
                x[n + 2] = -acc / ((n + 1) * (n + 2))
            return x

        tau = mp.mpf(0)
        u, du, v, dv = mp.mpf(1), mp.mpf(0), mp.mpf(0), mp.mpf(1)
        h = mp.mpf("0.001")
        steps = 0
        while tau < 1:
            qs = q_series(tau)
            xu = taylor(qs, u, du)
            xv = taylor(qs, v, dv)
            rho = mp.sqrt(tau**2 + t_pole**2) if t_pole != mp.inf else mp.inf
            h = min(h * 2, 1 - tau)
            if rho != mp.inf:
                h = min(h, rho / 3)
            while True:
                ok = True
                for xs in (xu, xv):
                    size = max(abs(xs[0]), abs(xs[1]) * h)
                    last = max(abs(xs[order - 1]) * h ** (order - 1), abs(xs[order]) * h**order)
                    if last > tail * size:
                        ok = False
                if ok:
                    break
                h = h / 2
            u_new = sum(xu[n] * h**n for n in range(order + 1))
            du_new = sum(n * xu[n] * h ** (n - 1) for n in range(1, order + 1))
            v_new = sum(xv[n] * h**n for n in range(order + 1))
            dv_new = sum(n * xv[n] * h ** (n - 1) for n in range(1, order + 1))
            u, du, v, dv = u_new, du_new, v_new, dv_new
            tau = tau + h if tau + h < 1 else mp.mpf(1)
            steps += 1
        if solutions:
            return u, du, v, dv
        s = 2 * (u * dv + du * v)
        wronskian_defect = abs(u * dv - du * v - 1)
        return s, wronskian_defect, steps


def half_period(model, alpha, beta, order, tail, dps):
    """u, u', v, v' at tau = 1 (the even and odd solutions), by the same Taylor integration
    as `trace`, at the working precision dps."""
    with mp.workdps(dps):
        return trace(model, alpha, beta, order, tail, dps, solutions=True)


def curve_root(point, order, tail, dps):
    """beta on the transition curve of `point` = (alpha, kind, order_n, parity, start): the
    root of the component of Phi(1) that vanishes there, u'(1) (periodic even, a_n), v(1)
    (periodic odd, b_n), u(1) (antiperiodic even), v'(1) (antiperiodic odd): a simple root
    even where the two curves of an order coincide (S - 2 only touches 0 there). Secant
    method from the start value (hillstab's Hill method; the root found must lie within
    1e-6 of it, or the start led to another curve)."""
    alpha, kind, n, parity, start = point
    index = {(2, 1): 1, (2, -1): 2, (-2, 1): 0, (-2, -1): 3}[(kind, parity)]
    with mp.workdps(dps):
        def f(b):
            return half_period(ELASTIC, alpha, b, order, tail, dps)[index]
        b0 = mp.mpf(start)
        b1 = b0 + mp.mpf("1e-7") * max(1, abs(b0))
        f0, f1 = f(b0), f(b1)
        for _ in range(40):
            if f1 == f0:
                break
            b2 = b1 - f1 * (b1 - b0) / (f1 - f0)
            b0, f0 = b1, f1
            b1, f1 = b2, f(b2)
            if abs(b1 - b0) < mp.mpf(10) ** (-(dps - 6)) * max(1, abs(b1)):
                break
        if abs(b1 - mp.mpf(start)) > mp.mpf("1e-6") * max(1, abs(mp.mpf(start))):
            raise RuntimeError("curve point %r: root %s far from its start" % (point, b1))
        return b1


def curve_line(point):
    b1 = curve_root(point, 40, mp.mpf("1e-26"), 32)
    b2 = curve_root(point, 56, mp.mpf("1e-34"), 44)
    with mp.workdps(44):
        line = "%s %d %d %d %s %s" % (repr(point[0]), point[1], point[2], point[3], mp.nstr(b2, 25),
                                      mp.nstr(max(abs(b1 - b2) / max(1, abs(b2)), mp.mpf("1e-40")), 3))
    print(line, file=sys.stderr, flush=True)
    return line


def curve_points():
    """Elastic transition curves crossing beta in [-50, 40] at alpha = 2, 5, 8, 9, 9.5, 9.8,
    every order from 1 (beta = 0 and beta = pi^2, exact curves, left out): (alpha, kind,
    order, parity, start) with the start from hillstab's Hill method at tolerance 1e-12."""
    return [
        (2.0, -2, 1, -1, 1.763509184004056),
        (2.0, -2, 1, 1, 3.267199012747406),
        (2.0, -2, 3, 1, 21.98879192037978),
        (2.0, -2, 3, -1, 21.99247997400036),
        (2.0, 2, 4, 1, 38.98677076411258),
        (2.0, 2, 4, -1, 38.98677076411258),
        (5.0, -2, 1, -1, 0.8766005119978297),
        (5.0, -2, 1, 1, 4.692232190876094),
        (5.0, -2, 3, 1, 20.73871418421774),
        (5.0, -2, 3, -1, 20.80411287458061),
        (5.0, 2, 4, -1, 36.20376810710144),
        (5.0, 2, 4, 1, 36.20376810710145),
        (8.0, -2, 1, -1, 0.2186457591441968),
        (8.0, -2, 1, 1, 6.598215026305491),
        (8.0, -2, 3, 1, 17.69592098774797),
        (8.0, -2, 3, -1, 18.06998018126381),
        (8.0, 2, 4, 1, 29.54450311629769),
        (8.0, 2, 4, -1, 29.54450311629769),
        (9.0, -2, 1, -1, 0.07126887852946062),
        (9.0, -2, 1, 1, 7.519300631954724),
        (9.0, -2, 3, 1, 15.69478945730775),
        (9.0, -2, 3, -1, 16.37402817160946),
        (9.0, 2, 4, 1, 25.21128316631184),
        (9.0, 2, 4, -1, 25.21128316631185),
        (9.0, -2, 5, 1, 37.15669612162398),
        (9.0, -2, 5, -1, 37.17481366658214),
        (9.5, -2, 1, -1, 0.02011554098864465),
        (9.5, -2, 1, 1, 8.18200879144145),
        (9.5, -2, 3, 1, 14.03810064801171),
        (9.5, -2, 3, -1, 15.02912488671466),
        (9.5, 2, 4, 1, 21.62850848213387),
        (9.5, 2, 4, -1, 21.6285084821341),
        (9.5, -2, 5, 1, 30.89516312344354),
        (9.5, -2, 5, -1, 30.93842011641719),
        (9.8, -2, 1, -1, 0.001667896825336967),
        (9.8, -2, 1, 1, 8.89869428900289),
        (9.8, -2, 3, 1, 12.08274819100451),
        (9.8, -2, 3, -1, 13.49600122124452),
        (9.8, 2, 4, 1, 17.34529364942884),
        (9.8, 2, 4, -1, 17.3452936494303),
        (9.8, -2, 5, 1, 23.24290253287949),
        (9.8, -2, 5, -1, 23.3626233928055),
        (9.8, 2, 6, 1, 30.71794188273553),
        (9.8, 2, 6, -1, 30.71794188273812),
        (9.8, -2, 7, 1, 39.5367576338566),
        (9.8, -2, 7, -1, 39.54930580637034),
    ]


def point_line(point):
    model, alpha, beta, label = point
    s1, w1, n1 = trace(model, alpha, beta, 50, mp.mpf("1e-30"), 40)
    s2, w2, n2 = trace(model, alpha, beta, 64, mp.mpf("1e-38"), 50)
    with mp.workdps(50):
        scale = max(mp.mpf(1), abs(s2))
        ref_error = abs(s1 - s2) / scale
        log_abs = mp.log(abs(s2)) if s2 != 0 else mp.mpf(-700)
        sign = 1 if s2 >= 0 else -1
        s_text = mp.nstr(s2, 25, min_fixed=-3, max_fixed=1) if abs(s2) < mp.mpf("1e300") else "0"
        line = "%d %s %s %d %s %s %s %s %d  # %s" % (
            model, repr(alpha), repr(beta), sign, mp.nstr(log_abs, 25, min_fixed=-3, max_fixed=1),
            s_text.replace("e", "e") if s_text != "0" else "0.0",
            mp.nstr(max(ref_error, mp.mpf("1e-40")), 3), mp.nstr(max(w2, mp.mpf("1e-45")) / scale, 3), n2, label)
    print(line, file=sys.stderr, flush=True)
    return line


def points():
    pts = []
    for alpha in (9.8, 9.85, 9.869):
        for beta in (-1e4, -1e3, 0.0, 1e3, 1e4, 1e5):
            pts.append((ELASTIC, alpha, beta, "hard set"))
    for alpha, beta, label in [
            (9.869, 0.3, "gsl failed"), (9.865, -9.865, "gsl failed"), (9.86, -1e6, "magnus4 failed"),
            (9.869, -1e6, "magnus4 failed"), (0.0, 1e5, "gsl failed, alpha = 0"),
            (0.0, -1e5, "gsl failed, alpha = 0"), (9.0, -1e4, "gsl failed"), (9.0, 0.0, "rk missed"),
            (9.5, 0.0, "rk missed"), (9.869, 2.47, "near pi^2"), (5.0, 1e5, "large beta"),
            (5.0, -1e4, "large negative beta")]:
        pts.append((ELASTIC, alpha, beta, label))
    with mp.workdps(50):
        q = mp.mpf(20)
        a0, b1 = mathieu_values(q)
        nu = float(q * mp.pi**2 / 2)
        pts.append((MATHIEU, nu, float(mp.pi**2 / 4 * a0), "mathieu q = 20 on a0 (S = +2)"))
        pts.append((MATHIEU, nu, float(mp.pi**2 / 4 * b1), "mathieu q = 20 on b1 (S = -2)"))
    return pts


def check_points():
    """A second set of the same kind at other points, for checking that what was tuned on the
    hard set holds elsewhere: larger |beta| (more oscillations or more growth), alpha = 9.7 and
    9.86, the Mathieu model at q = 10 and q = 30 on its a0 and b1 curves, and one more Mathieu
    point (nu = 226.18, beta = -193.40) found by an independent check."""
    pts = []
    for alpha in (0.0, 5.0, 9.7, 9.86):
        for beta in (-3e4, 3e4, 3e5):
            pts.append((ELASTIC, alpha, beta, "check set"))
    for alpha, beta in [(9.7, 0.0), (9.86, 0.0), (9.7, 2.47), (9.86, 2.47), (9.7, -3e5), (9.86, 1e3),
                        (9.7, -1e6), (9.3, 1e5)]:
        pts.append((ELASTIC, alpha, beta, "check set"))
    with mp.workdps(50):
        for qv in (10, 30):
            q = mp.mpf(qv)
            a0, b1 = mathieu_values(q)
            nu = float(q * mp.pi**2 / 2)
            pts.append((MATHIEU, nu, float(mp.pi**2 / 4 * a0), "mathieu q = %d on a0 (S = +2)" % qv))
            pts.append((MATHIEU, nu, float(mp.pi**2 / 4 * b1), "mathieu q = %d on b1 (S = -2)" % qv))
    # a Mathieu point where rk's round-off level was 4.4x below its error (S = -3.46e6)
    pts.append((MATHIEU, 226.17754433821787, -193.3961568448847, "mathieu rk round-off"))
    return pts


def grid_value(lo, hi, n, i):
    """hillstab's grid_value: lo + (hi - lo)(i - 1)/(n - 1) in double precision, hi exactly at i = n."""
    if n <= 1:
        return lo
    if i == n:
        return hi
    return lo + (hi - lo) * float(i - 1) / float(n - 1)


def chart_points():
    """40 points of the 300 x 300 chart alpha in [0, 9.8], beta in [-2, 12] of the chart benchmark
    (scripts/bench_chart.py, bench/chart_gsl.c): rows i in {1, 60, 120, 180, 240, 270, 290, 300} (the
    last ones near the hard end alpha = 9.8), columns j in {1, 75, 150, 225, 300}, the exact doubles
    both programs use."""
    pts = []
    for i in (1, 60, 120, 180, 240, 270, 290, 300):
        for j in (1, 75, 150, 225, 300):
            pts.append((ELASTIC, grid_value(0.0, 9.8, 300, i), grid_value(-2.0, 12.0, 300, j),
                        "chart 300 x 300 (%d, %d)" % (i, j)))
    return pts


def band_points():
    """The band beta in +-[1e-5, 1e-2] and {0}, alpha in [9.3, pi^2 - 1e-6]: four points
    reported as missed by earlier versions, then points drawn with a fixed seed: alpha
    uniform in [9.3, pi^2 - 1e-6] for half of them and with pi^2 - alpha log-uniform in
    [1e-6, pi^2 - 9.3] for the other half (the dip deepens as alpha -> pi^2); |beta|
    log-uniform in [1e-5, 1e-2] with a random sign, one point in eight at beta = 0."""
    pts = [(ELASTIC, 9.82, -0.0007, "band: magnus6 missed"), (ELASTIC, 9.73, 0.002, "band: magnus6 missed"),
           (ELASTIC, 9.536632300815704, 0.0004637511878637649, "band: auto missed"),
           (ELASTIC, 9.52, 0.0015, "band: auto missed")]
    rng = random.Random(20261201)
    top = float(mp.pi**2) - 1e-6
    for i in range(36):
        if i % 2 == 0:
            alpha = rng.uniform(9.3, top)
        else:
            alpha = float(mp.pi**2) - 10 ** rng.uniform(-6, float(mp.log10(mp.pi**2 - 9.3)))
            alpha = min(max(alpha, 9.3), top)
        if i % 8 == 7:
            beta = 0.0
        else:
            beta = rng.choice((-1, 1)) * 10 ** rng.uniform(-5, -2)
        pts.append((ELASTIC, alpha, beta, "band"))
    return pts


def pivot_points():
    """The approach to the pivot: alpha = pi^2 - 10^-k (the double nearest pi^2, minus 10^-k), k = 3 ... 6,
    against beta in +-{1e2, 1e3, 1e4, 3e4, 1e5} (the dip of Q at tau = 0 of depth |beta - pi^2|/(1 - alpha/pi^2)
    and width sqrt(1 - alpha/pi^2)), and the point where method auto once failed (1 - alpha/pi^2 = 1e-8,
    beta = -66515.8: its mapped mesh needed more than 2^18 steps). Deeper k take minutes a point here (the
    test monodromy/pivot_scan_every_method runs k = 7, 8 against the methods' agreement instead)."""
    pts = []
    for k in range(3, 7):
        alpha = float(mp.pi**2) - 10.0**-k
        for beta in (-1e5, -3e4, -1e4, -1e3, -1e2, 1e2, 1e3, 1e4, 3e4, 1e5):
            pts.append((ELASTIC, alpha, beta, "pivot 10^-%d" % k))
    pts.append((ELASTIC, 9.869604301014792, -66515.82489436984, "pivot: auto failed"))
    return pts


def curves_main(out, serial):
    pts = curve_points()
    with mproc.Pool(1 if serial else 2) as pool:
        lines = pool.map(curve_line, pts, chunksize=1)
    with open(out, "w") as f:
        f.write("# Reference transition curves of the elastic model (eq. (25)), made by\n")
        f.write("# data/reference/make_reference.py --curves (mpmath %s, Taylor series, 44 digits): beta where\n"
                % mp.__version__)
        f.write("# the component of Phi(1) = [[u, v], [u', v']] that vanishes on the curve is 0 (u'(1): periodic\n")
        f.write("# even a_n; v(1): periodic odd b_n; u(1): antiperiodic even; v'(1): antiperiodic odd), by the secant\n")
        f.write("# method; ref_error: |beta(order 40, 32 digits) - beta(order 56, 44 digits)|/max(1, |beta|)\n")
        f.write("# columns: alpha kind order parity beta ref_error\n")
        for line in lines:
            f.write(line + "\n")


def main():
    args = [a for a in sys.argv[1:] if a not in ("--check", "--band", "--serial", "--curves", "--chart", "--pivot")]
    if "--curves" in sys.argv[1:]:
        curves_main(args[0] if args else "data/reference/curve_set.dat", "--serial" in sys.argv[1:])
        return
    check = "--check" in sys.argv[1:]
    band = "--band" in sys.argv[1:]
    chart = "--chart" in sys.argv[1:]
    pivot = "--pivot" in sys.argv[1:]
    default = "data/reference/pivot_set.dat" if pivot else "data/reference/band_set.dat" if band else (
        "data/reference/check_set.dat" if check else (
            "data/reference/chart_set.dat" if chart else "data/reference/hard_set.dat"))
    out = args[0] if args else default
    pts = pivot_points() if pivot else band_points() if band else (
        check_points() if check else (chart_points() if chart else points()))
    with mproc.Pool(1 if "--serial" in sys.argv[1:] else 2) as pool:
        lines = pool.map(point_line, pts, chunksize=1)
    with open(out, "w") as f:
        f.write("# Reference traces S of x'' + Q(tau) x = 0 at hillstab's %s points, made by\n"
                % ("pivot" if pivot else "band" if band else ("check" if check else ("chart" if chart else "hard"))))
        f.write("# data/reference/make_reference.py (mpmath %s, Taylor series, 50 digits).\n" % mp.__version__)
        f.write("# model: 0 elastic Q of eq. (25), 1 mathieu q = beta - alpha cos(pi tau); alpha, beta: the exact\n")
        f.write("# doubles used; sign, ln_abs_S: sign and natural log of |S|; S: S itself (0.0 when |S| > 1e300);\n")
        f.write("# ref_error: |S(order 50, 40 digits) - S(order 64, 50 digits)|/max(1, |S|);\n")
        f.write("# wronskian: |u v' - u' v - 1|/max(1, |S|); steps: Taylor steps on [0, 1]\n")
        f.write("# columns: model alpha beta sign ln_abs_S S ref_error wronskian steps\n")
        for line in lines:
            f.write(line + "\n")


if __name__ == "__main__":
    main()
