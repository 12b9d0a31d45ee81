#!/usr/bin/env python3
"""High-precision transition values of x'' + (beta + alpha f(tau)) x = 0 for drives f with
several harmonics and sine terms (no even symmetry), the reference of the tests of Hill's
method on the Fourier coefficients (test/curves/test_hill_fourier.f90, `error_bounds_bound`).

Independent of hillstab's code: the Hermitian matrix kappa_k^2 delta_kj - g_(k-j) on the
exponentials e^{i kappa_k tau} (kappa_k = 2 pi k/P periodic, (2k+1) pi/P antiperiodic) in
mpmath at 40 digits, its eigenvalues by mpmath's eighe, at the truncations N = 24 and N = 32
(k = -N ... N); the table keeps the second and, as ref_error, the difference of the two.

Run from the repository root: python3 data/reference/make_fourier_reference.py
writes data/reference/fourier_set.dat (a minute on one core).
Columns: model alpha kind(+2/-2) rank(1 = lowest of its kind) beta ref_error
"""
import mpmath as mp

mp.mp.dps = 40

# the drives of the tests: (period, f0, cosine coefficients, sine coefficients)
MODELS = {
    1: (2, "0.4", ["-1", "0.3", "0.25"], ["0.6", "-0.45", "0.15"]),
    2: (4, "-0.2", ["0.5", "-1", "0", "0.3"], ["0.4", "0", "0.2", "-0.1"]),
}
POINTS = [(1, "3"), (1, "12"), (1, "-2.5"), (2, "2"), (2, "7")]
RANKS = 8


def values(model, alpha, n, anti):
    period, f0, a, b = MODELS[model]
    alpha = mp.mpf(alpha)
    om = 2 * mp.pi / period
    ks = list(range(-n, n)) if anti else list(range(-n, n + 1))

    def g_hat(m):
        if m == 0:
            return alpha * mp.mpf(f0)
        if abs(m) > len(a):
            return mp.mpc(0)
        c, s = alpha * mp.mpf(a[abs(m) - 1]), alpha * mp.mpf(b[abs(m) - 1])
        return (c - 1j * s) / 2 if m > 0 else (c + 1j * s) / 2

    h = mp.matrix(len(ks), len(ks))
    for i, ki in enumerate(ks):
        for j, kj in enumerate(ks):
            v = -g_hat(ki - kj)
            if i == j:
                v += ((ki + (mp.mpf(1) / 2 if anti else 0)) * om) ** 2
            h[i, j] = v
    return sorted(mp.re(e) for e in mp.eighe(h, eigvals_only=True))[:RANKS]


def main():
    lines = ["# fourier_set.dat: transition values of x'' + (beta + alpha f) x = 0, f of the test drives",
             "# (data/reference/make_fourier_reference.py: mpmath, 40 digits, truncations 24 and 32)",
             "# model 1: P = 2, f = 0.4 - cos + 0.3 cos 2 + 0.25 cos 3 + 0.6 sin - 0.45 sin 2 + 0.15 sin 3 (of pi tau)",
             "# model 2: P = 4, f = -0.2 + 0.5 cos - cos 2 + 0.3 cos 4 + 0.4 sin + 0.2 sin 3 - 0.1 sin 4 (of pi tau/2)",
             "# columns: model alpha kind rank beta ref_error"]
    for model, alpha in POINTS:
        for anti in (False, True):
            coarse = values(model, alpha, 24, anti)
            fine = values(model, alpha, 32, anti)
            for rank, (x, y) in enumerate(zip(coarse, fine), start=1):
                lines.append("%d %s %d %d %s %s" % (model, alpha, -2 if anti else 2, rank, mp.nstr(y, 30),
                                                    mp.nstr(abs(x - y), 3)))
    with open("data/reference/fourier_set.dat", "w") as out:
        out.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
