#!/usr/bin/env python3
"""Tips of the resonance regions of the damped three-mode column, independent of hillstab.

The column (data/scenes/column_regions.nml):
    x'' + C x' + (W - (P0 + P1 cos(Om t)) S) x = 0,
    W = diag(1, 16, 81), S = [[1, .3, .1], [.3, 4, .4], [.1, .4, 9]], C = 2 zeta diag(1, 4, 9),
    zeta = 0.01, P0 = 0.3, mass I.
Stability: the 6x6 monodromy Phi of y' = A(t) y, y = (x, x'), over one period T = 2 pi/Om,
integrated by scipy's DOP853 (in tau = Om t on [0, 2 pi], several (Om, P1) points stacked in
one integration); unstable iff max |eig(Phi)| > 1.

The tip of a region: c(Om) = the least P1 in [0, 1.5] where log max|lambda| > 0 near the
region (bracketed by stepping up from 0, or from the previous c, then Brent's root finder,
scipy.optimize.brentq, to xtol absolute), minimised over Om in hint +- 1 % by
scipy.optimize.minimize_scalar (bounded Brent, xatol).  The whole search runs at two
integration tolerances; the file gets the tighter run and the largest relative difference
between the two.

Writes data/reference/column_tips.dat (columns: kind order mode_i mode_j Om P1; kind 1
simple, 2 sum), the reference of test_regions/column_tips_against_reference.

Usage: python3 data/reference/make_column_tips.py [--output FILE]
"""
import argparse
import sys
import time

import numpy as np
import scipy
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar

W = np.diag([1.0, 16.0, 81.0])
S = np.array([[1.0, 0.3, 0.1], [0.3, 4.0, 0.4], [0.1, 0.4, 9.0]])
ZETA = 0.01
C = 2.0 * ZETA * np.diag([1.0, 4.0, 9.0])
P0 = 0.3
P1_MAX = 1.5
N = 3

# (kind, order, mode_i, mode_j, Om hint, P1 hint): the tips hillstab reports, to be confirmed
REGIONS = [
    (1, 1, 1, 1, 1.6724, 0.03332),
    (1, 2, 1, 1, 0.8295, 0.2146),
    (1, 2, 2, 2, 3.8185, 1.00365),
    (2, 1, 1, 2, 4.6804, 0.45199),
    (1, 1, 2, 2, 7.6936, 0.15397),
    (1, 1, 3, 3, 17.6961, 0.35401),
]

ROOT_XTOL = 1.0e-11       # absolute, on P1
OM_XATOL_REL = 2.0e-8     # Brent's minimisation over Om, relative to Om
OM_WINDOW = 0.01          # Om in hint*(1 +- OM_WINDOW)


class Column:
    """Monodromies of the column at one integration tolerance, counted."""

    def __init__(self, rtol, atol):
        self.rtol = rtol
        self.atol = atol
        self.count = 0

    def log_rho(self, om, p1):
        """log max|lambda(Phi)| at the points (om[k], p1[k]) (arrays of equal length)."""
        om = np.atleast_1d(np.asarray(om, dtype=float))
        p1 = np.atleast_1d(np.asarray(p1, dtype=float))
        m = om.size
        self.count += m
        n2 = 2 * N

        def rhs(tau, y):
            Y = y.reshape(m, n2, n2)
            x = Y[:, :N, :]
            v = Y[:, N:, :]
            load = P0 + p1 * np.cos(tau)                      # (m,)
            K = W[None, :, :] - load[:, None, None] * S[None, :, :]
            dx = v / om[:, None, None]
            dv = -(K @ x + C[None, :, :] @ v) / om[:, None, None]
            return np.concatenate([dx, dv], axis=1).ravel()

        y0 = np.tile(np.eye(n2), (m, 1, 1)).ravel()
        sol = solve_ivp(rhs, (0.0, 2.0 * np.pi), y0, method="DOP853", rtol=self.rtol, atol=self.atol)
        if not sol.success:
            raise RuntimeError(sol.message)
        phi = sol.y[:, -1].reshape(m, n2, n2)
        return np.log(np.abs(np.linalg.eigvals(phi)).max(axis=1))


def critical(col, om, guess):
    """c(om): the least P1 in [0, P1_MAX] with log rho > 0, bracketed near `guess` (or by
    stepping up from 0 when guess is None), then brentq. None when stable up to P1_MAX."""
    lo = hi = None
    if guess is not None:
        # a few P1 around the previous critical drive, in one integration
        grid = guess * (1.0 + np.array([-3e-2, -1e-2, -3e-3, -1e-3, 1e-3, 3e-3, 1e-2, 3e-2]))
        grid = grid[(grid > 0.0) & (grid <= P1_MAX)]
        g = col.log_rho(np.full(grid.size, om), grid)
        up = np.nonzero(g > 0.0)[0]
        if up.size and up[0] > 0 and np.all(g[: up[0]] <= 0.0):
            lo, hi, glo, ghi = grid[up[0] - 1], grid[up[0]], g[up[0] - 1], g[up[0]]
    if lo is None:
        # stepping up from 0: 48 samples of [0, P1_MAX] in one integration
        grid = np.linspace(0.0, P1_MAX, 49)[1:]
        g = col.log_rho(np.full(grid.size, om), grid)
        up = np.nonzero(g > 0.0)[0]
        if not up.size:
            return None
        k = up[0]
        if k == 0:
            lo, glo = 0.0, col.log_rho([om], [0.0])[0]
        else:
            lo, glo = grid[k - 1], g[k - 1]
        hi, ghi = grid[k], g[k]
        # the first unstable sample may hide a narrow stable gap below it; refine the
        # sampling between lo and hi to be sure the crossing is the first one
        fine = np.linspace(lo, hi, 9)[1:-1]
        gf = col.log_rho(np.full(fine.size, om), fine)
        upf = np.nonzero(gf > 0.0)[0]
        if upf.size:
            hi, ghi = fine[upf[0]], gf[upf[0]]
            if upf[0] > 0:
                lo, glo = fine[upf[0] - 1], gf[upf[0] - 1]
        else:
            lo, glo = fine[-1], gf[-1]
    assert glo <= 0.0 < ghi
    f = lambda p: col.log_rho([om], [p])[0]
    return brentq(f, lo, hi, xtol=ROOT_XTOL, rtol=4.0 * np.finfo(float).eps, maxiter=200)


def tip(col, om_hint):
    """The least c(Om) over Om in om_hint*(1 +- OM_WINDOW): (Om, P1)."""
    state = {"guess": None}

    def c(om):
        value = critical(col, om, state["guess"])
        if value is None:
            return 10.0 * P1_MAX
        state["guess"] = value
        return value

    c(om_hint)
    res = minimize_scalar(c, bounds=(om_hint * (1.0 - OM_WINDOW), om_hint * (1.0 + OM_WINDOW)),
                          method="bounded", options={"xatol": OM_XATOL_REL * om_hint, "maxiter": 200})
    om = res.x
    # the critical drive at the minimiser, bracketed afresh
    state["guess"] = None
    p1 = c(om)
    if abs(om - om_hint) > 0.99 * OM_WINDOW * om_hint:
        raise RuntimeError(f"tip at the window's end near Om = {om_hint}")
    return om, p1


def run(rtol, atol):
    col = Column(rtol, atol)
    out = []
    om_error = 0.0
    for (kind, order, i, j, om_hint, p1_hint) in REGIONS:
        start = time.time()
        om, p1 = tip(col, om_hint)
        # confirmation: stable just below, unstable just above
        g = col.log_rho([om, om], [p1 - 1e-9 * p1, p1 + 1e-9 * p1])
        ok = g[0] <= 0.0 < g[1]
        # the minimum: c at Om(1 -+ 1e-4) above c there; its curvature bounds the P1 error of
        # Brent's final Om bracket, a (xatol)^2
        h = 1.0e-4 * om
        side = [critical(col, om - h, p1), critical(col, om + h, p1)]
        ok = ok and min(side) > p1
        curvature = (side[0] + side[1] - 2.0 * p1) / (2.0 * h * h)
        om_error = max(om_error, curvature * (OM_XATOL_REL * om) ** 2 / p1)
        print(f"  rtol {rtol:.0e}: kind {kind} order {order} modes {i} {j}: Om = {om:.10f} P1 = {p1:.12f}"
              f" (hint {om_hint}, {p1_hint}; confirmed {ok}; {time.time() - start:.1f} s)", file=sys.stderr)
        if not ok:
            raise RuntimeError("tip not confirmed")
        out.append((kind, order, i, j, om, p1))
    return out, col.count, om_error


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", default="data/reference/column_tips.dat")
    args = parser.parse_args()
    start = time.time()
    tight, n_tight, om_error = run(1.0e-12, 1.0e-14)
    loose, n_loose, _ = run(1.0e-11, 1.0e-13)
    d_p1 = max(abs(a[5] - b[5]) / a[5] for a, b in zip(tight, loose))
    d_om = max(abs(a[4] - b[4]) / a[4] for a, b in zip(tight, loose))
    elapsed = time.time() - start
    print(f"self-consistency: worst relative difference P1 {d_p1:.1e}, Om {d_om:.1e}; "
          f"P1 error of the Om bracket {om_error:.0e} relative; {n_tight} + {n_loose} monodromies, {elapsed:.0f} s",
          file=sys.stderr)
    with open(args.output, "w") as f:
        f.write("# column_tips.dat: tips of the resonance regions of the damped 3-mode column\n")
        f.write("# (data/scenes/column_regions.nml), the reference of test_regions/column_tips_against_reference.\n")
        f.write("# Made by: python3 data/reference/make_column_tips.py (numpy " + np.__version__ + ", scipy "
                + scipy.__version__ + "; no hillstab code).\n")
        f.write("# Column: x'' + C x' + (W - (P0 + P1 cos(Om t)) S) x = 0, W = diag(1, 16, 81),\n")
        f.write("# S = [1, .3, .1; .3, 4, .4; .1, .4, 9], C = 2 zeta diag(1, 4, 9), zeta = 0.01, P0 = 0.3.\n")
        f.write("# Monodromy: scipy solve_ivp DOP853 on the 36-component fundamental matrix over one period,\n")
        f.write("# rtol 1e-12, atol 1e-14; unstable iff max|eig| > 1. c(Om): least P1 in [0, 1.5] unstable,\n")
        f.write(f"# bracketed by sampling, brentq to {ROOT_XTOL:.0e} absolute; tip: minimize_scalar (bounded) of c over\n")
        f.write(f"# Om in hint*(1 +- {OM_WINDOW}), xatol {OM_XATOL_REL:.0e} Om; each tip confirmed: stable at P1(1 - 1e-9),\n")
        f.write("# unstable at P1(1 + 1e-9), and c at Om(1 -+ 1e-4) above P1; the curvature of c there puts the\n")
        f.write(f"# P1 error of the final Om bracket below {om_error:.0e} relative.\n")
        f.write(f"# Self-consistency (the whole search again at rtol 1e-11, atol 1e-13): worst relative difference\n")
        f.write(f"# P1 {d_p1:.1e}, Om {d_om:.1e}. {n_tight} + {n_loose} monodromies, {elapsed:.0f} s.\n")
        f.write("# columns: kind order mode_i mode_j Om P1\n")
        for (kind, order, i, j, om, p1) in tight:
            f.write(f"{kind} {order} {i} {j} {om:.12f} {p1:.14f}\n")


if __name__ == "__main__":
    main()
