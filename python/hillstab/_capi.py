"""The C interface of libhillstab through ctypes (internal).

The library is the ``libhillstab.so`` that ``pip install`` compiled into this package
(``HILLSTAB_LIBRARY`` names another one). Every function returns a status: 0, or an error
code whose full message the calling thread reads with ``hillstab_last_error``; `check`
turns it into a Python exception. ctypes releases the GIL during each call, so the
library's OpenMP threads run while other Python threads go on.
"""
import ctypes
import glob
import math
import os
import re

import numpy as np

from .errors import HillstabError, PointsFailedError

#: error codes of include/hillstab.h
ERR_INVALID_PARAMETER = 1
ERR_OVERFLOW = 2
ERR_INTEGRATION = 3
ERR_IO = 4
ERR_INPUT = 5
ERR_SINGULAR = 6
ERR_ACCURACY = 7
ERR_POINTS_FAILED = 8

#: HILLSTAB_METHOD_*
METHODS = {"auto": 0, "formula": 1, "segments": 2, "magnus4": 3, "magnus6": 4, "rk": 5, "gsl": 6}
#: HILLSTAB_SAMPLING_*
SAMPLINGS = {"endpoint": 1, "midpoint": 2, "average": 3}
#: HILLSTAB_NEED_*
NEED_VERDICT, NEED_GROWTH, NEED_TRACE = 1, 2, 3
#: the status of a point: ok, round-off limited (the best value double precision allows), failed
STATUS_OK, STATUS_ROUNDOFF, STATUS_FAILED = 0, 1, 2
#: HILLSTAB_VALUE_*: the values of a point, by their index
VALUES = ("trace", "log_abs_trace", "log10_abs_trace", "overflow", "stable", "stable_paper", "lambda_max",
          "log_modulus_max", "log_modulus_min", "exponent", "error_estimate", "kind", "argument")
VALUE_COUNT = len(VALUES)

_c_double_p = ctypes.POINTER(ctypes.c_double)
_c_int_p = ctypes.POINTER(ctypes.c_int)
_c_size_p = ctypes.POINTER(ctypes.c_size_t)
_model_p = ctypes.c_void_p


def _find_library():
    path = os.environ.get("HILLSTAB_LIBRARY")
    if path:
        return path
    here = os.path.dirname(os.path.abspath(__file__))
    found = sorted(glob.glob(os.path.join(here, "libhillstab.so*")))
    if not found:
        raise ImportError("hillstab: libhillstab.so is not in " + here + " (install the package with pip, "
                          "or set HILLSTAB_LIBRARY to the library's path)")
    return found[0]


lib = ctypes.CDLL(_find_library())


def _declare(name, restype, *argtypes):
    function = getattr(lib, name)
    function.restype = restype
    function.argtypes = list(argtypes)
    return function


_declare("hillstab_last_error", ctypes.c_int, ctypes.c_char_p, ctypes.c_size_t)
_declare("hillstab_error_message", None, ctypes.c_int, ctypes.c_char_p, ctypes.c_size_t)
_declare("hillstab_version", ctypes.c_char_p)
_declare("hillstab_trace", ctypes.c_int, ctypes.c_int, ctypes.c_double, ctypes.c_double, ctypes.c_double,
         ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_double, _c_double_p, _c_double_p, _c_int_p)
_declare("hillstab_q", ctypes.c_int, ctypes.c_int, ctypes.c_double, ctypes.c_double, ctypes.c_double,
         ctypes.c_double, _c_double_p)
_declare("hillstab_model_count", ctypes.c_int)
_declare("hillstab_model_registry_name", ctypes.c_int, ctypes.c_int, ctypes.c_char_p, ctypes.c_size_t)
_declare("hillstab_model_new", ctypes.c_int, ctypes.c_char_p, ctypes.POINTER(_model_p))
_declare("hillstab_model_free", None, _model_p)
_declare("hillstab_model_set", ctypes.c_int, _model_p, ctypes.c_char_p, _c_double_p, ctypes.c_size_t)
_declare("hillstab_model_set_text", ctypes.c_int, _model_p, ctypes.c_char_p, ctypes.c_char_p)
_declare("hillstab_model_check", ctypes.c_int, _model_p)
_declare("hillstab_model_name", ctypes.c_int, _model_p, ctypes.c_char_p, ctypes.c_size_t)
_declare("hillstab_model_formula", ctypes.c_int, _model_p, ctypes.c_char_p, ctypes.c_size_t)
_declare("hillstab_model_variable_count", ctypes.c_int, _model_p, _c_int_p)
_declare("hillstab_model_variable_name", ctypes.c_int, _model_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_size_t,
         _c_int_p)
_declare("hillstab_model_tau_rate", ctypes.c_int, _model_p, ctypes.c_size_t, _c_double_p, _c_double_p, _c_double_p)
_declare("hillstab_points", ctypes.c_int, _model_p, ctypes.c_size_t, _c_double_p, _c_double_p, _c_double_p,
         ctypes.c_int, ctypes.c_int, ctypes.c_int, ctypes.c_double, ctypes.c_int, ctypes.c_int, ctypes.c_int,
         _c_double_p, _c_int_p)
_declare("hillstab_chart", ctypes.c_int, _model_p, ctypes.c_double, ctypes.c_double, ctypes.c_size_t,
         ctypes.c_double, ctypes.c_double, ctypes.c_size_t, ctypes.c_double, ctypes.c_int, ctypes.c_int,
         ctypes.c_int, ctypes.c_double, ctypes.c_int, ctypes.c_int, ctypes.c_int, _c_double_p, _c_double_p,
         _c_double_p, _c_int_p)
_declare("hillstab_chart_scaled", ctypes.c_int, _model_p, ctypes.c_double, ctypes.c_double, ctypes.c_size_t,
         ctypes.c_int, ctypes.c_double, ctypes.c_double, ctypes.c_size_t, ctypes.c_int, ctypes.c_double, ctypes.c_int,
         ctypes.c_int, ctypes.c_int, ctypes.c_double, ctypes.c_int, ctypes.c_int, ctypes.c_int, _c_double_p,
         _c_double_p, _c_double_p, _c_int_p)
_declare("hillstab_physical", ctypes.c_int, _model_p, ctypes.c_double, ctypes.c_double, ctypes.c_double,
         ctypes.c_double, ctypes.c_double, _c_double_p, _c_double_p, _c_double_p)
_declare("hillstab_critical_drives", ctypes.c_int, _model_p, ctypes.c_double, ctypes.c_double, ctypes.c_double,
         ctypes.c_double, ctypes.c_int, ctypes.c_double, ctypes.c_int, ctypes.c_size_t, _c_double_p, _c_double_p,
         _c_int_p, _c_int_p, _c_int_p, _c_size_p)
_declare("hillstab_critical_drives_along", ctypes.c_int, _model_p, ctypes.c_int, ctypes.c_double, ctypes.c_double,
         ctypes.c_double, ctypes.c_double, ctypes.c_int, ctypes.c_double, ctypes.c_int, ctypes.c_size_t, _c_double_p,
         _c_double_p, _c_int_p, _c_int_p, _c_int_p, _c_size_p)
_declare("hillstab_transition_curves", ctypes.c_int, _model_p, ctypes.c_size_t, _c_double_p, ctypes.c_double,
         ctypes.c_double, ctypes.c_double, ctypes.c_size_t, ctypes.c_int, _c_double_p, _c_int_p, _c_int_p,
         _c_int_p, _c_double_p, _c_int_p, _c_size_p, _c_int_p)
_declare("hillstab_run_scene", ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_size_t)


def last_error():
    """The calling thread's most recent status and message of the library."""
    buffer = ctypes.create_string_buffer(1100)
    status = lib.hillstab_last_error(buffer, len(buffer))
    return status, buffer.value.decode("utf-8", "replace")


def error_name(status):
    """The name of an error code ("invalid parameter", ...)."""
    buffer = ctypes.create_string_buffer(64)
    lib.hillstab_error_message(status, buffer, len(buffer))
    return buffer.value.decode()


def check(status, path=None, known=None, fix=None):
    """Raise the library's error of a failed call: ValueError for bad input (invalid
    parameter, invalid input), PointsFailedError when a scene's file was written with
    failed points, HillstabError for a computation that failed.

    The message's numbers are given in Python's format (`python_numbers`): ``known`` is the
    call's input values (a sequence, or a function of the message returning one), so that a
    value the library printed to a few digits is shown as the value passed; ``fix``, a
    function of the message, corrects it further (the index of a point in a chunked call)."""
    if status == 0:
        return
    code, message = last_error()
    if not message:
        message = error_name(status)
    if fix is not None:
        message = fix(message)
    if callable(known):
        known = known(message)
    message = python_numbers(message, known or ())
    if status in (ERR_INVALID_PARAMETER, ERR_INPUT):
        raise ValueError(message)
    if status == ERR_POINTS_FAILED:
        raise PointsFailedError(message, status, path)
    raise HillstabError(message, status)


# a number as Fortran's E and ES edit descriptors write it (-1.00000E-01), or a plain decimal
_NUMBER = re.compile(r"(?<![\w.])([-+]?)(\d+)\.(\d+)(?:E([-+]?\d+))?(?![\w.])")


def python_numbers(message, known=()):
    """The library's message with its Fortran-formatted numbers in Python's format: a number
    written with an exponent E (``-1.00000E-01``) or with 17 significant digits
    (``9.8696044010893586``) becomes the repr of the value (``-0.1``, ``9.869604401089358``)
    — of the input value in `known` that it shows, when the library printed fewer digits
    than a double has, else of the number as printed (``'{:.6g}'`` of a 6-digit one). The
    words are left as they are; numbers the library already wrote in their shortest form
    (``got 10.5``) are unchanged."""
    known = [float(v) for v in known]

    def replace(match):
        sign, whole, fraction, exponent = match.groups()
        token = match.group(0)
        digits = len((whole + fraction).lstrip("0")) or 1
        if exponent is None and digits < 17:
            return token  # a plain decimal the library wrote in its shortest form
        try:
            value = float(token)
        except ValueError:
            return token
        if digits >= 17 or value == 0.0:
            return repr(value)
        for candidate in known:
            if math.isfinite(candidate) and float("{:.{}e}".format(candidate, digits - 1)) == value:
                return repr(candidate)
        text = "{:.{}g}".format(value, digits)
        return text if any(c in text for c in ".ei") else text + ".0"

    return _NUMBER.sub(replace, message)


def text_out(function, *args, length=4096):
    """Call a function filling a text buffer (last two arguments: buffer, length)."""
    buffer = ctypes.create_string_buffer(length)
    check(function(*args, buffer, length))
    return buffer.value.decode("utf-8", "replace")


def doubles(array):
    """A C pointer to a contiguous float64 array."""
    return array.ctypes.data_as(_c_double_p)


def ints(array):
    """A C pointer to a contiguous C int array."""
    return array.ctypes.data_as(_c_int_p)


def sizes(array):
    """A C pointer to a contiguous size_t array."""
    return array.ctypes.data_as(_c_size_p)


def as_doubles(values):
    """A contiguous float64 copy-or-view of values."""
    return np.ascontiguousarray(values, dtype=np.float64)


def real_number(name, value):
    """A real number argument as a float: TypeError naming it for a bool, a complex number, a
    string, an array of more than one number or anything else that is not a real number."""
    if isinstance(value, (bool, np.bool_)):
        raise TypeError("{}: must be a real number, got a bool".format(name))
    if isinstance(value, (int, float, np.integer, np.floating)):
        return float(value)
    if isinstance(value, np.ndarray) and value.size == 1 and value.dtype.kind in "iuf":
        return float(value.reshape(()))
    if isinstance(value, (complex, np.complexfloating)) or (isinstance(value, np.ndarray) and
                                                             value.dtype.kind == "c"):
        raise TypeError("{}: must be a real number, got a complex number ({})".format(name, value))
    raise TypeError("{}: must be a real number, got {}".format(name, _described(value)))


def _described(value):
    """What a value is, for messages: its type and value, or an array's dtype and shape."""
    if isinstance(value, np.ndarray):
        return "an array of dtype {} and shape {}".format(value.dtype, value.shape)
    return "{} {!r}".format(type(value).__name__, value)[:120]


def real_array(name, value):
    """An argument of real numbers (a number, a nested list, an array of any real dtype and
    memory order) as a float64 array: TypeError naming it for complex entries (their
    imaginary part would be lost), booleans, strings or other objects; ValueError for a
    ragged nesting."""
    try:
        array = np.asarray(value)
    except (ValueError, TypeError) as error:
        raise ValueError("{}: not an array of numbers ({})".format(name, error)) from None
    kind = array.dtype.kind
    if kind == "c":
        raise TypeError("{}: must be real numbers, got complex ones (dtype {}): a complex value is refused, "
                        "never cut to its real part".format(name, array.dtype))
    if kind in "iuf":
        return array.astype(np.float64)
    if kind == "O":
        try:
            converted = array.astype(np.float64)
        except (ValueError, TypeError) as error:
            raise TypeError("{}: must be real numbers ({})".format(name, error)) from None
        if any(isinstance(x, (bool, np.bool_, complex, np.complexfloating)) for x in array.flat):
            raise TypeError("{}: must be real numbers, got {}".format(name, _described(value)))
        return converted
    raise TypeError("{}: must be real numbers, got {}".format(name, _described(array)))


INT = np.dtype(np.intc)
SIZE = np.dtype(np.uintp)
