#!/usr/bin/env python3
"""The stability transitions of twelve systems of Hill equations along one row each, the reference
of the audit of the system boundaries (test/curves/test_system_boundaries.f90, audit_against_reference).

The systems, as the matrix system of the scenes writes them (period P = 2):
    M x'' + (C + eps M + G) x' + (K0 + beta B + alpha sum_k (Kc_k cos(k pi tau) + Ks_k sin(k pi tau))) x = 0
with n = 2, 3 or 4 degrees of freedom, undamped (C = 0, eps = 0: Hamiltonian, also one gyroscopic) and
damped (C, eps or both; G = 0), one or two drive harmonics, some with sine terms. Their matrices come
from fixed seeds (random.Random) rounded to four decimals and are written into the data file; every
computation here takes those decimals exactly (mpmath) or as their doubles (numpy).

Independent of the Fortran code, in two precisions:
1. Double (numpy): the monodromy over one period from the identity, state (x, x'), by a fixed-step
   Taylor-series method (order 30, step rho/rate with rho = 0.3, the rate as in
   make_physical_reference.py), vectorised over beta. From it a signed quantity q, negative where the
   system is unstable: for a Hamiltonian system the characteristic polynomial of the monodromy is
   palindromic, its n values z = lambda + 1/lambda are the roots of a polynomial of degree n, and
   stable means every z real in [-2, 2]: q = min(min_k (4 - Re z_k^2), min_{k<l} Re (z_k - z_l)^2);
   for a damped system q = -ln max|lambda|. A scan of q at 4000 equally spaced beta of the row (plus a
   golden-section search of every positive local minimum of q for a tongue narrower than the
   samples, kept where q is negative at its minimum in extended precision too) gives the
   transitions; each is located by bisection on the sign of q to 1e-13 max(1, |beta|).
2. Extended precision (mpmath, 32 digits, Taylor order 30, rho = 0.8: the integrator of
   make_physical_reference.py): q at beta = e - w and e + w for every transition e, w = 2e-11
   max(1, |e|) (grown tenfold until both sides are decided and differ, then brought back to 2e-11 by
   bisection in extended precision): the signs differ, so the transition lies in [e - w, e + w]
   whatever the error of the double computation; and q at the midpoint of every region between
   transitions: the region's verdict. The kind of a transition is read off its unstable side in
   extended precision: a z beyond +2 (+1), beyond -2 (-1), a complex pair (combination, 0); damped:
   the largest |lambda| real positive, real negative or complex.
The double q at every extended-precision point is compared with the extended one (printed, asserted
below 1e-9), and Liouville's det = exp(-trace(M^-1 (C + eps M)) P) is asserted to 1e-25 for each
extended monodromy.

Run from the repository root: python3 data/reference/make_audit_reference.py
writes data/reference/audit_set.dat (about 15 minutes on one core: numpy and mpmath);
python3 data/reference/make_audit_reference.py 2 9 runs systems 2 and 9 only and prints their lines.
"""
import math
import os
import random
import sys
import time

import mpmath as mp
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_physical_reference import monodromy as mp_monodromy  # noqa: E402

OUT = "data/reference/audit_set.dat"
PERIOD = 2
SCAN = 4000            # samples of the double scan of a row
TASK_SAMPLES = 140     # the samples of the row given to the task (its window and brackets)
ORDER, RHO = 30, 0.3   # double Taylor method
MP_SETTING = (32, 30, 0.8)   # digits, order, rho of the extended one
W0 = 2.0e-11           # first half-width of the extended-precision bracket, relative to max(1, |e|)


# ---------------------------------------------------------------- the systems
def rounded(x):
    return "%.4f" % x


def symmetric(rng, n, size):
    a = [[0.0] * n for _ in range(n)]
    for q in range(n):
        for p in range(q + 1):
            a[p][q] = a[q][p] = size * (2 * rng.random() - 1)
    return a


def make_system(seed, n, harmonics=1, sine=False, damping=0.0, eps=0.0, gyroscopic=0.0, alpha=0.4,
                lo=0.5, hi=14.0, drive=0.6):
    """Matrices as decimal strings (row by row): M = (1 + 0.3 i) I + small, B = I + small, K0 = 0.4 i I +
    small, each drive symmetric of size `drive`, C = damping (I + small) when damping > 0, G skew."""
    rng = random.Random(seed)
    m, b, k0 = symmetric(rng, n, 0.1), symmetric(rng, n, 0.2), symmetric(rng, n, 0.3)
    for i in range(n):
        m[i][i] += 1 + 0.3 * (i + 1)
        b[i][i] += 1
        k0[i][i] += 0.4 * (i + 1)
    kc = [symmetric(rng, n, drive / (k + 1)) for k in range(harmonics)]
    ks = [symmetric(rng, n, 0.5 * drive / (k + 1)) for k in range(harmonics)] if sine else []
    c = [[0.0] * n for _ in range(n)]
    if damping > 0:
        c = symmetric(rng, n, 0.25 * damping)
        for i in range(n):
            c[i][i] += damping
    g = [[0.0] * n for _ in range(n)]
    if gyroscopic > 0:
        for q in range(n):
            for p in range(q):
                g[p][q] = gyroscopic * (2 * rng.random() - 1)
                g[q][p] = -float(rounded(g[p][q]))

    def text(a):
        return [rounded(v) if v != 0 else "0" for row in a for v in row]

    return {"seed": seed, "n": n, "harmonics": harmonics, "sine": sine, "eps": rounded(eps) if eps else "0",
            "alpha": rounded(alpha), "lo": rounded(lo), "hi": rounded(hi),
            "mass": text(m), "damping": text(c), "gyroscopic": text(g), "k0": text(k0), "b": text(b),
            "cos": [v for a in kc for v in text(a)], "sin": [v for a in ks for v in text(a)] if sine else [],
            "hamiltonian": damping == 0 and eps == 0}


SYSTEMS = [
    make_system(101, 2, alpha=0.5),
    make_system(102, 2, sine=True, alpha=0.6),
    make_system(103, 2, damping=0.02, alpha=0.8),
    make_system(104, 2, gyroscopic=0.3, alpha=0.5),
    make_system(105, 2, harmonics=2, alpha=1.0),
    make_system(201, 3, alpha=0.4),
    make_system(202, 3, harmonics=2, alpha=0.5),
    make_system(203, 3, eps=0.03, alpha=0.7),
    make_system(204, 3, damping=0.015, sine=True, alpha=0.7),
    make_system(301, 4, alpha=0.35),
    make_system(302, 4, damping=0.02, alpha=0.6),
    make_system(303, 4, damping=0.01, eps=0.01, harmonics=2, alpha=0.5),
]


def matrices(system, conv):
    n = system["n"]

    def mat(values):
        return [[conv(values[r * n + c]) for c in range(n)] for r in range(n)]

    h = system["harmonics"]
    blocks = lambda values: [mat(values[k * n * n:(k + 1) * n * n]) for k in range(len(values) // (n * n))]
    return (mat(system["mass"]), mat(system["damping"]), mat(system["gyroscopic"]), mat(system["k0"]),
            mat(system["b"]), blocks(system["cos"]), blocks(system["sin"]) if system["sine"] else [], h)


# ---------------------------------------------------------------- double precision (numpy)
class DoubleSystem:
    """The first-order form x'' = D x' - M^-1 (K0 + beta B + alpha sum f_t K_t) x in doubles."""

    def __init__(self, system):
        m, c, g, k0, b, kc, ks, _ = [np.array(x, dtype=float) if i < 5 else x
                                     for i, x in enumerate(matrices(system, float))]
        self.n = system["n"]
        alpha, eps = float(system["alpha"]), float(system["eps"])
        minv = np.linalg.inv(m)
        self.d = -minv @ (c + eps * m + g)
        self.p0 = minv @ k0
        self.b = minv @ b
        self.terms = [(alpha * minv @ np.array(a), "cos", (k + 1) * math.pi) for k, a in enumerate(kc)]
        self.terms += [(alpha * minv @ np.array(a), "sin", (k + 1) * math.pi) for k, a in enumerate(ks)]
        self.hamiltonian = system["hamiltonian"]

    def monodromy(self, betas, order=ORDER, rho=RHO):
        betas = np.asarray(betas, dtype=float)
        nb, n = len(betas), self.n
        kb = self.p0[None] + betas[:, None, None] * self.b[None]
        norm = lambda a: np.max(np.sum(np.abs(a), axis=-1))
        rate = math.sqrt(norm(kb) + sum(norm(k) for k, _, _ in self.terms)) + norm(self.d) + \
            max(nu for _, _, nu in self.terms)
        nsteps = math.ceil(PERIOD * rate / rho)
        h = PERIOD / nsteps
        x = np.zeros((nb, n, 2 * n))
        v = np.zeros((nb, n, 2 * n))
        for i in range(n):
            x[:, i, i] = 1
            v[:, i, n + i] = 1
        fac = [math.factorial(j) for j in range(order + 1)]
        xs = np.empty((order + 1, nb, n, 2 * n))
        vs = np.empty((order + 1, nb, n, 2 * n))
        for step in range(nsteps):
            t0 = step * h
            series = []
            for _, kind, nu in self.terms:
                c0, s0 = math.cos(nu * t0), math.sin(nu * t0)
                cyc = [c0, -s0, -c0, s0] if kind == "cos" else [s0, c0, -s0, -c0]
                series.append(np.array([(nu * h) ** j / fac[j] * cyc[j % 4] for j in range(order + 1)]))
            xs[0], vs[0] = x, v
            for k in range(order):
                acc = -kb @ xs[k] + self.d @ vs[k]
                for (kt, _, _), ser in zip(self.terms, series):
                    acc -= kt @ np.tensordot(ser[k::-1], xs[:k + 1], axes=(0, 0))
                vs[k + 1] = acc * (h / (k + 1))
                xs[k + 1] = vs[k] * (h / (k + 1))
            x, v = xs.sum(axis=0), vs.sum(axis=0)
        return np.concatenate([x, v], axis=1)

    def quantity(self, betas, order=ORDER, rho=RHO):
        """q (negative: unstable) and the kind of its most unstable part (1, -1, 0) at each beta."""
        phi = self.monodromy(betas, order, rho)
        ev = np.linalg.eigvals(phi)
        if not self.hamiltonian:
            top = np.argmax(np.abs(ev), axis=1)
            lam = ev[np.arange(len(ev)), top]
            kinds = np.where(np.abs(lam.imag) > 1e-7 * np.abs(lam), 0, np.sign(lam.real)).astype(int)
            return -np.log(np.abs(lam)), kinds
        q, kinds = [], []
        for row in ev:
            z = np.roots(z_polynomial([complex(e) for e in row], lambda a: a.real))
            value, kind = z_quantity(list(z), lambda a: float(np.real(a)))
            q.append(value)
            kinds.append(kind)
        return np.array(q), np.array(kinds)


def z_polynomial(ev, real):
    """The polynomial (highest degree first) in z = lambda + 1/lambda whose roots are the n values z of
    a palindromic characteristic polynomial with roots ev (2n of them)."""
    c = [complex(1)]
    for r in ev:                                  # coefficients, highest degree first
        c = [a - r * b for a, b in zip(c + [0], [0] + c)]
    n = len(ev) // 2
    c = [real(a) for a in c]
    a = [(c[n - i] + c[n + i]) / 2 for i in range(n + 1)]   # palindromic: c_{n-i} = c_{n+i}
    # lambda^-n p(lambda) = a_0 + sum_i a_i s_i(z), s_i = lambda^i + lambda^-i: s_0 = 2, s_1 = z,
    # s_{i+1} = z s_i - s_{i-1} (coefficient lists lowest degree first)
    s_prev, s = [2], [0, 1]
    total = [a[0]] + [0] * n
    for i in range(1, n + 1):
        for j, cj in enumerate(s):
            total[j] += a[i] * cj
        shifted = [0] + s
        s, s_prev = [shifted[j] - (s_prev[j] if j < len(s_prev) else 0) for j in range(len(shifted))], s
    return total[::-1]


def z_quantity(z, re):
    """q = min(min_k (4 - Re z_k^2), min_{k<l} Re (z_k - z_l)^2) and the kind of its minimum."""
    best, kind = None, 0
    for zk in z:
        value = 4 - re(zk) ** 2
        if best is None or value < best:
            best, kind = value, (1 if re(zk) > 0 else -1)
    for k in range(len(z)):
        for l in range(k + 1, len(z)):
            value = re((z[k] - z[l]) ** 2)
            if value < best:
                best, kind = value, 0
    return best, kind


# ---------------------------------------------------------------- extended precision (mpmath)
def mp_quantity(system, beta):
    """q, the kind of its most unstable part, and the Liouville defect at beta in extended precision."""
    dps, order, rho = MP_SETTING
    mp.mp.dps = dps
    m, c, g, k0, b, kc, ks, _ = matrices(system, mp.mpf)
    n = system["n"]
    alpha, eps, beta = mp.mpf(system["alpha"]), mp.mpf(system["eps"]), mp.mpf(beta)
    mm = mp.matrix(m)
    minv = mm ** -1
    prod = lambda a: (minv * mp.matrix(a)).tolist()
    cm = prod([[c[i][j] + eps * m[i][j] + g[i][j] for j in range(n)] for i in range(n)])
    kk = prod([[k0[i][j] + beta * b[i][j] for j in range(n)] for i in range(n)])
    terms = [([[alpha * v for v in row] for row in prod(a)], "cos", (k + 1) * mp.pi) for k, a in enumerate(kc)]
    terms += [([[alpha * v for v in row] for row in prod(a)], "sin", (k + 1) * mp.pi) for k, a in enumerate(ks)]
    phi, _ = mp_monodromy(n, cm, kk, terms, mp.mpf(PERIOD), order, rho)
    trace_d = sum((minv * mp.matrix([[c[i][j] + eps * m[i][j] for j in range(n)] for i in range(n)]))[i, i]
                  for i in range(n))
    det_ref = mp.exp(-trace_d * PERIOD)
    liouville = abs(mp.det(phi) - det_ref) / det_ref
    ev = [mp.mpc(e) for e in mp.eig(phi, left=False, right=False)]
    if not system["hamiltonian"]:
        lam = max(ev, key=abs)
        kind = 0 if abs(lam.imag) > mp.mpf("1e-20") * abs(lam) else (1 if lam.real > 0 else -1)
        return -mp.log(abs(lam)), kind, liouville
    coeffs = z_polynomial(ev, lambda a: mp.re(a))
    z = mp.polyroots(coeffs, maxsteps=200, extraprec=2 * dps)
    q, kind = z_quantity([mp.mpc(v) for v in z], lambda a: mp.re(a))
    return q, kind, liouville


# ---------------------------------------------------------------- the scan
def bisect(ds, lows, highs, q_low_negative, tol=1e-13):
    """Bisection of the sign of q on each bracket (all brackets at once)."""
    lows, highs = np.array(lows, dtype=float), np.array(highs, dtype=float)
    neg = np.array(q_low_negative)
    for _ in range(60):
        mids = 0.5 * (lows + highs)
        q, _ = ds.quantity(mids)
        same = (q < 0) == neg
        lows = np.where(same, mids, lows)
        highs = np.where(same, highs, mids)
        if np.all(highs - lows <= tol * np.maximum(1, np.abs(mids))):
            break
    return 0.5 * (lows + highs)


def golden_minima(ds, lows, highs, steps=40):
    """Golden-section minimisation of q on each bracket (all at once): the minimisers and minima."""
    g = (math.sqrt(5) - 1) / 2
    a, b = np.array(lows, dtype=float), np.array(highs, dtype=float)
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = ds.quantity(c)[0], ds.quantity(d)[0]
    for _ in range(steps):
        left = fc < fd                            # the minimum in [a, d]: c becomes d
        b = np.where(left, d, b)
        a = np.where(left, a, c)
        c_new = np.where(left, b - g * (b - a), d)
        d_new = np.where(left, c, a + g * (b - a))
        f = ds.quantity(np.where(left, c_new, d_new))[0]
        fc, fd = np.where(left, f, fd), np.where(left, fc, f)
        c, d = c_new, d_new
    x = 0.5 * (a + b)
    return x, ds.quantity(x)[0]


def scan_row(system):
    ds = DoubleSystem(system)
    lo, hi = float(system["lo"]), float(system["hi"])
    betas = np.linspace(lo, hi, SCAN)
    q = np.concatenate([ds.quantity(betas[i:i + 500])[0] for i in range(0, SCAN, 500)])
    inside = q < 0
    brackets = [(betas[j], betas[j + 1], inside[j]) for j in range(SCAN - 1) if inside[j] != inside[j + 1]]
    # a tongue narrower than the samples: a positive local minimum of q going negative
    # (strict by 1e-12: mass-proportional damping alone leaves q flat where stable)
    dips = [j for j in range(1, SCAN - 1) if not (inside[j - 1] or inside[j] or inside[j + 1])
            and q[j] < q[j - 1] - 1e-12 and q[j] < q[j + 1] - 1e-12]
    narrow = 0
    if dips:
        xs, qs = golden_minima(ds, [betas[j - 1] for j in dips], [betas[j + 1] for j in dips])
        for j, x, qx in zip(dips, xs, qs):
            # a negative minimum: a tongue if extended precision agrees (not a touch of q = 0)
            if qx < 0 and mp_quantity(system, repr(float(x)))[0] < 0:
                narrow += 1
                brackets += [(betas[j - 1], x, False), (x, betas[j + 1], True)]
    brackets.sort()
    edges = bisect(ds, [a for a, _, _ in brackets], [b for _, b, _ in brackets], [s for _, _, s in brackets]) \
        if brackets else np.array([])
    return ds, betas, q, edges, [not s for _, _, s in brackets], narrow, len(dips)


def main():
    start = time.time()
    head = [
        "# audit_set.dat: stability transitions of systems of Hill equations along one row each, the reference",
        "# of test_system_boundaries/audit_against_reference. Made by: python3 data/reference/make_audit_reference.py",
        "# (numpy double scan of %d samples a row: Taylor order %d, rho %g, transitions by bisection on the sign of q"
        % (SCAN, ORDER, RHO),
        "# to 1e-13 max(1, |beta|); confirmed in mpmath, (digits, order, rho) = %s: q at e - w and e + w of opposite"
        % (MP_SETTING,),
        "# signs, so the transition lies within w of e, w brought to 2e-11 max(1, |e|) by extended-precision bisection",
        "# where the double edge was farther off; q at the midpoint of each region gives its verdict).",
        "# System: M x'' + (C + eps M + G) x' + (K0 + beta B + alpha sum_k (Kc_k cos k pi tau + Ks_k sin k pi tau)) x = 0,",
        "# period 2; q < 0 unstable: Hamiltonian (C = 0, eps = 0) min(4 - Re z^2, nearest pair Re (z_k - z_l)^2) over",
        "# the n values z = lambda + 1/lambda, damped -ln max|lambda|. Matrices row by row, the drives block after block.",
        "# Lines: system id n harmonics has_sin eps alpha lo hi task_samples hamiltonian",
        "#        mass|damping|gyroscopic|k0|b|cos|sin values",
        "#        edge beta w stable_below kind q_below q_above   (kind: 1 at +1, -1 at -1, 0 combination;",
        "#             q_below, q_above: extended-precision q at beta - w, beta + w)",
        "#        region lo hi stable beta_mid q_mid   (extended-precision q at beta_mid)",
        "#        end",
    ]
    body, totals = [], {"systems": 0, "edges": 0, "regions": 0}
    worst_dq, worst_liou, worst_w = 0.0, mp.mpf(0), 0.0
    refined, mp_bisected = 0, 0
    only = [int(a) for a in sys.argv[1:]]        # a trial of some systems: nothing written
    for number, system in enumerate(SYSTEMS, 1):
        if only and number not in only:
            continue
        t0 = time.time()
        ds, betas, q, edges, stable_below, narrow, dips = scan_row(system)
        n = system["n"]
        body.append("system %d %d %d %d %s %s %s %s %d %d" % (
            number, n, system["harmonics"], int(system["sine"]), system["eps"], system["alpha"], system["lo"],
            system["hi"], TASK_SAMPLES, int(system["hamiltonian"])))
        for key in ("mass", "damping", "gyroscopic", "k0", "b", "cos", "sin"):
            if system[key]:
                body.append(key + " " + " ".join(system[key]))
        # the edges: extended-precision sides
        located = []
        for e, below in zip(edges, stable_below):
            scale = max(1.0, abs(e))
            w = W0 * scale
            while True:
                qb, kb, lb = mp_quantity(system, repr(float(e - w)))
                qa, ka, la = mp_quantity(system, repr(float(e + w)))
                worst_liou = max(worst_liou, lb, la)
                ok = (qb > 0) == below and (qa > 0) == (not below) and min(abs(qb), abs(qa)) > mp.mpf("1e-22")
                if ok or w > 1e-6 * scale:
                    break
                w *= 10
            assert ok, ("edge not confirmed", number, e, w, qb, qa)
            if w > W0 * scale:
                # the double edge is off by more than W0: bisection in extended precision
                lo_e, hi_e = float(e - w), float(e + w)
                while hi_e - lo_e > 2 * W0 * scale:
                    mid = 0.5 * (lo_e + hi_e)
                    qm, km, lm = mp_quantity(system, repr(mid))
                    worst_liou = max(worst_liou, lm)
                    if (qm > 0) == below:
                        lo_e, qb, kb = mid, qm, km
                    else:
                        hi_e, qa, ka = mid, qm, km
                    mp_bisected += 1
                refined += 1
                e, w = 0.5 * (lo_e + hi_e), 0.5 * (hi_e - lo_e)
                assert (qb > 0) == below and (qa > 0) == (not below) and min(abs(qb), abs(qa)) > mp.mpf("1e-22")
            dq = ds.quantity([e - w, e + w])[0]
            worst_dq = max(worst_dq, abs(dq[0] - float(qb)), abs(dq[1] - float(qa)))
            worst_w = max(worst_w, w / scale)
            kind = ka if below else kb
            located.append(float(e))
            body.append("edge %r %.3e %d %d %s %s" % (float(e), w, int(below), kind, mp.nstr(qb, 6), mp.nstr(qa, 6)))
            totals["edges"] += 1
        # the regions: extended-precision verdict at each midpoint
        bounds = [float(system["lo"])] + located + [float(system["hi"])]
        for k in range(len(bounds) - 1):
            mid = float(0.5 * (bounds[k] + bounds[k + 1]))
            if not len(edges):
                stable = bool(q[SCAN // 2] > 0)
            elif k == len(edges):
                stable = not stable_below[-1]
            else:
                stable = stable_below[k]
                assert k == 0 or stable == (not stable_below[k - 1]), ("verdicts alternate", number, k)
            qm, _, lm = mp_quantity(system, repr(mid))
            worst_liou = max(worst_liou, lm)
            worst_dq = max(worst_dq, abs(float(ds.quantity([mid])[0][0]) - float(qm)))
            assert (qm > 0) == stable, ("region verdict", number, mid, qm, stable)
            body.append("region %r %r %d %r %s" % (bounds[k], bounds[k + 1], int(stable), mid, mp.nstr(qm, 6)))
            totals["regions"] += 1
        body.append("end")
        totals["systems"] += 1
        print("system %d (n %d, %s): %d edges (%d from %d local minima), %.0f s"
              % (number, n, "undamped" if system["hamiltonian"] else "damped", len(edges), narrow, dips,
                 time.time() - t0), flush=True)
    assert worst_dq < 1e-9, worst_dq
    assert worst_liou < mp.mpf("1e-25"), worst_liou
    head.append("# %d systems, %d edges, %d regions; largest w/max(1, |beta|) %.1e; largest |q double - q extended| "
                "%.1e; Liouville to %s" % (totals["systems"], totals["edges"], totals["regions"], worst_w, worst_dq,
                                          mp.nstr(worst_liou, 2)))
    if only:
        print("\n".join(body))
        return
    with open(OUT, "w") as out:
        out.write("\n".join(head + body) + "\n")
    print("%s; wrote %s in %.0f s" % (head[-1][2:], OUT, time.time() - start))


if __name__ == "__main__":
    main()
