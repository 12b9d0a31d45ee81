"""Transition curves |S| = 2 by Hill's method, and Mathieu's characteristic values.

`transition_curves` gives, at each α of an array, every curve crossing a β window (the
boundaries of the stability chart), computed by the library's banded eigenproblems in
parallel over α. `critical_drives` gives, at one β, every α of a range where the stability
changes: the least drive that destabilises (or stabilises) the equation, and every later
change. `mathieu_a` and `mathieu_b` are the characteristic values a_m(q), b_m(q)
of Mathieu's equation y'' + (a − 2q cos 2v) y = 0 in the standard form (the Mathieu
model's curves: a = 4β/π², q = 2α/π²), each found as the curve of its order and parity,
so they follow their own branch at any q (no jump between branches at large q).
"""
import math

import numpy as np

from . import _capi
from ._capi import lib, check
from .floquet import Result, _indexed
from .models import as_model


class CriticalDrives:
    """The changes of stability at a fixed β, ascending in α: ``alpha``, ``alpha_error`` (the
    bound of its error; along β: ``beta``, ``beta_error``; either way ``value``,
    ``value_error`` and ``axis``), ``side`` (+1: S reaches +2 cosh(εP/2) there, −1: −2 cosh(εP/2)),
    ``direction`` (+1: stable below, unstable above; −1 the reverse) and ``status`` (0
    confirmed by the verdicts on both sides, 2 not), each an array."""

    def __init__(self, **arrays):
        for key, value in arrays.items():
            setattr(self, key, value)

    def __len__(self):
        return self.value.size

    def __repr__(self):
        return "<hillstab critical drives: {} change(s) at {} = {}>".format(
            self.value.size, self.axis, ", ".join("{:.8g}".format(a) for a in self.value))


def critical_drives(beta, alpha, model="elastic", epsilon=0.0, method="auto", tolerance=1e-10, n_samples=400):
    """Every α of the range ``alpha = (alpha_min, alpha_max)`` where the stability of the
    model's equation at ``beta`` (damping ``epsilon``) changes, as a `CriticalDrives`; or,
    with ``beta`` a range and ``alpha`` a number, every β of that range at the fixed α
    (an `Equation`'s drive amplitude at one frequency: ``critical_drives((0, 0.1), 314.16,
    model=kapitza)``; each point's damping is then the equation's, ``epsilon`` 0).

    The signed distance |S| − 2 cosh(εP/2) is sampled at ``n_samples`` values (S by
    ``method`` to ``tolerance``); each sign change is refined to ``tolerance`` relative to
    max(1, |value|), or to S's own error, and confirmed by the verdicts on both sides; a
    region narrower than the samples is found where |S| comes within 5 % of the threshold at
    a neighbouring sample (more samples find narrower ones). For the Kapitza pendulum at 50 Hz
    (l = 0.2 m, κ = 0.2 1/s; Mathieu's model with β = −gπ²/(lω²), ε = κπ/ω, α = Aπ²/l) the
    first change is the least stabilising amplitude, 6.30680 mm:

    >>> import math
    >>> w = 2 * math.pi * 50
    >>> d = critical_drives(-9.81 * math.pi**2 / (0.2 * w**2), (0.0, 0.1 * math.pi**2 / 0.2), model="mathieu",
    ...                     epsilon=0.2 * math.pi / w, tolerance=1e-12)
    >>> d.alpha[0] * 0.2 / math.pi**2
    0.0063068...

    The result's ``value`` and ``value_error`` are the coordinate searched and its bound,
    also as ``alpha``/``alpha_error`` or ``beta``/``beta_error`` (and, for an `Equation`, by
    the axis' parameter, e.g. ``d.A``).
    """
    if method not in _capi.METHODS:
        raise ValueError("method: unknown method '{}' (expected {})".format(method, ", ".join(_capi.METHODS)))
    along_beta = isinstance(beta, (tuple, list, np.ndarray)) and not isinstance(alpha, (tuple, list, np.ndarray))
    name, fixed_name = ("beta", "alpha") if along_beta else ("alpha", "beta")
    span, fixed = (beta, alpha) if along_beta else (alpha, beta)
    try:
        low, high = span
    except (TypeError, ValueError):
        raise ValueError("{0}: must be ({0}_min, {0}_max)".format(name)) from None
    if isinstance(n_samples, (bool, np.bool_)) or not isinstance(n_samples, (int, np.integer)):
        raise TypeError("n_samples: must be an int, got {}".format(type(n_samples).__name__))
    model = as_model(model)
    capacity = 64
    while True:
        values = np.zeros(capacity)
        errors = np.zeros(capacity)
        sides = np.zeros(capacity, dtype=_capi.INT)
        directions = np.zeros(capacity, dtype=_capi.INT)
        statuses = np.zeros(capacity, dtype=_capi.INT)
        count = np.zeros(1, dtype=np.uintp)
        check(lib.hillstab_critical_drives_along(model.handle, 2 if along_beta else 1,
                                                 _capi.real_number(fixed_name, fixed),
                                                 _capi.real_number(name, low), _capi.real_number(name, high),
                                                 _capi.real_number("epsilon", epsilon), _capi.METHODS[method],
                                                 _capi.real_number("tolerance", tolerance), int(n_samples), capacity,
                                                 _capi.doubles(values), _capi.doubles(errors), _capi.ints(sides),
                                                 _capi.ints(directions), _capi.ints(statuses), _capi.sizes(count)))
        found = int(count[0])
        if found <= capacity:
            break
        capacity = found
    arrays = dict(value=values[:found].copy(), value_error=errors[:found].copy(), side=sides[:found].astype(np.int8),
                  direction=directions[:found].astype(np.int8), status=statuses[:found].astype(np.int8))
    arrays[name] = arrays["value"]
    arrays[name + "_error"] = arrays["value_error"]
    axes = getattr(model, "axes", None)
    if axes:
        arrays.setdefault(axes[1] if along_beta else axes[0], arrays["value"])
    return CriticalDrives(axis=name, **arrays)


class Curves:
    """The transition curves at each α: flat arrays over every curve found (``alpha``,
    ``beta``, ``order`` n, ``parity`` +1 for a_n / −1 for b_n, ``trace_sign`` S = ±2 on it,
    ``error_bound`` of β, ``coexistent`` for a tongue of zero width, ``index`` of its α),
    ``count`` per α and ``status`` per α (2 where Hill's method failed)."""

    def __init__(self, **arrays):
        for key, value in arrays.items():
            setattr(self, key, value)

    def at(self, i):
        """The curves at the i-th α, as a dict of arrays."""
        mask = self.index == i
        return {name: getattr(self, name)[mask] for name in
                ("beta", "order", "parity", "trace_sign", "error_bound", "coexistent")}

    def __repr__(self):
        return "<hillstab curves: {} points at {} alpha values>".format(self.beta.size, self.count.size)


def transition_curves(alpha, beta_min, beta_max, model="elastic", tolerance=1e-11, threads=0):
    """The curves |S| = 2 crossing [beta_min, beta_max] at each α (a scalar or an array),
    by Hill's method (models elastic and mathieu). `tolerance` is the convergence target
    on β, relative to max(1, |β|). Returns `Curves`; bad input raises ValueError with the
    library's message.

    >>> c = transition_curves(5.0, -2.0, 40.0)
    >>> c.beta, c.order, c.parity
    """
    model = as_model(model)
    alphas = _capi.as_doubles(np.atleast_1d(alpha).ravel())
    n = alphas.size
    capacity = 32
    while True:
        beta = np.zeros((n, capacity))
        bound = np.zeros((n, capacity))
        order, parity, sign, coexistent = (np.zeros((n, capacity), dtype=_capi.INT) for _ in range(4))
        count = np.zeros(n, dtype=_capi.SIZE)
        status = np.zeros(n, dtype=_capi.INT)
        check(lib.hillstab_transition_curves(
            model.handle, n, _capi.doubles(alphas), float(beta_min), float(beta_max), float(tolerance), capacity,
            int(threads), _capi.doubles(beta), _capi.ints(order), _capi.ints(parity), _capi.ints(sign),
            _capi.doubles(bound), _capi.ints(coexistent), _capi.sizes(count), _capi.ints(status)),
            known=_indexed("alpha", (alphas,), beta_min, beta_max, tolerance))
        if n == 0 or int(count.max()) <= capacity:
            break
        capacity = int(count.max())
    mask = np.arange(capacity)[None, :] < count.astype(np.int64)[:, None]
    index = np.broadcast_to(np.arange(n)[:, None], (n, capacity))[mask]
    return Curves(alpha=alphas[index], beta=beta[mask], order=order[mask].astype(int),
                  parity=parity[mask].astype(int), trace_sign=sign[mask].astype(int), error_bound=bound[mask],
                  coexistent=coexistent[mask].astype(bool), index=index, count=count.astype(int),
                  status=status.astype(np.int8))


def _characteristic(m, q, parity, tolerance, threads):
    m = int(m)
    if m < 0 or (parity < 0 and m < 1):
        raise ValueError("order m must be >= {} for {}, got {}".format(0 if parity > 0 else 1,
                                                                        "a_m" if parity > 0 else "b_m", m))
    q = np.asarray(q, dtype=np.float64)
    flat = q.ravel()
    result = np.full(flat.shape, np.nan)
    if flat.size == 0:
        return result.reshape(q.shape)
    if not np.all(np.isfinite(flat)):
        raise ValueError("q must be finite")
    quarter = math.pi ** 2 / 4.0
    # m^2 - 2|q| <= a_m(q), b_m(q) <= m^2 + 2|q|: the window of the m-th curve
    spread = 2.0 * float(np.max(np.abs(flat))) + 1.0
    curves = transition_curves(flat * (2.0 * quarter), quarter * (m * m - spread), quarter * (m * m + spread),
                               model="mathieu", tolerance=tolerance, threads=threads)
    hit = (curves.order == m) & (curves.parity == parity)
    found = np.zeros(flat.shape, dtype=int)
    np.add.at(found, curves.index[hit], 1)
    if np.any(curves.status == _capi.STATUS_FAILED) or np.any(found != 1):
        bad = int(np.argmax((found != 1) | (curves.status == _capi.STATUS_FAILED)))
        raise _capi.HillstabError("{}_{}(q = {!r}) not found by Hill's method".format(
            "a" if parity > 0 else "b", m, flat[bad]), _capi.ERR_INTEGRATION)
    result[curves.index[hit]] = curves.beta[hit] / quarter
    return result.reshape(q.shape)


def mathieu_a(m, q, tolerance=1e-13, threads=0):
    """The characteristic value a_m(q) of the even Mathieu functions ce_m (scipy's
    ``mathieu_a``), q a scalar or an array.

    >>> mathieu_a(0, 1.0)      # -0.455138604107...
    """
    return _characteristic(m, q, 1, tolerance, threads)


def mathieu_b(m, q, tolerance=1e-13, threads=0):
    """The characteristic value b_m(q) of the odd Mathieu functions se_m (m >= 1; scipy's
    ``mathieu_b``), q a scalar or an array.

    >>> mathieu_b(1, 1.0)      # -0.110248816992...
    """
    return _characteristic(m, q, -1, tolerance, threads)
