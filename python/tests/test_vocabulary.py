"""One vocabulary: Python's values are named as the columns of the command line's chart and
points files (what read_output returns) and as the C API's HILLSTAB_VALUE_S, _MU, ...; the
earlier names (trace, log_abs_trace, log10_abs_trace, exponent) are aliases for this
release, giving the same arrays, in values= and as attributes."""
import os
import sys
import warnings

import numpy as np
import pytest

import hillstab
from hillstab import ALIASES, ALL_VALUES

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
#: the values no file column holds, named in the files' style or by what they are
NO_COLUMN = {"log_abs_S", "log_moduli"}
ALPHA = np.array([0.5, 3.7, 9.0, 4.0, 7.5])
BETA = np.array([-1.0, 2.47, 2.47, 30.0, 8.0])


def same_bits(a, b):
    a = np.ascontiguousarray(a, dtype=np.float64).ravel()
    b = np.ascontiguousarray(b, dtype=np.float64).ravel()
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def test_names_are_the_files_columns(cli):
    columns = [name for name in ALL_VALUES if name not in NO_COLUMN]
    scene = ("&scene task = 'chart', model = 'mathieu', epsilon = 0.2, output = 'all', format = 'binary', "
             "columns = 'alpha beta {} status' /\n"
             "&chart alpha_min = 0.0, alpha_max = 9.0, n_alpha = 4, beta_min = -2.0, beta_max = 12.0, n_beta = 6 /\n"
             ).format(" ".join(columns))
    cli.run("all", scene)
    out = hillstab.read_output(cli.path("all_chart.bin"))
    assert set(columns) <= set(out.columns)
    c = hillstab.chart((0.0, 9.0, 4), (-2.0, 12.0, 6), model="mathieu", epsilon=0.2, threads=2)
    assert c.names == ALL_VALUES
    for name in columns:
        assert same_bits(out[name], getattr(c, name)), name
        assert same_bits(out[name], c[name]), name


def test_old_names_give_the_same_arrays():
    r = hillstab.floquet(ALPHA, BETA, model="elastic", epsilon=0.1)
    for old, new in ALIASES.items():
        assert same_bits(getattr(r, old), getattr(r, new)), old
        assert same_bits(r[old], r[new]), old
    assert np.allclose(r.log_abs_S, np.log(np.abs(r.S)), rtol=1e-14, atol=1e-14)


def test_values_take_either_name():
    new = hillstab.floquet(ALPHA, BETA, model="elastic", values=("S", "mu", "log10_abs_S", "log_abs_S"))
    old = hillstab.floquet(ALPHA, BETA, model="elastic",
                           values=("trace", "exponent", "log10_abs_trace", "log_abs_trace"))
    mixed = hillstab.floquet(ALPHA, BETA, model="elastic", values=("trace", "mu", "S"))
    # the names are the files' whichever were asked for, each once
    assert new.names == old.names == ("S", "mu", "log10_abs_S", "log_abs_S")
    assert mixed.names == ("S", "mu")
    for name in new.names:
        assert same_bits(getattr(new, name), getattr(old, name)), name
    assert same_bits(mixed.trace, new.S) and same_bits(mixed.exponent, new.mu)
    c_new = hillstab.chart((0.0, 9.0, 3), (-1.0, 5.0, 4), model="elastic", values=("S",))
    c_old = hillstab.chart((0.0, 9.0, 3), (-1.0, 5.0, 4), model="elastic", values=("trace",))
    assert c_new.names == c_old.names == ("S",)
    assert same_bits(c_new.S, c_old.trace)
    with pytest.raises(AttributeError, match="not asked for"):
        c_new.exponent
    with pytest.raises(ValueError, match="unknown value"):
        hillstab.floquet(ALPHA, BETA, model="elastic", values=("Trace",))


def test_no_warning_from_the_package():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = hillstab.floquet(ALPHA, BETA, model="elastic", values=("exponent", "trace"))
        r.trace, r.exponent, r.S, r.mu
        hillstab.trace(3.7, 2.47, model="elastic")
        hillstab.Spring(k=25, m=0.25, r0=0.3, g=9.81).growth_per_second([0.02])


def test_every_value_documented_with_its_convention():
    """One table, in floquet's module docstring and on the guide page: every value, what it
    is of (χ = e^{ετ/2} x or x), and its earlier name."""
    guide = open(os.path.join(ROOT, "docs", "guide", "python.md"), encoding="utf-8").read()
    module = sys.modules["hillstab.floquet"].__doc__
    tables = [
        {line.split()[0]: line for line in module.splitlines() if line.split() and line.split()[0] in ALL_VALUES},
        {line.split("|")[1].strip(" `"): line for line in guide.splitlines() if line.startswith("| `")}]
    for rows in tables:
        for name in ALL_VALUES:
            assert name in rows, name
            of = rows[name].replace("|", " ").split()[1]
            assert of in ("χ", "x"), rows[name]
        for old, new in ALIASES.items():
            assert old in rows[new], (old, new)
        assert all(rows[name].replace("|", " ").split()[1] == "x" for name in ("stable", "lambda_max", "log_moduli", "mu"))
        assert all(rows[name].replace("|", " ").split()[1] == "χ" for name in ("S", "log10_abs_S", "stable_paper"))
