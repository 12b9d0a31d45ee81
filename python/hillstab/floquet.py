"""Floquet data of many points and charts over grids, computed inside the library.

`floquet` takes arrays of (α, β) (and damping ε), `chart` a grid; both return numpy
arrays of the values a chart or points file of the command line holds (equal to its
binary files to the bit for the same model, method and tolerance) and a per-point
`status`: 0 ok, 1 round-off limited (the best value double precision allows), 2 failed
(the files' placeholders: S 0, stable −1, lambda_max −1, log10_abs_trace −999). `trace`
returns S alone and raises when a point failed.

Values (``values=`` chooses them; only what they need is computed):

- ``trace``: S, the trace of the one-period monodromy (S₁ of χ with damping), ±1e300
  with ``overflow`` 1 beyond; ``log_abs_trace`` ln|S|, ``log10_abs_trace`` log₁₀|S| (exact
  also where S overflows); ``error_estimate``, the method's estimate of
  |error of S|/max(1, |S|) (−1: none);
- ``stable`` (1, 0, or 0.5 when marginal: |S| within its error bound of the threshold)
  and ``stable_paper`` (the paper's |S₁| ≤ 2): verdicts only, screened;
- ``lambda_max``, the largest multiplier modulus of x over a period; ``log_moduli``, ln|λ|
  of both multipliers (largest first); ``exponent``, μ = ln λ_max / 2 per unit τ.
"""
import warnings

import numpy as np

from . import _capi
from ._capi import lib, check, real_number, real_array
from .errors import HillstabError, HillstabWarning
from .models import as_model

#: every value `floquet` and `chart` can return
ALL_VALUES = ("trace", "log_abs_trace", "log10_abs_trace", "overflow", "error_estimate", "stable",
              "stable_paper", "lambda_max", "log_moduli", "exponent")
_VERDICTS = {"stable", "stable_paper"}
_GROWTH = _VERDICTS | {"lambda_max", "log_moduli", "exponent"}


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

    Only the values asked for are present: the others were not computed to the tolerance
    and asking for them raises AttributeError.
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
        """The values present."""
        return self._names

    @property
    def ok(self):
        """True where the point was computed (status 0 or 1)."""
        return self.status < _capi.STATUS_FAILED

    def __getattr__(self, name):
        arrays = self.__dict__.get("_arrays", {})
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
            arrays[name] = values[..., _capi.VALUES.index(name)].reshape(shape).copy()
    return arrays


def _warn(status, where):
    failed = int(np.count_nonzero(status == _capi.STATUS_FAILED))
    limited = int(np.count_nonzero(status == _capi.STATUS_ROUNDOFF))
    if failed:
        first = where(np.argmax(status.ravel() == _capi.STATUS_FAILED))
        warnings.warn("{} of {} point(s) failed (status 2, placeholders), first at {}".format(
            failed, status.size, first), HillstabWarning, stacklevel=3)
    if limited:
        first = where(np.argmax(status.ravel() == _capi.STATUS_ROUNDOFF))
        warnings.warn("{} of {} point(s) reached only the round-off level of double precision, not the "
                      "tolerance (status 1), first at {}".format(limited, status.size, first),
                      HillstabWarning, stacklevel=3)


def floquet(alpha, beta, model="elastic", epsilon=0.0, method="auto", tolerance=1e-10, n_segments=2,
            sampling="endpoint", values=ALL_VALUES, threads=0):
    """Floquet data of the points (α, β) — arrays of any shape, broadcast together with
    the damping ε — as the command line's task ``points`` computes them.

    Parameters: ``model`` a Model or a name (``"elastic"``, ``"mathieu"``); ``method`` one
    of auto, formula, segments, magnus4, magnus6, rk, gsl; ``tolerance`` the target of
    |error of S|/max(1, |S|) (exact methods); ``n_segments``, ``sampling`` (segments);
    ``values`` the values wanted (module doc; verdicts only: ``values=("stable",)``);
    ``threads`` the library's threads (0: OpenMP's default, ``OMP_NUM_THREADS``).

    Returns a `Result`: one array per value, of the points' shape (``log_moduli`` with a
    last axis of 2), and ``status``. Bad input raises ValueError with the library's
    message; points whose computation failed have status 2 (a HillstabWarning says so).

    >>> r = floquet([3.7, 9.0], 2.47)
    >>> r.stable, r.exponent
    """
    need = _need(values)
    model = as_model(model)
    kind, pieces, samples = _method(method, n_segments, sampling)
    a, b, e = np.broadcast_arrays(real_array("alpha", alpha), real_array("beta", beta),
                                  real_array("epsilon", epsilon))
    shape = a.shape
    a, b, e = (_capi.as_doubles(x.ravel()) for x in (a, b, e))
    n = a.size
    out = np.empty((n, _capi.VALUE_COUNT))
    status = np.empty(n, dtype=_capi.INT)
    paper = 1 if "stable_paper" in values else 0
    check(lib.hillstab_points(model.handle, n, _capi.doubles(a), _capi.doubles(b), _capi.doubles(e), kind, pieces,
                              samples, real_number("tolerance", tolerance), need, paper, int(threads),
                              _capi.doubles(out),
                              _capi.ints(status)))
    _warn(status, lambda k: "alpha = {!r}, beta = {!r}".format(float(a[k]), float(b[k])))
    return Result(_unpack(out, values, shape), status.reshape(shape).astype(np.int8), values)


def trace(alpha, beta, model="elastic", epsilon=0.0, method="auto", tolerance=1e-10, n_segments=2,
          sampling="endpoint", threads=0):
    """S, the trace of the one-period monodromy, at the points (α, β) (arrays broadcast
    together with ε; ±1e300 where |S| overflows): `floquet`'s ``trace``, but a point that
    failed raises HillstabError (a bare array has no status to carry it).

    >>> trace(3.7, 2.47)
    array(...)
    """
    result = floquet(alpha, beta, model, epsilon, method, tolerance, n_segments, sampling,
                     values=("trace",), threads=threads)
    if np.any(result.status == _capi.STATUS_FAILED):
        raise HillstabError("{} point(s) failed; use floquet() for per-point status".format(
            int(np.count_nonzero(result.status == _capi.STATUS_FAILED))), _capi.ERR_INTEGRATION)
    return result.trace


def chart(alpha, beta, model="elastic", epsilon=0.0, method="auto", tolerance=1e-10, n_segments=2,
          sampling="endpoint", values=ALL_VALUES, threads=0):
    """The stability chart over a grid, as the command line's task ``chart`` computes it.

    ``alpha`` and ``beta`` are (first, last, count) with both ends included, the grid of
    ``&chart alpha_min, alpha_max, n_alpha`` and ``beta_*``. The other parameters as in
    `floquet`; ``values=("stable",)`` computes the verdicts alone (a screening pass
    settles most points: several times faster).

    Returns a `Result` with 2-D arrays ``[i_alpha, i_beta]`` per value, ``status`` and the
    axes ``alpha`` (n_alpha,) and ``beta`` (n_beta,) — for matplotlib,
    ``pcolormesh(c.beta, c.alpha, c.stable)``.
    """
    need = _need(values)
    model = as_model(model)
    kind, pieces, samples = _method(method, n_segments, sampling)
    alpha_min, alpha_max, n_alpha = _axis(alpha, "alpha")
    beta_min, beta_max, n_beta = _axis(beta, "beta")
    alphas = np.empty(n_alpha)
    betas = np.empty(n_beta)
    out = np.empty((n_alpha, n_beta, _capi.VALUE_COUNT))
    status = np.empty((n_alpha, n_beta), dtype=_capi.INT)
    paper = 1 if "stable_paper" in values else 0
    check(lib.hillstab_chart(model.handle, alpha_min, alpha_max, n_alpha, beta_min, beta_max, n_beta,
                             real_number("epsilon", epsilon), kind, pieces, samples,
                             real_number("tolerance", tolerance), need, paper, int(threads),
                             _capi.doubles(alphas), _capi.doubles(betas), _capi.doubles(out),
                             _capi.ints(status)))
    _warn(status, lambda k: "alpha = {!r}, beta = {!r}".format(float(alphas[k // n_beta]), float(betas[k % n_beta])))
    return Result(_unpack(out, values, (n_alpha, n_beta)), status.astype(np.int8), values,
                  extra={"alpha": alphas, "beta": betas})


def _axis(axis, name):
    try:
        first, last, count = axis
    except (TypeError, ValueError):
        raise ValueError("{} must be (first, last, count)".format(name)) from None
    if int(count) != count or count < 1:
        raise ValueError("{}: the count must be a whole number >= 1, got {!r}".format(name, count))
    return real_number(name, first), real_number(name, last), int(count)
