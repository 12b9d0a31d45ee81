#!/usr/bin/env python3
"""High-precision one-period monodromy matrices of linear periodic ODEs written in physical time t,
the reference of the tests of the physical-time front end (trace and Floquet multipliers).

Set 1, damped Kapitza pendulum (inverted pendulum on a vertically vibrated pivot):
    theta'' + kappa theta' + (-g/l + (A w^2/l) cos(w t)) theta = 0,   g = 9.81, l = 0.2, T = 2 pi/w
Set 2, one degree of freedom with a mass and a sine term:
    m x'' + c x' + (k0 + k1 cos(W t) + k2 sin(2 W t)) x = 0,   m = 2.5, c = 0.3, k0 = 40, k2 = 5, T = 2 pi/W
Set 3, damped 3-mode column (Bolotin type), x in R^3:
    M x'' + C x' + (Wm - (P0 + P1 cos(Om t)) S) x = 0,   T = 2 pi/Om, M = I, Wm = diag(1, 16, 81),
    S = [[1, 0.3, 0.1], [0.3, 4, 0.4], [0.1, 0.4, 9]], C = 2 zeta diag(1, 4, 9), zeta = 0.01, P0 = 0.3

Independent of the Fortran code: the equation as written, in the state (x, x'), is integrated over one
period T from the identity (the 2d columns of the fundamental matrix) by a fixed-step Taylor-series
method in mpmath. At each step start t0 the Taylor coefficients of cos(nu (t0 + s)) and sin(nu (t0 + s))
are exact (nu^j/j! times the cyclic derivatives of cos/sin at nu t0), those of the solution follow from
the recurrence of x'' = -C x' - K(t) x (Cauchy products of the coefficient series with the solution
series), and the step is the sum of the series. Step count n = ceil(T rate/rho),
rate = nu_max + sqrt(|K0| + sum |Kj|) + |C| (row-sum norms, M = identity after division by m).
Every point is computed twice: (digits, order, rho) = (45, 44, 0.8), the reported values, and
(36, 36, 1.0), a different step grid; ref_error is the largest difference of the two over the
trace and all multiplier parts, relative to max(1, |value|) -- an upper bound of the reported
values' error (the first run is itself much more accurate, ~1e-38).
The multipliers are the eigenvalues of the monodromy matrix: for 2x2 by the quadratic formula in
extended precision, for 6x6 by mpmath's eig; sorted by modulus descending, ties (moduli equal to a
relative 1e-25, e.g. complex-conjugate pairs) by argument ascending in (-pi, pi]; imaginary parts
below 1e-30 |lambda| (eig's rounding) are set to 0.
Checks (asserted): Liouville, det(monodromy) = exp(-trace(C) T) (= 1 for kappa = 0) to 1e-20
relative for every point of every set, worst deviation printed; ref_error < 1e-20; and a few set-1
points at kappa = 0 are recomputed with mpmath.odefun (its own Taylor method, derivatives from
Euler-step finite differences at raised precision) at 30 digits, agreement printed.

Parameters are the decimal numbers as written in the table (short decimals, computed exactly, not
their nearest doubles). Points are deterministic: fixed lists plus Halton sequences (bases 2, 3),
chosen so that about half of each set is stable (stable: all |multiplier| <= 1, to 1e-25).

Run from the repository root: python3 data/reference/make_physical_reference.py
writes data/reference/physical_set.dat (a few minutes on one core, mpmath only; gmpy2 speeds it up).
Columns (first column names the set):
    set 1: set kappa w A trace re1 im1 re2 im2 ref_error
    set 2: set W k1 trace re1 im1 re2 im2 ref_error
    set 3: set Om P1 trace re1 im1 re2 im2 re3 im3 re4 im4 re5 im5 re6 im6 ref_error
"""
import time

import mpmath as mp

MAIN = (45, 44, 0.8)    # digits, Taylor order, rho (step = rho/rate)
CHECK = (36, 36, 1.0)
OUT = "data/reference/physical_set.dat"


# ---------------------------------------------------------------- the integrator
def monodromy(d, cm, k0, terms, period, order, rho):
    """Monodromy (2d x 2d, state (x, x')) of x'' = -cm x' - (k0 + sum_j Kj f_j(t)) x over [0, period].

    cm, k0: d x d lists of mpf; terms: list of (Kj, kind, nu) with f_j = cos(nu t) or sin(nu t)."""
    n2 = 2 * d
    ne = d * n2                     # entries of the d x 2d block x (entry e = row*n2 + column)

    def norm(a):
        return max(sum(abs(v) for v in row) for row in a)

    rate = mp.sqrt(norm(k0) + sum(norm(k) for k, _, _ in terms)) + norm(cm) + max(nu for _, _, nu in terms)
    nsteps = int(mp.ceil(period * rate / rho))
    h = period / nsteps
    # scaled series Y_k = X_k h^k: the recurrence in s/h, with C h, K h^2 and nu h
    ch = [[v * h for v in row] for row in cm]
    k0h = [[v * h * h for v in row] for row in k0]
    th = [([[v * h * h for v in row] for row in k], kind, nu) for k, kind, nu in terms]
    fac = [mp.mpf(1)]
    for j in range(1, order + 1):
        fac.append(fac[-1] * j)
    x = [mp.mpf(1) if e // n2 == e % n2 else mp.mpf(0) for e in range(ne)]
    v = [mp.mpf(1) if e // n2 + d == e % n2 else mp.mpf(0) for e in range(ne)]
    for i in range(nsteps):
        t0 = i * h
        coefs = []
        for _, kind, nu in th:
            c0, s0 = mp.cos(nu * t0), mp.sin(nu * t0)
            cyc = [c0, -s0, -c0, s0] if kind == "cos" else [s0, c0, -s0, -c0]
            nuh, p, ser = nu * h, mp.mpf(1), []
            for j in range(order + 1):
                ser.append(p / fac[j] * cyc[j % 4])
                p *= nuh
            coefs.append(ser)
        y = [[x[e], v[e] * h] for e in range(ne)]
        for k in range(order - 1):
            # (f_j x)_k, Cauchy products, for each term and entry
            convs = [[mp.fdot(ser[:k + 1], y[e][k::-1]) for e in range(ne)] for ser in coefs]
            den = (k + 1) * (k + 2)
            new = []
            for r in range(d):
                for c in range(n2):
                    col1 = [y[s * n2 + c][k + 1] for s in range(d)]
                    col0 = [y[s * n2 + c][k] for s in range(d)]
                    acc = mp.fdot(ch[r], col1) * (k + 1) + mp.fdot(k0h[r], col0)
                    for (kj, _, _), cv in zip(th, convs):
                        acc += mp.fdot(kj[r], [cv[s * n2 + c] for s in range(d)])
                    new.append(-acc / den)
            for e in range(ne):
                y[e].append(new[e])
        x = [mp.fsum(y[e]) for e in range(ne)]
        v = [mp.fdot(range(1, order + 1), y[e][1:]) / h for e in range(ne)]
    mono = mp.matrix(n2, n2)
    for r in range(d):
        for c in range(n2):
            mono[r, c] = x[r * n2 + c]
            mono[r + d, c] = v[r * n2 + c]
    return mono, nsteps


# ---------------------------------------------------------------- the three equations
def mpf(s):
    return mp.mpf(s)


def eq_set1(kappa, w, a):
    g, l = mpf("9.81"), mpf("0.2")
    kappa, w, a = mpf(kappa), mpf(w), mpf(a)
    return 1, [[kappa]], [[-g / l]], [([[a * w ** 2 / l]], "cos", w)], 2 * mp.pi / w


def eq_set2(big_w, k1):
    m, c, k0, k2 = mpf("2.5"), mpf("0.3"), mpf("40"), mpf("5")
    big_w, k1 = mpf(big_w), mpf(k1)
    return (1, [[c / m]], [[k0 / m]], [([[k1 / m]], "cos", big_w), ([[k2 / m]], "sin", 2 * big_w)],
            2 * mp.pi / big_w)


S3 = (("1", "0.3", "0.1"), ("0.3", "4", "0.4"), ("0.1", "0.4", "9"))
WM3 = ("1", "16", "81")


def eq_set3(om, p1):
    s = [[mpf(v) for v in row] for row in S3]
    zeta, p0 = mpf("0.01"), mpf("0.3")
    om, p1 = mpf(om), mpf(p1)
    c = [[2 * zeta * (i + 1) ** 2 if i == j else mpf(0) for j in range(3)] for i in range(3)]
    k0 = [[(mpf(WM3[i]) if i == j else 0) - p0 * s[i][j] for j in range(3)] for i in range(3)]
    k1 = [[-p1 * s[i][j] for j in range(3)] for i in range(3)]
    return 3, c, k0, [(k1, "cos", om)], 2 * mp.pi / om


EQUATIONS = {1: eq_set1, 2: eq_set2, 3: eq_set3}


# ---------------------------------------------------------------- the points
def halton(i, base):
    f, r = 1.0, 0.0
    while i > 0:
        f /= base
        r += f * (i % base)
        i //= base
    return r


def set1_points():
    sqrt2gl = (2 * 9.81 * 0.2) ** 0.5        # threshold A w = sqrt(2 g l) (Kapitza, small q)
    pts = []
    for kappa, zeros, near, first in (
            ("0", ("60", "314.16", "700"),
             (("314.16", 0.99), ("314.16", 1.01), ("150", 0.999), ("600", 1.002)), 1),
            ("0.2", ("100", "314.16", "550"),
             (("314.16", 0.995), ("314.16", 1.005), ("90", 1.02), ("450", 0.98)), 24)):
        pts += [(kappa, w, "0") for w in zeros]
        pts += [(kappa, w, "%.7f" % (r * sqrt2gl / float(w))) for w, r in near]
        for j in range(23):
            u, v = halton(first + j, 2), halton(first + j, 3)
            w = 60 + 640 * u
            if j % 2 == 0:                    # A over the whole range [0, 0.1]
                a = 0.1 * v
            elif v < 0.5:                     # A below 1.1 times the threshold (mostly unstable)
                a = 1.1 * sqrt2gl / w * 2 * v
            else:                             # A in [0.085, 0.1], about the upper boundary q ~ 0.9
                a = 0.085 + 0.015 * (2 * v - 1)
            pts.append((kappa, "%.2f" % w, "%.6f" % a))
    return pts


def set2_points():
    pts = [("4", "0"), ("20", "0")]           # k1 = 0: the sine term alone (2W = 8 = 2 sqrt(k0/m) at W = 4)
    for j in range(1, 34):                    # the resonance region W in [2, 11], larger k1 favoured
        u, v = halton(j, 2), halton(j, 3)
        pts.append(("%.3f" % (2 + 9 * u), "%.2f" % (80 * v ** 0.5)))
    for j in range(34, 49):                   # W in [11, 30]
        u, v = halton(j, 2), halton(j, 3)
        pts.append(("%.3f" % (11 + 19 * u), "%.2f" % (80 * v)))
    return pts


def set3_points():
    mp.mp.dps = 30
    s = mp.matrix([[mpf(v) for v in row] for row in S3])
    k0 = mp.diag([mpf(v) for v in WM3]) - mpf("0.3") * s
    om = [mp.sqrt(e) for e in sorted(mp.eigsy(k0, eigvals_only=True))]
    res = [2 * om[0], 2 * om[1], 2 * om[2], om[0] + om[1], om[0] + om[2], om[1] + om[2]]
    pts = [("%.4f" % float(res[0]), "0"), ("10", "0")]
    deltas = ((-0.05, -0.015, 0, 0.015, 0.05), (-0.02, -0.007, 0, 0.007, 0.02), (-0.02, -0.007, 0, 0.007, 0.02),
              (-0.015, -0.007, 0, 0.007, 0.015), (-0.01, 0, 0.01), (-0.01, 0, 0.01))
    j = 1
    for r, ds in zip(res, deltas):            # around the principal and the sum resonances
        for delta in ds:
            pts.append(("%.4f" % (float(r) * (1 + delta)), "%.4f" % (0.4 + 1.1 * halton(j, 3))))
            j += 1
    for i in range(1, 11):                    # slow drive, large P1 (quasi-static buckling of mode 1)
        pts.append(("%.4f" % (0.5 + 0.8 * halton(i, 2)), "%.4f" % (0.7 + 0.8 * halton(i, 3))))
    for i in range(11, 23):                   # the whole box
        pts.append(("%.4f" % (0.5 + 19.5 * halton(i, 2)), "%.4f" % (1.5 * halton(i, 3))))
    return pts


# ---------------------------------------------------------------- multipliers
def multipliers(mono, tie=mpf("1e-25")):
    n = mono.rows
    if n == 2:
        tr = mono[0, 0] + mono[1, 1]
        det = mono[0, 0] * mono[1, 1] - mono[0, 1] * mono[1, 0]
        disc = tr * tr - 4 * det
        if disc >= 0:
            l1 = (tr + mp.sign(tr) * mp.sqrt(disc)) / 2 if tr != 0 else mp.sqrt(disc) / 2
            ev = [mp.mpc(l1, 0), mp.mpc(det / l1, 0)]
        else:
            ev = [mp.mpc(tr / 2, mp.sqrt(-disc) / 2), mp.mpc(tr / 2, -mp.sqrt(-disc) / 2)]
    else:
        ev = [mp.mpc(e) for e in mp.eig(mono, left=False, right=False)]
        ev = [mp.mpc(e.real, 0) if abs(e.imag) < mpf("1e-30") * abs(e) else e for e in ev]
    ev.sort(key=lambda e: -abs(e))
    out, i = [], 0
    while i < len(ev):                        # groups of equal modulus, by argument ascending
        j = i + 1
        while j < len(ev) and abs(ev[i]) - abs(ev[j]) <= tie * abs(ev[i]):
            j += 1
        out += sorted(ev[i:j], key=lambda e: mp.pi if (e.imag == 0 and e.real < 0) else mp.arg(e))
        i = j
    return out


def compute(set_id, params, setting):
    dps, order, rho = setting
    mp.mp.dps = dps
    d, cm, k0, terms, period = EQUATIONS[set_id](*params)
    mono, nsteps = monodromy(d, cm, k0, terms, period, order, rho)
    ev = multipliers(mono)
    tr = sum(mono[i, i] for i in range(mono.rows))
    det_ref = mp.exp(-sum(cm[i][i] for i in range(d)) * period)
    liouville = abs(mp.det(mono) - det_ref) / det_ref
    values = [tr]
    for e in ev:
        values += [e.real, e.imag]
    return values, liouville, max(abs(e) for e in ev), nsteps, mono


# ---------------------------------------------------------------- cross-check with mpmath.odefun
def odefun_check(kappa, w, a, dps=30):
    mp.mp.dps = dps
    _, _, k0, terms, period = eq_set1(kappa, w, a)
    q0, q1, nu = k0[0][0], terms[0][0][0][0], terms[0][2]

    def f(t, y):
        q = q0 + q1 * mp.cos(nu * t)
        return [y[1], -q * y[0], y[3], -q * y[2]]

    sol = mp.odefun(f, 0, [mpf(1), mpf(0), mpf(0), mpf(1)])
    y = sol(period)
    return mp.matrix([[y[0], y[2]], [y[1], y[3]]])


def main():
    start = time.time()
    sets = {1: set1_points(), 2: set2_points(), 3: set3_points()}
    rows, worst_err, worst_liou, counts = [], {}, {}, {}
    for set_id, pts in sets.items():
        worst_err[set_id], worst_liou[set_id], counts[set_id] = mpf(0), mpf(0), [0, 0]
        for params in pts:
            vals, liou, rho_max, nsteps, _ = compute(set_id, params, MAIN)
            chk, liou2, _, _, _ = compute(set_id, params, CHECK)
            mp.mp.dps = MAIN[0]
            err = max(abs(a - b) / max(1, abs(a)) for a, b in zip(vals, chk))
            assert liou < mpf("1e-20") and liou2 < mpf("1e-20"), (set_id, params, liou, liou2)
            assert err < mpf("1e-20"), (set_id, params, err)
            stable = rho_max <= 1 + mpf("1e-25")
            counts[set_id][0 if stable else 1] += 1
            worst_err[set_id] = max(worst_err[set_id], err)
            worst_liou[set_id] = max(worst_liou[set_id], liou, liou2)
            rows.append("%d %s %s %s" % (set_id, " ".join(params), " ".join(mp.nstr(x, 25) for x in vals),
                                          mp.nstr(err, 3)))
        print("set %d: %d points, %d stable, %d unstable, worst ref_error %s, worst Liouville deviation %s "
              "(%.0f s)" % (set_id, len(pts), counts[set_id][0], counts[set_id][1],
                            mp.nstr(worst_err[set_id], 3), mp.nstr(worst_liou[set_id], 3),
                            time.time() - start), flush=True)

    # independent cross-check: mpmath.odefun on set-1 points at kappa = 0
    worst_x = mpf(0)
    for params in (("0", "314.16", "0"), ("0", "314.16", "%.7f" % (1.01 * (2 * 9.81 * 0.2) ** 0.5 / 314.16)),
                   sets[1][7], sets[1][8]):
        ref = compute(1, params, MAIN)[4]
        alt = odefun_check(*params)
        mp.mp.dps = MAIN[0]                   # compare at full precision (unary minus rounds)
        dev = mp.mnorm(alt - ref, 1) / mp.mnorm(ref, 1)
        worst_x = max(worst_x, dev)
        print("odefun cross-check kappa=%s w=%s A=%s: trace %s vs %s, relative matrix difference %s"
              % (params + (mp.nstr(ref[0, 0] + ref[1, 1], 20), mp.nstr(alt[0, 0] + alt[1, 1], 20),
                           mp.nstr(dev, 3))), flush=True)
    assert worst_x < mpf("1e-20")

    head = [
        "# physical_set.dat: one-period monodromy (state (x, x'), from the identity, physical time t) of",
        "# linear periodic ODEs: its trace and Floquet multipliers (data/reference/make_physical_reference.py:",
        "# mpmath fixed-step Taylor series, (digits, order, rho) = %s reported, %s for ref_error)" % (MAIN, CHECK),
        "# set 1: theta'' + kappa theta' + (-g/l + (A w^2/l) cos(w t)) theta = 0, g = 9.81, l = 0.2, T = 2 pi/w",
        "# set 2: m x'' + c x' + (k0 + k1 cos(W t) + k2 sin(2 W t)) x = 0, m = 2.5, c = 0.3, k0 = 40, k2 = 5,"
        " T = 2 pi/W",
        "# set 3: M x'' + C x' + (Wm - (P0 + P1 cos(Om t)) S) x = 0, x in R^3, T = 2 pi/Om, M = I,"
        " Wm = diag(1, 16, 81),",
        "#        S = [[1, 0.3, 0.1], [0.3, 4, 0.4], [0.1, 0.4, 9]], C = 2 zeta diag(1, 4, 9), zeta = 0.01,"
        " P0 = 0.3",
        "# parameters: the decimals as written (computed exactly, not their doubles); trace = trace of the",
        "# monodromy; re_i im_i: multipliers sorted by modulus descending, equal moduli (conjugate pairs) by",
        "# argument ascending in (-pi, pi]; ref_error: max over trace and multiplier parts of the difference",
        "# of the two runs relative to max(1, |value|); det(monodromy) = exp(-trace(C) T) checked to 1e-20",
        "# stable (all |multiplier| <= 1): set 1 %d of %d, set 2 %d of %d, set 3 %d of %d"
        % (counts[1][0], len(sets[1]), counts[2][0], len(sets[2]), counts[3][0], len(sets[3])),
        "# set 1 columns: set kappa w A trace re1 im1 re2 im2 ref_error",
        "# set 2 columns: set W k1 trace re1 im1 re2 im2 ref_error",
        "# set 3 columns: set Om P1 trace re1 im1 re2 im2 re3 im3 re4 im4 re5 im5 re6 im6 ref_error",
    ]
    with open(OUT, "w") as out:
        out.write("\n".join(head + rows) + "\n")
    print("worst odefun cross-check difference %s; wrote %s (%d rows) in %.0f s"
          % (mp.nstr(worst_x, 3), OUT, len(rows), time.time() - start))


if __name__ == "__main__":
    main()
