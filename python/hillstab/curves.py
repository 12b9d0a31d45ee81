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
import ctypes
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


#: HILLSTAB_REGION_*: the kinds of resonance regions (2ν_i = k, ν_i + ν_j = k, |ν_i − ν_j| = k;
#: unassigned: unstable at the top drive outside every predicted region)
REGION_UNASSIGNED, REGION_SIMPLE, REGION_SUM, REGION_DIFFERENCE = 0, 1, 2, 3
#: HILLSTAB_REGION_*: the statuses of a region's tip
REGION_FOUND, REGION_CLOSED, REGION_UNCONFIRMED, REGION_OPEN_BELOW, REGION_THEORY, REGION_SAME_SIGNATURE = 0, 1, 2, 3, 4, 5
REGION_UNCOVERED = 6
#: the kinds and statuses in words, as the library names them
REGION_KIND_NAMES = {REGION_UNASSIGNED: "unassigned", REGION_SIMPLE: "simple", REGION_SUM: "sum",
                     REGION_DIFFERENCE: "difference"}
REGION_STATUS_NAMES = {REGION_FOUND: "found", REGION_CLOSED: "closed", REGION_UNCONFIRMED: "unconfirmed",
                       REGION_OPEN_BELOW: "open below", REGION_THEORY: "theory",
                       REGION_SAME_SIGNATURE: "same signature", REGION_UNCOVERED: "uncovered"}

_capi._declare("hillstab_regions", ctypes.c_int, _capi._model_p, ctypes.c_int, ctypes.c_double, ctypes.c_double,
               ctypes.c_double, ctypes.c_double, ctypes.c_double, ctypes.c_int, ctypes.c_double, ctypes.c_int,
               ctypes.c_int, ctypes.c_size_t, *([_capi._c_int_p] * 3 + [_capi._c_double_p] * 7 +
                                                [_capi._c_int_p] * 3 + [_capi._c_size_p]))


class Regions:
    """The resonance regions of a driven problem, ascending in their predicted frequency, each
    an entry of these arrays:

    - ``kind`` (`REGION_SIMPLE` 2ν_i = k, `REGION_SUM` ν_i + ν_j = k, `REGION_DIFFERENCE`
      |ν_i − ν_j| = k; in words ``kind_name``), ``order`` k, ``modes`` (i, j), shape (n, 2);
    - ``predicted``: the frequency of the resonance at drive 0, ``window`` (n, 2) the
      frequencies searched for its tip;
    - the tip: ``frequency`` and ``drive`` (the least drive at which the region opens), with
      ``frequency_error`` and ``drive_error``;
    - ``edges`` (n, 2): the frequencies of its edges at the top of the drive range (0 where it
      is not open there), ``clipped`` (n, 2) True where an edge is the window's end;
    - ``status`` (`REGION_FOUND` confirmed on both sides, `REGION_CLOSED` stable up to the top
      drive over its window, `REGION_UNCONFIRMED`, `REGION_OPEN_BELOW` unstable at the bottom
      of the range already, `REGION_THEORY` undamped and constant when undriven: the tip is
      the resonance at drive 0, `REGION_SAME_SIGNATURE` a difference region of two modes of
      equal Krein signature, closed and not searched, `REGION_UNCOVERED` a stretch of the top
      drive unstable outside every region's edges, of kind `REGION_UNASSIGNED`, its edges
      there and its tip not searched; in words ``status_name``) and
      ``evaluations`` (distances computed).

    ``drive_axis`` is 1 (the drive is α, the frequency β) or 2 (the drive is β, the frequency
    α); the tips are also ``alpha`` and ``beta`` accordingly, and for an `Equation` or
    `Equations` by the axes' parameters (``r.h``, ``r.W``).
    """

    def __init__(self, **arrays):
        for key, value in arrays.items():
            setattr(self, key, value)

    def __len__(self):
        return self.kind.size

    def __repr__(self):
        return "<hillstab regions: {} region(s), tips at {}>".format(
            self.kind.size, ", ".join("({:.6g}, {:.6g})".format(f, d) for f, d in zip(self.frequency, self.drive)))


def _drive_axis(drive_axis, default):
    if drive_axis is None:
        return default
    if isinstance(drive_axis, str):
        names = {"alpha": 1, "beta": 2}
        if drive_axis not in names:
            raise ValueError("drive_axis: 1 or 'alpha' (the drive is alpha), 2 or 'beta', got {!r}".format(drive_axis))
        return names[drive_axis]
    if isinstance(drive_axis, (bool, np.bool_)) or not isinstance(drive_axis, (int, np.integer)):
        raise TypeError("drive_axis: must be 1 or 2 (or 'alpha', 'beta'), got {}".format(type(drive_axis).__name__))
    if drive_axis not in (1, 2):
        raise ValueError("drive_axis: 1 (the drive is alpha) or 2 (the drive is beta), got {}".format(drive_axis))
    return int(drive_axis)


def _pair(name, value):
    try:
        low, high = value
    except (TypeError, ValueError):
        raise ValueError("{0}: must be a range ({0}_min, {0}_max), got {1!r}".format(name, value)) from None
    return _capi.real_number(name, low), _capi.real_number(name, high)


def _integer(name, value):
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError("{}: must be an int, got {}".format(name, type(value).__name__))
    return int(value)


def _regions(function, handle, axes, frequency, drive, order, drive_axis, epsilon, method_code, tolerance, n_samples):
    """The call of hillstab_regions or hillstab_system_regions (function) and its `Regions`."""
    f_min, f_max = _pair("frequency", frequency)
    d_min, d_max = _pair("drive", drive)
    order = _integer("order", order)
    n_samples = _integer("n_samples", n_samples)
    epsilon = _capi.real_number("epsilon", epsilon)
    tolerance = _capi.real_number("tolerance", tolerance)
    known = (f_min, f_max, d_min, d_max, epsilon, tolerance)

    def named(message):
        # the library's argument names as this function's
        for c_name, name in (("f_min, f_max", "frequency"), ("d_min, d_max", "drive"), ("f_min, d_min", "frequency, "
                             "drive"), ("f_max, d_max", "frequency, drive")):
            message = message.replace(c_name + ":", name + " (" + c_name + "):")
        return message

    capacity = 64
    while True:
        ints = {name: np.zeros(capacity * width, dtype=_capi.INT) for name, width in
                (("kind", 1), ("order", 1), ("modes", 2), ("clipped", 2), ("status", 1), ("evaluations", 1))}
        reals = {name: np.zeros(capacity * width) for name, width in
                 (("predicted", 1), ("window", 2), ("frequency", 1), ("frequency_error", 1), ("drive", 1),
                  ("drive_error", 1), ("edges", 2))}
        count = np.zeros(1, dtype=_capi.SIZE)
        check(function(handle, drive_axis, f_min, f_max, d_min, d_max, epsilon, method_code, tolerance, order,
                       n_samples, capacity, _capi.ints(ints["kind"]), _capi.ints(ints["order"]),
                       _capi.ints(ints["modes"]), _capi.doubles(reals["predicted"]), _capi.doubles(reals["window"]),
                       _capi.doubles(reals["frequency"]), _capi.doubles(reals["frequency_error"]),
                       _capi.doubles(reals["drive"]), _capi.doubles(reals["drive_error"]),
                       _capi.doubles(reals["edges"]), _capi.ints(ints["clipped"]), _capi.ints(ints["status"]),
                       _capi.ints(ints["evaluations"]), _capi.sizes(count)), known=known, fix=named)
        found = int(count[0])
        if found <= capacity:
            break
        capacity = found
    arrays = {}
    for name, array in list(ints.items()) + list(reals.items()):
        width = 2 if name in ("modes", "clipped", "window", "edges") else 1
        part = array[:found * width].copy()
        arrays[name] = part.reshape(found, 2) if width == 2 else part
    for name in ("kind", "order", "modes", "status", "evaluations"):
        arrays[name] = arrays[name].astype(int)
    arrays["clipped"] = arrays["clipped"] != 0
    arrays["kind_name"] = np.array([REGION_KIND_NAMES.get(k, "unknown") for k in arrays["kind"]], dtype=object)
    arrays["status_name"] = np.array([REGION_STATUS_NAMES.get(k, "unknown") for k in arrays["status"]], dtype=object)
    # the tips by the model's coordinates, and by the axes' parameters
    alpha, beta = ("drive", "frequency") if drive_axis == 1 else ("frequency", "drive")
    arrays["alpha"], arrays["beta"] = arrays[alpha], arrays[beta]
    for name, key in zip(axes or (), ("alpha", "beta")):
        if name and name not in arrays:
            arrays[name] = arrays[key]
    return Regions(drive_axis=drive_axis, **arrays)


def regions(model, frequency, drive, order=2, drive_axis=None, epsilon=0.0, method="auto", tolerance=1e-10,
            n_samples=32):
    """The resonance regions of a driven model over ``frequency = (f_min, f_max)``, and the tip
    of each — the least drive of ``drive = (d_min, d_max)`` at which it opens, and the
    frequency there — as `Regions`.

    From the natural frequencies ν_i(f) of the undriven equation (fractions of the drive
    frequency) every resonance of order k = 1 … ``order`` (at most 8) is predicted: simple
    (2ν_i = k), sum (ν_i + ν_j = k) and difference (|ν_i − ν_j| = k) — a scalar equation
    has the simple ones only; each region's tip is then searched in the window between its
    neighbours (S by ``method`` to ``tolerance``, also the target of the tip relative to
    max(1, |x|); ``n_samples`` drives sampled for a first root), with its edges at the top
    drive and a status (`Regions`).

    ``model`` is a `Model`, a model's name, an `Equation`, or a `System` or `Equations`
    (their `System.regions`). ``drive_axis`` says which coordinate is the drive: 1 (or
    ``"alpha"``: the drive is α and the frequency β) or 2 (``"beta"``: the drive is β and
    the frequency α). Its default is 2 for an `Equation` (its α the drive frequency, its β an
    amplitude: ``frequency`` is then a range of its α parameter, ``drive`` of its β) and 1
    for the built-in models by name (``"mathieu"``, ``"elastic"``: α is the drive amplitude,
    β the frequency-like coordinate). ``epsilon`` is the damping (0 for an `Equation`, which
    carries its own).

    The damped Mathieu equation x'' + 2ζx' + (1 + h cos Wt) x = 0: its principal region's
    tip lies at W ≈ 2, h ≈ 4ζ:

    >>> e = Equation("1 + h*cos(W*t)", frequency="W", damping="2*zeta",
    ...              parameters={"zeta": 0.01, "h": 0.0, "W": 2.0}, alpha="W", beta="h")
    >>> r = regions(e, frequency=(0.5, 3.0), drive=(0.0, 0.5), order=3)
    >>> r.order, r.W, r.h          # the tips, also r.frequency, r.drive

    Bad input raises ValueError (TypeError for an argument of the wrong type) naming the
    argument.
    """
    from .system import System
    if isinstance(model, System):
        return model.regions(frequency, drive, order=order, drive_axis=drive_axis, epsilon=epsilon, method=method,
                             tolerance=tolerance, n_samples=n_samples)
    if not isinstance(method, str):
        raise TypeError("method: must be a method's name (a str), got {}".format(type(method).__name__))
    if method not in _capi.METHODS:
        raise ValueError("method: unknown method '{}' (expected {})".format(method, ", ".join(_capi.METHODS)))
    model = as_model(model)
    axes = getattr(model, "axes", None)
    default = 2 if axes is not None or model.name == "equation" else 1
    return _regions(lib.hillstab_regions, model.handle, axes, frequency, drive, order, _drive_axis(drive_axis, default),
                    epsilon, _capi.METHODS[method], tolerance, n_samples)


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
