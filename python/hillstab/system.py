"""Systems of Hill equations, n coupled degrees of freedom:

    M x'' + (C + ε M + G) x' + K(τ) x = 0,
    K(τ) = K0 + β B + α Σₖ (Kₖᶜ cos(2πkτ/P) + Kₖˢ sin(2πkτ/P)),   k = 1 … H,

through the library's ``hillstab_system_*`` functions (the matrix system of the scenes'
``&system`` group). `System` takes numpy arrays: M (``mass``), C (``damping``), G
(``gyroscopic``), ``k0`` and ``b`` as n × n arrays, the drive matrices ``cos`` and ``sin``
as (H, n, n) arrays (an n × n array is one harmonic), and the ``period`` P (a multiple of 2).
`System.monodromy` gives the 2n × 2n monodromy Φ acting on (x, x'), `System.floquet` its
multipliers, exponents, verdict and kind; over arrays of points (any shapes that
broadcast, with the damping) `System.floquet` and `System.points` return a `SystemResult`
of arrays — the columns of the command line's files, to the bit — computed on the
library's threads, and `System.chart` the same over a grid.

`Equations` is the system as its user writes it, n coupled equations in physical time with
named parameters and matrices (the scene group ``&equations``),
M x'' + (C + G) x' + K(t) x = 0: the same methods, α and β being the values of its two
axes' parameters, the results named after them too.

Bad input (M not symmetric positive definite, C not symmetric, G not skew, a matrix of the
wrong shape or empty, an n that is not an integer, an unknown method, a tolerance outside
(1e-15, 1), a non-finite point, ε < 0) raises ValueError with a message that names the
argument (``hillstab_system_set: mass: M must be positive definite ...``); an argument of
the wrong type — complex matrices (their imaginary part is never dropped), strings, booleans,
a complex α — raises TypeError naming it.

>>> pair = System(mass=np.diag([1.0, 0.64]), b=[[1.1, -0.1], [-0.1, 0.9]], cos=-np.diag([1.0, 0.8]))
>>> pair.floquet(0.4, 1.2).verdict
1
"""
import ctypes
import math
import re

import numpy as np

from . import _capi, _progress
from ._capi import lib, check, real_number, real_array
from .floquet import _warn, _axis, _scale

_system_p = ctypes.c_void_p
_c_double_p = ctypes.POINTER(ctypes.c_double)
_c_int_p = ctypes.POINTER(ctypes.c_int)

_capi._declare("hillstab_system_new", ctypes.c_int, ctypes.POINTER(_system_p))
_capi._declare("hillstab_system_new_named", ctypes.c_int, ctypes.c_char_p, ctypes.POINTER(_system_p))
_capi._declare("hillstab_system_set_text", ctypes.c_int, _system_p, ctypes.c_char_p, ctypes.c_char_p)
_capi._declare("hillstab_system_free", None, _system_p)
_capi._declare("hillstab_system_set", ctypes.c_int, _system_p, ctypes.c_char_p, _c_double_p, ctypes.c_size_t)
_capi._declare("hillstab_system_check", ctypes.c_int, _system_p)
_capi._declare("hillstab_system_dof", ctypes.c_int, _system_p, _c_int_p)
_capi._declare("hillstab_system_states", ctypes.c_int, _system_p, _c_int_p)
_capi._declare("hillstab_system_monodromy", ctypes.c_int, _system_p, ctypes.c_double, ctypes.c_double,
               ctypes.c_double, ctypes.c_int, ctypes.c_double, _c_double_p, _c_double_p, _c_double_p, _c_int_p)
_capi._declare("hillstab_system_floquet", ctypes.c_int, _system_p, ctypes.c_double, ctypes.c_double,
               ctypes.c_double, ctypes.c_int, ctypes.c_double, _c_double_p, _c_double_p, _c_double_p, _c_double_p,
               _c_int_p, _c_int_p, _c_double_p, _c_double_p, _c_double_p, _c_double_p, _c_int_p)
_capi._declare("hillstab_system_column_count", ctypes.c_int, _system_p, _c_int_p)
_capi._declare("hillstab_system_tau_rate", ctypes.c_int, _system_p, ctypes.c_size_t, _c_double_p, _c_double_p,
               _c_double_p)
_capi._declare("hillstab_system_column_name", ctypes.c_int, _system_p, ctypes.c_int, ctypes.c_char_p,
               ctypes.c_size_t)
_capi._declare("hillstab_system_points", ctypes.c_int, _system_p, ctypes.c_size_t, _c_double_p, _c_double_p,
               _c_double_p, ctypes.c_int, ctypes.c_double, ctypes.c_int, _c_double_p, _c_int_p)
_capi._declare("hillstab_system_regions", ctypes.c_int, _system_p, ctypes.c_int, ctypes.c_double, ctypes.c_double,
               ctypes.c_double, ctypes.c_double, ctypes.c_double, ctypes.c_int, ctypes.c_double, ctypes.c_int,
               ctypes.c_int, ctypes.c_size_t, *([_c_int_p] * 3 + [_c_double_p] * 7 + [_c_int_p] * 3 +
                                                [ctypes.POINTER(ctypes.c_size_t)]))
_capi._declare("hillstab_system_chart", ctypes.c_int, _system_p, ctypes.c_double, ctypes.c_double, ctypes.c_size_t,
               ctypes.c_double, ctypes.c_double, ctypes.c_size_t, ctypes.c_double, ctypes.c_int, ctypes.c_double,
               ctypes.c_int, _c_double_p, _c_double_p, _c_double_p, _c_int_p)

_capi._declare("hillstab_system_chart_scaled", ctypes.c_int, _system_p, ctypes.c_double, ctypes.c_double,
               ctypes.c_size_t, ctypes.c_int, ctypes.c_double, ctypes.c_double, ctypes.c_size_t, ctypes.c_int,
               ctypes.c_double, ctypes.c_int, ctypes.c_double, ctypes.c_int, _c_double_p, _c_double_p, _c_double_p,
               _c_int_p)

#: the methods of systems (codes HILLSTAB_METHOD_*)
SYSTEM_METHODS = {"auto": 0, "magnus4": 3, "magnus6": 4, "rk": 5, "gsl": 6}
#: HILLSTAB_SYSTEM_VERDICT_*
VERDICT_UNSTABLE, VERDICT_STABLE, VERDICT_MARGINAL = 0, 1, -1
#: HILLSTAB_SYSTEM_KIND_*, and their names
KIND_STABLE, KIND_PLUS_ONE, KIND_MINUS_ONE, KIND_COMBINATION, KIND_DAMPED, KIND_UNDECIDED = 0, 1, 2, 3, 4, 5
KIND_NAMES = {0: "stable", 1: "parametric at +1", 2: "parametric at -1", 3: "combination (Krein collision)",
              4: "damped, asymptotically stable", 5: "undecided (marginal)"}


def _method(method):
    if not isinstance(method, str):
        raise TypeError("method: must be a method's name (a str), got {}".format(type(method).__name__))
    if method not in SYSTEM_METHODS:
        raise ValueError("method: unknown system method '{}' (expected {})".format(
            method, ", ".join(SYSTEM_METHODS)))
    return SYSTEM_METHODS[method]


def _threads(threads):
    if isinstance(threads, (bool, np.bool_)) or not isinstance(threads, (int, np.integer)):
        raise TypeError("threads: must be an int (0: OpenMP's default), got {}".format(type(threads).__name__))
    if threads < 0:
        raise ValueError("threads: must be >= 0 (0: OpenMP's default), got {}".format(threads))
    return int(threads)


def _degrees_of_freedom(n):
    """n as an int: TypeError naming n for what is not a number, ValueError for a number
    that is not an integer (2.7 is not read as 2)."""
    if isinstance(n, (bool, np.bool_)):
        raise TypeError("n: the degrees of freedom must be an integer, got a bool")
    if isinstance(n, (int, np.integer)):
        return int(n)
    value = real_number("n", n)
    if not (math.isfinite(value) and value == math.floor(value)):
        raise ValueError("n: the degrees of freedom must be an integer from 1 to 20, got {!r}".format(value))
    return int(value)


def _unscaled(phi, log_scale):
    """Φ = e^s Φ̃ entry by entry, as e^r Φ̃ times 2^k (s = k ln 2 + r, the power of two exact):
    an entry beyond the double range is ±inf, a zero entry stays 0 (never nan), and no
    floating-point warning is raised."""
    if log_scale == 0.0:
        return phi
    k = math.floor(log_scale / math.log(2.0))
    r = log_scale - k * math.log(2.0)
    with np.errstate(over="ignore", under="ignore"):
        return np.ldexp(phi * math.exp(r), k)


class SystemFloquet:
    """The Floquet analysis of one point of a system.

    ``multipliers``: the 2n multipliers λ of Φ (complex, by decreasing modulus; where they
    would exceed 1e300 they are Φ̃'s and ``log_scale`` s > 0, Φ's being e^s times them);
    ``exponents``: ln|λ_i|/P of the n largest, each to the tolerance however many decades
    they span (from the period's product kept factored where Φ cannot resolve them; the
    smaller ``multipliers`` of Φ itself may then be rounding); ``verdict``: 1 stable,
    0 unstable, −1 marginal (the error bound does not decide); ``kind``: 0 stable, 1 at +1,
    2 at −1, 3 combination resonance, 4 damped, 5 undecided (a marginal verdict;
    `kind_name`); ``trace`` tr Φ and ``a2`` = Σ λ_iλ_j = ((tr Φ)² − tr Φ²)/2 (±1e300
    beyond); ``defect``: the structural defect relative to |Φ|² or to Hadamard's bound of
    det Φ; ``error_estimate`` (never below the method's rounding) and ``status`` (0, or 1
    round-off limited: the tolerance lies below the rounding or an exponent is not resolved)
    of the monodromy.
    """

    def __init__(self, **values):
        for key, value in values.items():
            setattr(self, key, value)

    @property
    def stable(self):
        """True where the verdict is stable."""
        return self.verdict == VERDICT_STABLE

    @property
    def kind_name(self):
        """The kind in words."""
        return KIND_NAMES.get(self.kind, "unknown")

    def __repr__(self):
        return "<hillstab system floquet: verdict {}, kind {} ({}), trace {:.6g}>".format(
            self.verdict, self.kind, self.kind_name, self.trace)


class SystemResult:
    """The Floquet analysis of many points of a system, as arrays of the points' shape.

    The values of a system's chart and points files, by the files' column names
    (attributes and ``result["name"]``): ``trace`` tr Φ, ``a2``, ``overflow`` (1 where tr Φ
    or a₂ passed ±1e300), ``stable`` (the verdict: 1 stable, 0 unstable, −1 marginal),
    ``kind`` (0 … 5, `KIND_NAMES`), ``lambda_max`` the largest |λ| (at most 1e300), ``mu``
    its exponent ln|λ|/P, ``argument`` its argument, ``mu_1`` … ``mu_n`` the n largest
    exponents (also as ``exponents``, with a last axis of n), ``defect``,
    ``error_estimate``, ``status`` (0 within the tolerance, 1 round-off limited, 2 failed
    with the files' placeholders: stable −1, kind −1, error_estimate −1) and ``steps``.
    ``verdict`` is ``stable``. A chart's result has the axes ``alpha`` and ``beta`` too.
    """

    def __init__(self, arrays, names, extra=None):
        self._arrays = arrays
        self._names = tuple(names)
        n = sum(1 for name in names if name.startswith("mu_"))
        #: the n largest exponents, a last axis of n
        self.exponents = np.stack([arrays["mu_{}".format(k + 1)] for k in range(n)], axis=-1)
        for key, value in (extra or {}).items():
            setattr(self, key, value)

    @property
    def names(self):
        """The columns, in the files' order."""
        return self._names

    @property
    def verdict(self):
        """The verdict (the column ``stable``)."""
        return self._arrays["stable"]

    @property
    def ok(self):
        """True where the point was computed (status 0 or 1)."""
        return self._arrays["status"] < 2

    def __getattr__(self, name):
        arrays = self.__dict__.get("_arrays", {})
        if name in arrays:
            return arrays[name]
        raise AttributeError(name)

    def __getitem__(self, name):
        """A column by name (a chart's ``result["alpha"]`` is the 2-D column, ``result.alpha``
        its axis)."""
        if name in self._arrays:
            return self._arrays[name]
        return getattr(self, name)

    def __repr__(self):
        return "<hillstab system result: {} points, columns {}>".format(self._arrays["status"].size,
                                                                        " ".join(self._names))


def _shift_point(offset):
    """A message fix for a chunk of points: "point K:" counted within the whole call."""
    pattern = re.compile(r"(: point )(\d+)(:)")
    return lambda message: pattern.sub(lambda m: m.group(1) + str(int(m.group(2)) + offset) + m.group(3),
                                       message, count=1)


def _is_scalar(value):
    return np.ndim(value) == 0 and not isinstance(value, (list, tuple))


class System:
    """A system of n Hill equations with constant M, C, G and K(τ) = K0 + β B + α Σ drives.

    Arguments (numpy arrays or nested lists): ``mass`` M (default I), ``damping`` C (0),
    ``gyroscopic`` G (0), ``k0`` (0), ``b`` (I), all n × n; ``cos`` and ``sin``: (H, n, n)
    (or one n × n matrix), at least one nonzero; ``period`` P, a multiple of 2 (2: cos kπτ).
    n comes from the first matrix given (``n`` when only the defaults are wanted). The
    system is checked when made: ValueError naming the argument otherwise.
    """

    def __init__(self, mass=None, damping=None, gyroscopic=None, k0=None, b=None, cos=None, sin=None, period=2.0,
                 n=None):
        given = {"mass": mass, "damping": damping, "gyroscopic": gyroscopic, "k0": k0, "b": b}
        drives = {"cos": cos, "sin": sin}
        squares = {}
        for name, value in given.items():
            if value is not None:
                array = real_array(name, value)
                if array.ndim != 2 or array.shape[0] != array.shape[1] or array.shape[0] < 1:
                    raise ValueError("{}: must be an n x n array (n >= 1), got shape {}".format(name, array.shape))
                squares[name] = array
        blocks = {}
        for name, value in drives.items():
            if value is not None:
                array = real_array(name, value)
                if array.ndim == 2:
                    array = array[np.newaxis]
                if array.ndim != 3 or array.shape[1] != array.shape[2] or array.shape[1] < 1 or array.shape[0] < 1:
                    raise ValueError("{}: must be an (H, n, n) array (H >= 1 harmonics, n >= 1) or one n x n "
                                     "matrix, got shape {}".format(name, np.shape(array)))
                blocks[name] = array
        period = real_number("period", period)
        if n is None:
            for name, array in list(squares.items()) + list(blocks.items()):
                n = array.shape[-1]
                break
        else:
            n = _degrees_of_freedom(n)
        if n is None:
            raise ValueError("n: give a matrix (mass, k0, b, cos, ...) or n")
        for name, array in squares.items():
            if array.shape != (n, n):
                raise ValueError("{}: must be an n x n array, n = {}, got shape {}".format(name, n, array.shape))
        for name, array in blocks.items():
            if array.shape[1:] != (n, n):
                raise ValueError("{}: must be an (H, n, n) array, n = {}, got shape {}".format(
                    name, n, np.shape(array)))
        handle = _system_p()
        check(lib.hillstab_system_new(ctypes.byref(handle)))
        self._handle = handle
        self._set("n", [float(n)])
        for name, array in list(squares.items()) + list(blocks.items()):
            self._set(name, array)
        self._set("period", [period])
        check(lib.hillstab_system_check(self._handle))
        #: the degrees of freedom
        self.n = n
        #: the size of the state y = (x, x'): 2n (Φ is states × states)
        self.states = 2 * n
        #: the period P of K in τ
        self.period = period

    def _set(self, name, values):
        array = _capi.as_doubles(np.ravel(values, order="C"))
        check(lib.hillstab_system_set(self._handle, name.encode(), _capi.doubles(array), array.size))

    def __del__(self):
        handle = getattr(self, "_handle", None)
        if handle is not None and handle.value:
            try:
                lib.hillstab_system_free(handle)
            except Exception:  # the interpreter is shutting down
                pass
            self._handle = None

    @property
    def handle(self):
        """The C handle (``hillstab_system *``)."""
        return self._handle

    def monodromy(self, alpha, beta, epsilon=0.0, method="auto", tolerance=1e-10):
        """The one-period monodromy Φ at (α, β) with damping ε M: (phi, error_estimate,
        status), phi the 2n × 2n ndarray acting on (x, x') (±inf where an entry of Φ overflows
        a double, without a warning), error_estimate relative to max(1, max|Φ_ij|), status 0
        or 1 (round-off limited)."""
        alpha, beta, epsilon, tolerance = self._point(alpha, beta, epsilon, tolerance)
        m = self.states
        phi = np.zeros((m, m), dtype=np.float64)
        log_scale = ctypes.c_double(0.0)
        estimate = ctypes.c_double(0.0)
        status = ctypes.c_int(0)
        check(lib.hillstab_system_monodromy(self._handle, alpha, beta, epsilon, _method(method), tolerance,
                                            _capi.doubles(phi), ctypes.byref(log_scale), ctypes.byref(estimate),
                                            ctypes.byref(status)))
        return _unscaled(phi, log_scale.value), estimate.value, status.value

    @staticmethod
    def _point(alpha, beta, epsilon, tolerance):
        return (real_number("alpha", alpha), real_number("beta", beta), real_number("epsilon", epsilon),
                real_number("tolerance", tolerance))

    def floquet(self, alpha, beta, epsilon=0.0, method="auto", tolerance=1e-10, threads=0, progress=None,
                chunk=None):
        """The Floquet analysis at (α, β) with damping ε M.

        At one point (numbers): a `SystemFloquet`, with the multipliers. At arrays of points
        (α, β and ε of any shapes that broadcast together): `points`' `SystemResult`, each
        point computed alone as the command line's task ``points`` computes it, on the
        library's threads (``progress``, ``chunk``: as in `points`). Status 1 and 2 give a
        `HillstabWarning`, as for a scalar model.
        """
        if not (_is_scalar(alpha) and _is_scalar(beta) and _is_scalar(epsilon)):
            return self.points(alpha, beta, epsilon, method, tolerance, threads, progress, chunk)
        m = self.states
        re = np.zeros(m, dtype=np.float64)
        im = np.zeros(m, dtype=np.float64)
        exponents = np.zeros(self.n, dtype=np.float64)
        doubles = [ctypes.c_double(0.0) for _ in range(5)]
        ints = [ctypes.c_int(0) for _ in range(3)]
        log_scale, trace, a2, defect, estimate = doubles
        verdict, kind, status = ints
        alpha, beta, epsilon, tolerance = self._point(alpha, beta, epsilon, tolerance)
        check(lib.hillstab_system_floquet(self._handle, alpha, beta, epsilon, _method(method),
                                          tolerance, _capi.doubles(re), _capi.doubles(im),
                                          ctypes.byref(log_scale), _capi.doubles(exponents), ctypes.byref(verdict),
                                          ctypes.byref(kind), ctypes.byref(trace), ctypes.byref(a2),
                                          ctypes.byref(defect), ctypes.byref(estimate), ctypes.byref(status)))
        _warn(np.array([status.value]), lambda k: "alpha = {!r}, beta = {!r}".format(alpha, beta))
        return SystemFloquet(multipliers=re + 1j * im, log_scale=log_scale.value, exponents=exponents,
                             verdict=verdict.value, kind=kind.value, trace=trace.value, a2=a2.value,
                             defect=defect.value, error_estimate=estimate.value, status=status.value)

    def tau_rate(self, alpha, beta):
        """dτ/dt at the points (α, β) (arrays broadcast together): ``mu`` (or ``mu_k``) times it
        is the exponent per unit of the system's own time t — a system of equations' Ω/π at each
        point (its drive may depend on either axis); 0 for a system in τ alone and at a point
        outside the domain. Through ``hillstab_system_tau_rate``."""
        a, b = np.broadcast_arrays(real_array("alpha", alpha), real_array("beta", beta))
        shape = a.shape
        a, b = (_capi.as_doubles(x.ravel()) for x in (a, b))
        rate = np.empty(a.size)
        check(lib.hillstab_system_tau_rate(self._handle, a.size, _capi.doubles(a), _capi.doubles(b),
                                           _capi.doubles(rate)))
        return rate.reshape(shape)

    def column_names(self):
        """The columns of the system's chart and points files (14 + n names)."""
        count = ctypes.c_int(0)
        check(lib.hillstab_system_column_count(self._handle, ctypes.byref(count)))
        return tuple(_capi.text_out(lib.hillstab_system_column_name, self._handle, k, length=64)
                     for k in range(count.value))

    def _result(self, values, status, shape, extra=None):
        names = self.column_names()
        arrays = {}
        for k, name in enumerate(names):
            column = values[..., k].reshape(shape)
            if name in ("overflow", "stable", "kind", "status", "steps"):
                column = np.rint(column).astype(np.int64)
            else:
                column = column.copy()
            arrays[name] = column
        arrays["status"] = status.reshape(shape).astype(np.int8)
        return SystemResult(arrays, names, extra)

    def points(self, alpha, beta, epsilon=0.0, method="auto", tolerance=1e-10, threads=0, progress=None, chunk=None):
        """The Floquet analysis of the points (α, β) with damping ε M — arrays of any shapes
        that broadcast together — each computed alone as the command line's task ``points``
        computes it (its files' numbers to the bit), on ``threads`` of the library's threads
        (0: OpenMP's default). Returns a `SystemResult` of the broadcast shape; status 1 and
        2 give a `HillstabWarning`. ``progress``: a callable ``progress(done, total)`` called
        after each chunk of ``chunk`` points (default about 1 % of them, at least 100), or
        True for a bar (tqdm when installed, else a line on stderr); the chunks are computed
        in order and give the same numbers to the bit (each point is computed alone)."""
        a, b, e = np.broadcast_arrays(real_array("alpha", alpha), real_array("beta", beta),
                                      real_array("epsilon", epsilon))
        shape = a.shape
        a, b, e = (_capi.as_doubles(x.ravel()) for x in (a, b, e))
        n = a.size
        width = 14 + self.n
        out = np.empty((n, width))
        status = np.zeros(n, dtype=_capi.INT)
        code_of_method = _method(method)
        tolerance = real_number("tolerance", tolerance)
        threads = _threads(threads)
        report = _progress.Progress(progress, n, "points")
        parts = _progress.chunks(n, _progress.chunk_size(chunk, n, 100)) if report.active else []
        try:
            for start, stop in parts or [(0, n)]:
                code = lib.hillstab_system_points(self._handle, stop - start, _capi.doubles(a[start:]),
                                                  _capi.doubles(b[start:]), _capi.doubles(e[start:]), code_of_method,
                                                  tolerance, threads, _capi.doubles(out[start:]),
                                                  _capi.ints(status[start:]))
                if code != _capi.ERR_POINTS_FAILED:
                    check(code, known=(tolerance,), fix=_shift_point(start))
                if report.active:
                    report.update(stop)
        finally:
            report.close()
        _warn(status, lambda k: "alpha = {!r}, beta = {!r}".format(float(a[k]), float(b[k])))
        return self._result(out, status, shape)

    def chart(self, alpha, beta, epsilon=0.0, method="auto", tolerance=1e-10, threads=0, progress=None,
              alpha_scale="linear", beta_scale="linear"):
        """The chart over a grid, as the command line's task ``chart`` computes it (its files'
        numbers to the bit: the points of a row share their nodes). ``alpha`` and ``beta``
        are (first, last, count), both ends included, equally spaced, or geometric with
        ``alpha_scale="log"`` (``beta_scale``; first > 0), as ``&chart alpha_scale``. Returns a `SystemResult` with 2-D
        arrays ``[i_alpha, i_beta]`` and the axes ``alpha`` (n_alpha,) and ``beta``
        (n_beta,); status 1 and 2 give a `HillstabWarning`. ``progress`` (a callable
        ``progress(done, total)`` of rows, or True for a bar) reports the rows as they are
        done, the chart still one call into the library (in a worker thread): the same
        numbers to the bit. `read_output` gives a chart file in the same shape."""
        alpha_min, alpha_max, n_alpha = _axis(alpha, "alpha")
        beta_min, beta_max, n_beta = _axis(beta, "beta")
        scales = _scale(alpha_scale, "alpha_scale"), _scale(beta_scale, "beta_scale")
        alphas = np.empty(n_alpha)
        betas = np.empty(n_beta)
        width = 14 + self.n
        out = np.empty((n_alpha, n_beta, width))
        status = np.zeros((n_alpha, n_beta), dtype=_capi.INT)
        epsilon = real_number("epsilon", epsilon)
        tolerance = real_number("tolerance", tolerance)
        code_of_method = _method(method)
        threads = _threads(threads)

        def call():
            code = lib.hillstab_system_chart_scaled(self._handle, alpha_min, alpha_max, n_alpha, scales[0], beta_min,
                                                    beta_max, n_beta, scales[1], epsilon, code_of_method, tolerance,
                                                    threads, _capi.doubles(alphas), _capi.doubles(betas),
                                                    _capi.doubles(out), _capi.ints(status))
            if code != _capi.ERR_POINTS_FAILED:
                check(code, known=(epsilon, tolerance, alpha_min, alpha_max, beta_min, beta_max))

        report = _progress.Progress(progress, n_alpha, "rows")
        try:
            if report.active:
                _progress.watch(call, status, report)
            else:
                call()
        finally:
            report.close()
        _warn(status, lambda k: "alpha = {!r}, beta = {!r}".format(float(alphas[k // n_beta]),
                                                                  float(betas[k % n_beta])))
        return self._result(out, status, (n_alpha, n_beta), extra={"alpha": alphas, "beta": betas})

    def regions(self, frequency, drive, order=2, drive_axis=None, epsilon=0.0, method="auto", tolerance=1e-10,
                n_samples=32):
        """The resonance regions over ``frequency = (f_min, f_max)`` and the tip of each in
        ``drive = (d_min, d_max)``, as `hillstab.Regions` (see `hillstab.regions`): from the
        natural frequencies ν_i of the undriven system, the simple (2ν_i = k), sum
        (ν_i + ν_j = k) and difference (|ν_i − ν_j| = k) regions of order k = 1 … ``order``.
        ``drive_axis`` 1 (or ``"alpha"``: the drive is α, the frequency β) is the default of a
        `System`, whose α Σ drives is the drive; 2 (``"beta"``: the drive is β, the frequency
        α) that of `Equations`, whose α is the drive frequency. Damping ε M (``epsilon``; 0 for
        `Equations`, which carry their own); Φ by ``method`` to ``tolerance`` (also the target
        of the tips). Bad input raises ValueError naming the argument."""
        from .curves import _regions, _drive_axis
        default = 2 if getattr(self, "axes", None) else 1
        return _regions(lib.hillstab_system_regions, self._handle, getattr(self, "axes", None), frequency, drive, order,
                        _drive_axis(drive_axis, default), epsilon, _method(method), tolerance, n_samples)

    def __repr__(self):
        return "hillstab.System(n={}, period={:g})".format(self.n, self.period)


def _number_text(name, value):
    """A real number as the expression its shortest repr is: TypeError naming the argument
    for what is not a real number, ValueError for one that is not finite."""
    value = real_number(name, value)
    if not math.isfinite(value):
        raise ValueError("{}: must be finite, got {!r}".format(name, value))
    return repr(value)


def _matrices_text(matrices, n):
    """``{name: n x n array}`` as the text 'W = [1.0, 0.0; 0.0, 4.0], S = [...]' (rows by ';',
    each entry the repr of its double, so that the library reads the same numbers); n the
    shape every matrix must have (None: the first one's)."""
    parts = []
    for name, value in matrices.items():
        if not isinstance(name, str):
            raise TypeError("matrices: a matrix's name must be a str, got {!r}".format(name))
        array = real_array("matrices: " + name, value)
        if array.ndim != 2 or array.shape[0] != array.shape[1] or array.shape[0] < 1:
            raise ValueError("matrices: {}: must be an n x n array (n >= 1), got shape {}".format(
                name, array.shape))
        if n is None:
            n = array.shape[0]
        if array.shape != (n, n):
            raise ValueError("matrices: {}: must be an n x n array, n = {}, got shape {}".format(
                name, n, array.shape))
        if not np.all(np.isfinite(array)):
            raise ValueError("matrices: {}: the entries must be finite".format(name))
        rows = ("; ".join(", ".join(repr(float(x)) for x in row) for row in array))
        parts.append("{} = [{}]".format(name, rows))
    return ", ".join(parts), n


class Equations(System):
    """A system as its user writes it: n coupled equations in physical time t with named
    parameters and named constant matrices (the scene group ``&equations``),

        M x'' + (C + G) x' + K(t) x = 0,   K of period 2π/Ω,

    through the library's ``hillstab_system_new_named("equations")`` and
    ``hillstab_system_set_text``. ``stiffness`` K(t), ``mass`` M (default ``"1"``: I),
    ``damping`` C (``"0"``) and ``gyroscopic`` G (``"0"``) are matrix expressions: scalar
    expressions of t (K only), the parameters and the matrices' names, linear in the matrices
    (``"W - (P0 + P1*cos(Om*t))*S"``; a number or a part without a matrix is that multiple of
    I); ``matrices`` a dict ``{name: n x n array}`` (or the scene's text
    ``"W = [1, 0; 0, 4], S = [...]"``); ``parameters`` a dict ``{name: value}`` in order (or
    the text ``"P0 = 0.3, Om = 2"``); ``frequency`` Ω or ``period`` T (expressions of the
    parameters, or numbers); ``alpha`` and ``beta`` the parameters the points' two
    coordinates are; ``n`` the degrees of freedom (default: the matrices' size). Either axis
    may enter anything but M: where β enters K alone and affinely, a row's points share its
    form; else each point is the system at its β, prepared alone (the same values, slower).

    ``state`` instead of ``stiffness`` (with no mass, damping or gyroscopic matrix) gives the
    first-order form y' = A(t) y, a periodic state-space model of ``n`` states: A(t) a matrix
    expression as above; Φ is then n × n with n multipliers and n exponents (``states``), its
    every system method (the Magnus ones on the full A).

    The methods are `System`'s — `floquet`, `points`, `chart`, `monodromy` — with α and β
    the values of the two axes' parameters; the results carry the axes by those names too
    (``chart(...).Om`` is the axis ``alpha``, ``points(...).P1`` the column ``beta``). The
    damping is the system's own, (π/Ω) C in τ = Ωt/π, prepared at each point's α as the
    command line's tasks prepare it (their files' numbers to the bit): ``epsilon`` must stay
    0. The results are the physical system's: its multipliers over one period 2π/Ω, the
    exponents ``mu`` per unit τ (μ Ω/π per unit time). A text the system refuses raises
    ValueError naming the variable (``hillstab_system_check: matrices: S, row 2 has 2
    entries, n = 3 are needed``). A text holds at most 8000 characters.

    >>> column = Equations("W - (P0 + P1*cos(Om*t))*S", frequency="Om", damping="2*zeta*Z",
    ...                    matrices={"W": np.diag([1.0, 16.0, 81.0]), "S": [[1, 0.3, 0.1], [0.3, 4, 0.4],
    ...                              [0.1, 0.4, 9]], "Z": np.diag([1.0, 4.0, 9.0])},
    ...                    parameters={"P0": 0.3, "P1": 0.0, "Om": 2.0, "zeta": 0.01}, alpha="Om", beta="P1")
    >>> column.floquet(1.6, 0.4).kind_name
    'parametric at -1'
    """

    def __init__(self, stiffness=None, frequency=None, period=None, parameters=None, matrices=None, mass="1",
                 damping="0", gyroscopic="0", alpha=None, beta=None, n=None, state=None):
        if n is not None:
            n = _degrees_of_freedom(n)
        if matrices is None:
            matrices = ""
        if isinstance(matrices, dict):
            matrices, n = _matrices_text(matrices, n)
        elif not isinstance(matrices, str):
            raise TypeError("matrices: a dict {{name: n x n array}} or a text 'W = [1, 0; 0, 4], ...', got "
                            "{}".format(type(matrices).__name__))
        if n is None:
            raise ValueError("n: give the degrees of freedom (or the matrices as a dict of arrays)")
        if parameters is None:
            parameters = ""
        if isinstance(parameters, dict):
            for name in parameters:
                if not isinstance(name, str):
                    raise TypeError("parameters: a parameter's name must be a str, got {!r}".format(name))
            parameters = ", ".join("{} = {}".format(name, _number_text("parameters: " + name, value))
                                   for name, value in parameters.items())
        texts = []
        if stiffness is None and state is None:
            raise ValueError("stiffness: give K(t) of M x'' + (C + G) x' + K(t) x = 0, or state: A(t) of "
                             "y' = A(t) y")
        for name, text in (("parameters", parameters), ("matrices", matrices), ("stiffness", stiffness),
                           ("state", state), ("mass", mass), ("damping", damping), ("gyroscopic", gyroscopic),
                           ("frequency", frequency), ("period", period), ("alpha", alpha), ("beta", beta)):
            if text is None:
                continue
            if not isinstance(text, str):
                if name in ("mass", "damping", "gyroscopic", "frequency", "period"):
                    text = _number_text(name, text)
                else:
                    raise TypeError("{}: a string, got {!r}".format(name, text))
            texts.append((name, text))
        handle = _system_p()
        check(lib.hillstab_system_new_named(b"equations", ctypes.byref(handle)))
        self._handle = handle
        self._set("n", [float(n)])
        for name, text in texts:
            check(lib.hillstab_system_set_text(self._handle, name.encode(), text.encode()))
        check(lib.hillstab_system_check(self._handle))
        dof = ctypes.c_int(0)
        check(lib.hillstab_system_dof(self._handle, ctypes.byref(dof)))
        #: the degrees of freedom (in first-order form: the states)
        self.n = dof.value
        states = ctypes.c_int(0)
        check(lib.hillstab_system_states(self._handle, ctypes.byref(states)))
        #: the size of the state: 2n, or n in first-order form (Φ is states × states)
        self.states = states.value
        #: the parameters of the two axes, as the results name them too
        self.axes = (alpha, beta)
        #: the period of the system in τ = Ωt/π (one period of K is τ in [0, 2])
        self.period = 2.0

    def column_names(self):
        """The columns of the system's chart and points files: the first two named after the
        axes' parameters, as the files name them."""
        names = super().column_names()
        return tuple(self.axes) + names[2:]

    def _result(self, values, status, shape, extra=None):
        result = super()._result(values, status, shape, extra)
        for name, key in zip(self.axes, ("alpha", "beta")):
            # the columns also by their generic names, and a chart's axes by the parameters'
            result._arrays.setdefault(key, result._arrays[name])
            if extra and key in extra:
                setattr(result, name, extra[key])
        return result

    def __repr__(self):
        axes = getattr(self, "axes", (None, None))
        return "hillstab.Equations(n={}, alpha={!r}, beta={!r})".format(getattr(self, "n", None), *axes)
