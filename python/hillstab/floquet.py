"""Floquet data of many points and charts over grids, computed inside the library.

`floquet` takes arrays of (α, β) (and damping ε), `chart` a grid; both return numpy
arrays of the values a chart or points file of the command line holds (equal to its
binary files to the bit for the same model, method and tolerance) and a per-point
`status`: 0 ok, 1 round-off limited (the best value double precision allows), 2 failed
(the files' placeholders: S 0, stable −1, lambda_max −1, log10_abs_S −999). `trace`
returns S alone and raises when a point failed.

One vocabulary: the values are named as the columns of the command line's chart and
points files (and as `read_output` returns them), and as the C API's HILLSTAB_VALUE_S,
_MU, … The two values no file holds are named in the same style (``log_abs_S``) or by
what they are (``log_moduli``). The earlier names ``trace``, ``log_abs_trace``,
``log10_abs_trace`` and ``exponent`` are aliases for this release: ``values=("trace",)``
and ``result.trace`` still work and give the same arrays (`ALIASES`).

Values (``values=`` chooses them; only what they need is computed). With damping ε > 0
(x'' + ε x' + Q x = 0) the values are of two functions, as in the files: those marked χ
are of χ = e^{ετ/2} x (eq. (47), χ'' + (Q − ε²/4) χ = 0), those marked x of x itself,
which includes the decay e^{−ετ/2}: a multiplier of x is e^{−εP/2} times one of χ
(e^{−ε} for P = 2, the period of Q for elastic and mathieu), so where |S₁| < 2,
λ_max = e^{−ε} and μ = −ε/2. Without damping the two are the same.

============== ========= ================ ==============================================
name           of        earlier alias    what it is
============== ========= ================ ==============================================
S              χ         trace            S₁, the trace of χ's one-period monodromy,
                                          ±1e300 with ``overflow`` 1 beyond
log_abs_S      χ         log_abs_trace    ln|S₁| (exact also where S overflows; no column)
log10_abs_S    χ         log10_abs_trace  log₁₀|S₁| (at least −300)
overflow       χ                          1 where |S₁| passed 1e300 (S clamped)
error_estimate χ                          the method's estimate of |error of S|/max(1, |S|)
                                          (−1: none)
stable         x                          1, 0, or 0.5 when marginal (|S| within its error
                                          bound of the threshold): the verdict on x
stable_paper   χ                          the paper's |S₁| ≤ 2 (1 or 0)
lambda_max     x                          the largest multiplier modulus of x over a period
log_moduli     x                          ln|λ| of both multipliers of x (largest first;
                                          a last axis of 2; no column)
mu             x         exponent         μ = ln λ_max / P, per unit τ (not per second)
kind           x                          where λ_max leaves the unit circle: 0 stable, 1 at
                                          +1, 2 at −1, 4 damped, 5 undecided (a system's codes)
argument       x                          arg λ_max/π: 0 at +1, 1 at −1, the rotation number
                                          arccos(S/2)/π where |S| < 2
============== ========= ================ ==============================================

``stable`` and ``stable_paper`` alone are verdicts only, screened (fastest).
"""
import math
import re
import warnings

import numpy as np

from . import _capi, _progress
from ._capi import lib, check, real_number, real_array
from .errors import HillstabError, HillstabWarning
from .models import as_model

#: every value `floquet` and `chart` can return, by the files' names
ALL_VALUES = ("S", "log_abs_S", "log10_abs_S", "overflow", "error_estimate", "stable",
              "stable_paper", "lambda_max", "log_moduli", "mu", "kind", "argument")
#: the earlier names, aliases for this release: earlier name -> the files' name
ALIASES = {"trace": "S", "log_abs_trace": "log_abs_S", "log10_abs_trace": "log10_abs_S", "exponent": "mu"}
#: the index of each value in the library's output (HILLSTAB_VALUE_*), by its name
_INDEX = {"S": "trace", "log_abs_S": "log_abs_trace", "log10_abs_S": "log10_abs_trace", "mu": "exponent"}
_VERDICTS = {"stable", "stable_paper", "kind"}
_GROWTH = _VERDICTS | {"lambda_max", "log_moduli", "mu", "argument"}


def _canonical(values):
    """The values asked for by the files' names (an earlier name is its alias), each once, in order."""
    if isinstance(values, str):
        values = (values,)
    names = []
    for name in values:
        name = ALIASES.get(name, name)
        if name not in names:
            names.append(name)
    return tuple(names)


def _need(values):
    names = set(values)
    unknown = names - set(ALL_VALUES)
    if unknown:
        raise ValueError("unknown value(s) {} (expected some of {})".format(
            ", ".join(sorted(unknown)), ", ".join(ALL_VALUES)))
    if not names:
        raise ValueError("no value asked for")
    if names <= _VERDICTS:
        return _capi.NEED_VERDICT
    if names <= _GROWTH:
        return _capi.NEED_GROWTH
    return _capi.NEED_TRACE


def _method(method, n_segments, sampling):
    if method not in _capi.METHODS:
        raise ValueError("unknown method '{}' (expected {})".format(method, ", ".join(_capi.METHODS)))
    if sampling not in _capi.SAMPLINGS:
        raise ValueError("unknown sampling '{}' (expected {})".format(sampling, ", ".join(_capi.SAMPLINGS)))
    return _capi.METHODS[method], int(n_segments), _capi.SAMPLINGS[sampling]


class Result:
    """Arrays of values by name (attributes and ``result["name"]``), with ``status``.

    The names are the files' columns (``S``, ``mu``, ``log10_abs_S``, …; module doc's
    table); the earlier ``trace``, ``log_abs_trace``, ``log10_abs_trace`` and ``exponent``
    are aliases for this release and give the same arrays. Only the values asked for are
    present: the others were not computed to the tolerance and asking for them raises
    AttributeError. With damping ε, ``S`` is S₁ of χ = e^{ετ/2} x while ``lambda_max``,
    ``log_moduli`` and ``mu`` are of x (a factor e^{−ε} per period 2 between their
    multipliers; module doc). A chart's result has the axes ``alpha`` and ``beta`` too.
    """

    def __init__(self, arrays, status, names, extra=None):
        self._arrays = arrays
        #: per point: 0 ok, 1 round-off limited, 2 failed (placeholders)
        self.status = status
        self._names = tuple(names)
        for key, value in (extra or {}).items():
            setattr(self, key, value)

    @property
    def names(self):
        """The values present, by the files' names."""
        return self._names

    @property
    def ok(self):
        """True where the point was computed (status 0 or 1)."""
        return self.status < _capi.STATUS_FAILED

    def __getattr__(self, name):
        arrays = self.__dict__.get("_arrays", {})
        name = ALIASES.get(name, name)
        if name in arrays:
            return arrays[name]
        if name in ALL_VALUES:
            raise AttributeError("'{}' was not asked for (values={}): it was not computed to the tolerance"
                                 .format(name, self.__dict__.get("_names")))
        raise AttributeError(name)

    def __getitem__(self, name):
        return getattr(self, name)

    def __repr__(self):
        return "<hillstab result: {} points, values {}>".format(self.status.size, ", ".join(self._names))


def _unpack(values, names, shape):
    arrays = {}
    for name in names:
        if name == "log_moduli":
            arrays[name] = np.stack([values[..., _capi.VALUES.index("log_modulus_max")],
                                     values[..., _capi.VALUES.index("log_modulus_min")]], axis=-1
                                    ).reshape(shape + (2,))
        else:
            arrays[name] = values[..., _capi.VALUES.index(_INDEX.get(name, name))].reshape(shape).copy()
    return arrays


#: π² as the library has it (pi*pi in double precision): the elastic model's bound of α and β
PI2 = math.pi * math.pi


def _warn(status, where, stacklevel=3):
    failed = int(np.count_nonzero(status == _capi.STATUS_FAILED))
    limited = int(np.count_nonzero(status == _capi.STATUS_ROUNDOFF))
    if failed:
        first = where(np.argmax(status.ravel() == _capi.STATUS_FAILED))
        warnings.warn("{} of {} point(s) failed (status 2, placeholders), first at {}".format(
            failed, status.size, first), HillstabWarning, stacklevel=stacklevel)
    if limited:
        first = where(np.argmax(status.ravel() == _capi.STATUS_ROUNDOFF))
        warnings.warn("{} of {} point(s) reached only the round-off level of double precision, not the "
                      "tolerance (status 1), first at {}".format(limited, status.size, first),
                      HillstabWarning, stacklevel=stacklevel)


def in_physical_domain(alpha, beta):
    """True where (α, β) describes a real spring pendulum, 0 ≤ α < π² and 0 ≤ β < π² (the
    library's ``in_physical_domain``, the column ``physical`` of its files)."""
    alpha = np.asarray(alpha, dtype=np.float64)
    beta = np.asarray(beta, dtype=np.float64)
    return (alpha >= 0.0) & (alpha < PI2) & (beta >= 0.0) & (beta < PI2)


def _warn_default_model(alpha, beta, stacklevel):
    """The warning of a call that did not name its model, when some points lie outside the
    elastic pendulum's physical domain (β < 0 or β ≥ π² there: α outside [0, π²) is refused)."""
    outside = ~in_physical_domain(alpha, beta)
    count = int(np.count_nonzero(outside))
    if not count:
        return
    k = int(np.argmax(outside.ravel()))
    a, b = float(np.ravel(alpha)[k]), float(np.ravel(beta)[k])
    why = []
    if not a >= 0.0:
        why.append("alpha < 0")
    elif not a < PI2:
        why.append("alpha >= pi**2")
    if not b >= 0.0:
        why.append("beta < 0")
    elif not b < PI2:
        why.append("beta >= pi**2")
    warnings.warn(
        "no model given: the default, the elastic pendulum (model='elastic'), was used, but {} of {} point(s) lie "
        "outside its physical domain 0 <= alpha < pi**2, 0 <= beta < pi**2 = {!r} (first at alpha = {!r}, "
        "beta = {!r}: {}), where it describes no spring pendulum; for Mathieu's equation pass model='mathieu' "
        "(hillstab.model_names() lists the models), or model='elastic' to say it is meant".format(
            count, outside.size, PI2, a, b, ", ".join(why)), HillstabWarning, stacklevel=stacklevel)


def _shift(word, offset):
    """A message fix: the index after `word` ("point 3 (", "row 0 (") moved by `offset` (the
    index of the chunk's first point or row within the whole call), or mapped by it when it
    is a function."""
    pattern = re.compile(r"^({} )(\d+)( \()".format(word))
    move = offset if callable(offset) else (lambda k: k + offset)
    return lambda message: pattern.sub(lambda m: m.group(1) + str(move(int(m.group(2)))) + m.group(3),
                                       message, count=1)


def _indexed(word, columns, *scalars):
    """`known` for check: the values of the point (or row) a message names, and the scalars."""
    pattern = re.compile(r"^{} (\d+) \(".format(word))

    def known(message):
        match = pattern.match(message)
        values = list(scalars)
        if match:
            k = int(match.group(1))
            values += [float(c[k]) for c in columns if k < c.size]
        return values
    return known


def floquet(alpha, beta, model=None, epsilon=0.0, method="auto", tolerance=1e-10, n_segments=2,
            sampling="endpoint", values=ALL_VALUES, threads=0, progress=None, chunk=None):
    """Floquet data of the points (α, β) — arrays of any shape, broadcast together with
    the damping ε — as the command line's task ``points`` computes them.

    Parameters: ``model`` a Model or a name (``"elastic"``, ``"mathieu"``, `model_names`);
    when it is not given the elastic pendulum is used, with a HillstabWarning if some
    points lie outside its physical domain 0 ≤ α < π², 0 ≤ β < π² (Mathieu's equation is
    ``model="mathieu"``); ``method`` one of auto, formula, segments, magnus4, magnus6, rk,
    gsl; ``tolerance`` the target of |error of S|/max(1, |S|) (exact methods);
    ``n_segments``, ``sampling`` (segments); ``values`` the values wanted, by the files'
    names (module doc's table; the earlier names are aliases; verdicts only:
    ``values=("stable",)``); ``threads`` the library's threads (0: OpenMP's
    default, ``OMP_NUM_THREADS``); ``progress`` a callable ``progress(done, total)`` called
    after each chunk of ``chunk`` points (default about 1 % of them, at least 1000), or True
    for a bar (tqdm when installed, else a line on stderr): the points are then computed
    chunk after chunk, with the same numbers to the bit (each point is computed alone).

    Returns a `Result`: one array per value, of the points' shape (``log_moduli`` with a
    last axis of 2), and ``status``. With damping, ``S`` is S₁ of χ = e^{ετ/2} x and
    ``lambda_max``, ``mu`` are of x (module doc). Bad input raises ValueError with the
    library's message (numbers in Python's format); points whose computation failed have
    status 2 (a HillstabWarning says so).

    >>> r = floquet([3.7, 9.0], 2.47, model="elastic")
    >>> r.stable, r.mu
    """
    return _floquet(alpha, beta, model, epsilon, method, tolerance, n_segments, sampling, values, threads,
                    progress, chunk, stacklevel=4)


def _floquet(alpha, beta, model, epsilon, method, tolerance, n_segments, sampling, values, threads, progress,
             chunk, stacklevel):
    values = _canonical(values)
    need = _need(values)
    explicit = model is not None
    model = as_model(model if explicit else "elastic")
    kind, pieces, samples = _method(method, n_segments, sampling)
    a, b, e = np.broadcast_arrays(real_array("alpha", alpha), real_array("beta", beta),
                                  real_array("epsilon", epsilon))
    shape = a.shape
    a, b, e = (_capi.as_doubles(x.ravel()) for x in (a, b, e))
    n = a.size
    tolerance = real_number("tolerance", tolerance)
    out = np.empty((n, _capi.VALUE_COUNT))
    status = np.empty(n, dtype=_capi.INT)
    paper = 1 if "stable_paper" in values else 0
    report = _progress.Progress(progress, n, "points")
    parts = _progress.chunks(n, _progress.chunk_size(chunk, n, 1000)) if report.active else []
    parts = parts or [(0, n)]
    try:
        for start, stop in parts:
            code = lib.hillstab_points(model.handle, stop - start, _capi.doubles(a[start:]), _capi.doubles(b[start:]),
                                       _capi.doubles(e[start:]), kind, pieces, samples, tolerance, need, paper,
                                       int(threads), _capi.doubles(out[start:]), _capi.ints(status[start:]))
            check(code, known=_indexed("point", (a[start:], b[start:], e[start:]), tolerance),
                  fix=_shift("point", start))
            if report.active:
                report.update(stop)
    finally:
        report.close()
    _warn(status, lambda k: "alpha = {!r}, beta = {!r}".format(float(a[k]), float(b[k])), stacklevel)
    if not explicit:
        _warn_default_model(a, b, stacklevel)
    return Result(_unpack(out, values, shape), status.reshape(shape).astype(np.int8), values)


def trace(alpha, beta, model=None, epsilon=0.0, method="auto", tolerance=1e-10, n_segments=2,
          sampling="endpoint", threads=0):
    """S, the trace of the one-period monodromy, at the points (α, β) (arrays broadcast
    together with ε; ±1e300 where |S| overflows): `floquet`'s ``S``, but a point that
    failed raises HillstabError (a bare array has no status to carry it). With damping ε it
    is S₁, the trace of χ = e^{ετ/2} x, not of x (`floquet`). Without ``model`` the elastic
    pendulum, with a HillstabWarning for points outside its physical domain (`floquet`).

    >>> trace(3.7, 2.47, model="elastic")
    array(...)
    """
    result = _floquet(alpha, beta, model, epsilon, method, tolerance, n_segments, sampling, ("S",), threads,
                      None, None, stacklevel=4)
    if np.any(result.status == _capi.STATUS_FAILED):
        raise HillstabError("{} point(s) failed; use floquet() for per-point status".format(
            int(np.count_nonzero(result.status == _capi.STATUS_FAILED))), _capi.ERR_INTEGRATION)
    return result.S


def chart(alpha, beta, model=None, epsilon=0.0, method="auto", tolerance=1e-10, n_segments=2,
          sampling="endpoint", values=ALL_VALUES, threads=0, progress=None, alpha_scale="linear",
          beta_scale="linear"):
    """The stability chart over a grid, as the command line's task ``chart`` computes it.

    ``alpha`` and ``beta`` are (first, last, count) with both ends included, the grid of
    ``&chart alpha_min, alpha_max, n_alpha`` and ``beta_*``: equally spaced, or geometric
    with ``alpha_scale="log"`` (``beta_scale``; the first value > 0), as ``&chart
    alpha_scale``, the same values to the bit. The other parameters as in
    `floquet` (without ``model``: the elastic pendulum, with a HillstabWarning when the grid
    leaves its physical domain); ``values=("stable",)`` computes the verdicts alone (a
    screening pass settles most points: several times faster). ``progress`` (a callable
    ``progress(done, total)`` of rows, or True for a bar) reports the rows as they are done;
    the chart is still one call into the library (run in a worker thread), so its numbers
    are those of a call without progress to the bit.

    Returns a `Result` with 2-D arrays ``[i_alpha, i_beta]`` per value, ``status`` and the
    axes ``alpha`` (n_alpha,) and ``beta`` (n_beta,) — for matplotlib,
    ``pcolormesh(c.alpha, c.beta, c.stable.T)``. With damping, ``S`` is S₁ of
    χ = e^{ετ/2} x and ``lambda_max``, ``mu`` are of x (module doc). `read_output`
    gives a chart file in the same shape (``Output.grid``).
    """
    values = _canonical(values)
    need = _need(values)
    explicit = model is not None
    model = as_model(model if explicit else "elastic")
    kind, pieces, samples = _method(method, n_segments, sampling)
    alpha_min, alpha_max, n_alpha = _axis(alpha, "alpha")
    beta_min, beta_max, n_beta = _axis(beta, "beta")
    scales = _scale(alpha_scale, "alpha_scale"), _scale(beta_scale, "beta_scale")
    epsilon = real_number("epsilon", epsilon)
    tolerance = real_number("tolerance", tolerance)
    alphas = np.empty(n_alpha)
    betas = np.empty(n_beta)
    out = np.empty((n_alpha, n_beta, _capi.VALUE_COUNT))
    status = np.empty((n_alpha, n_beta), dtype=_capi.INT)
    paper = 1 if "stable_paper" in values else 0

    def call():
        check(lib.hillstab_chart_scaled(model.handle, alpha_min, alpha_max, n_alpha, scales[0], beta_min, beta_max,
                                        n_beta, scales[1], epsilon, kind, pieces, samples, tolerance, need, paper,
                                        int(threads), _capi.doubles(alphas), _capi.doubles(betas),
                                        _capi.doubles(out), _capi.ints(status)),
              known=(epsilon, tolerance, alpha_min, alpha_max, beta_min, beta_max))

    report = _progress.Progress(progress, n_alpha, "rows")
    try:
        if report.active:
            _progress.watch(call, status, report)
        else:
            call()
    finally:
        report.close()
    _warn(status, lambda k: "alpha = {!r}, beta = {!r}".format(float(alphas[k // n_beta]), float(betas[k % n_beta])))
    if not explicit:
        _warn_default_model(*np.broadcast_arrays(alphas[:, np.newaxis], betas[np.newaxis, :]), stacklevel=3)
    extra = {"alpha": alphas, "beta": betas}
    axes = getattr(model, "axes", None)
    if axes:
        # an equation's axes by their parameters' names too
        extra.update({axes[0]: alphas, axes[1]: betas})
    return Result(_unpack(out, values, (n_alpha, n_beta)), status.astype(np.int8), values, extra=extra)


# the scales of a chart's axis (HILLSTAB_SCALE_*)
_SCALES = {"linear": 0, "log": 1}


def _scale(scale, name):
    """The code of an axis scale, 'linear' or 'log' (any case); ValueError naming the
    argument for anything else."""
    if isinstance(scale, str) and scale.strip().lower() in _SCALES:
        return _SCALES[scale.strip().lower()]
    raise ValueError("{} must be 'linear' or 'log', got {!r}".format(name, scale))


def _axis(axis, name):
    try:
        first, last, count = axis
    except (TypeError, ValueError):
        raise ValueError("{} must be (first, last, count)".format(name)) from None
    if int(count) != count or count < 1:
        raise ValueError("{}: the count must be a whole number >= 1, got {!r}".format(name, count))
    return real_number(name, first), real_number(name, last), int(count)
