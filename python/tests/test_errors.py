"""Bad input raises ValueError with the library's message (the same text the per-point C
entry points and the command line give); failed points are statuses, not NaN; thread counts
do not change any value; models, transition curves and Mathieu's characteristic values."""
import ctypes
import math
import re
import subprocess
import warnings

import numpy as np
import pytest

import hillstab
from hillstab import _capi

from test_values import same_bits


def per_point_message(alpha, beta, epsilon=0.0, model=1, method=0, tolerance=1e-10):
    """The message hillstab_trace (one point, a model code) leaves in hillstab_last_error, its
    numbers in Python's format as the package gives them (`_capi.python_numbers`)."""
    s, log_abs, overflow = ctypes.c_double(), ctypes.c_double(), ctypes.c_int()
    status = _capi.lib.hillstab_trace(model, alpha, beta, epsilon, method, 2, 1, tolerance, ctypes.byref(s),
                                      ctypes.byref(log_abs), ctypes.byref(overflow))
    assert status == 1
    raw = _capi.last_error()[1]
    assert "1.0000000000000000E+01" in raw or alpha != 10.0  # the library's own format
    return _capi.python_numbers(raw, [alpha, beta, epsilon, tolerance])


def test_point_outside_domain():
    message = per_point_message(10.0, 1.0)
    assert "alpha" in message and message
    with pytest.raises(ValueError) as caught:
        hillstab.floquet([1.0, 10.0], [1.0, 1.0])
    assert message in str(caught.value)
    assert "point 1 (alpha = 10" in str(caught.value)
    with pytest.raises(ValueError) as caught:
        hillstab.chart((0.0, 10.0, 3), (0.0, 1.0, 3))
    assert message.split(",")[0] in str(caught.value)
    with pytest.raises(ValueError, match="epsilon must be >= 0"):
        hillstab.floquet(1.0, 1.0, epsilon=-1.0)
    with pytest.raises(ValueError, match="must be finite"):
        hillstab.floquet(1.0, np.nan)


def test_bad_method_settings():
    message = per_point_message(1.0, 1.0, tolerance=2.0)
    with pytest.raises(ValueError) as caught:
        hillstab.floquet(1.0, 1.0, tolerance=2.0)
    assert message in str(caught.value) and "method 'auto'" in str(caught.value)
    with pytest.raises(ValueError, match="n_segments must lie in"):
        hillstab.chart((0.0, 1.0, 2), (0.0, 1.0, 2), method="segments", n_segments=0)
    with pytest.raises(ValueError, match="unknown method 'fast'"):
        hillstab.floquet(1.0, 1.0, method="fast")
    with pytest.raises(ValueError, match="unknown value"):
        hillstab.floquet(1.0, 1.0, values=("S1",))


def test_models():
    assert hillstab.model_names()[:3] == ["elastic", "mathieu", "meissner"]
    m = hillstab.Model("Mathieu")
    assert m.name == "mathieu" and "cos" in m.formula and m.variables == {}
    names = hillstab.model_names()
    expected = ", ".join(names[:-1]) + " or " + names[-1]
    with pytest.raises(ValueError, match=re.escape("unknown model 'pendulum' (expected " + expected + ")")):
        hillstab.Model("pendulum")
    with pytest.raises(ValueError, match="the elastic model has no variable 'c'"):
        hillstab.Model("elastic").set("c", [1.0, 2.0])
    hillstab.Model("elastic").check()
    # a model by name or as an object gives the same values
    assert same_bits(hillstab.trace(3.0, 2.0, model="mathieu"), hillstab.trace(3.0, 2.0, model=m))
    # Q of the model at a point: the elastic coefficient's formula
    e = hillstab.Model("elastic")
    q = (2.0 - 3.0 * math.cos(math.pi * 0.3)) / (1.0 - 3.0 / math.pi ** 2 * math.cos(math.pi * 0.3))
    assert abs(e.q(0.3, 3.0, 2.0) - q) < 1e-14


def test_bad_scene_message(cli):
    text = "&scene task = 'chart', output = 'bad' /\n&chart alpha_min = 0, alpha_max = 12, n_alpha = 3 /\n"
    done = cli.run("bad", text, expect=2)
    message = done.stderr.strip().splitlines()[-1]
    with pytest.raises(ValueError) as caught:
        hillstab.run_scene(cli.path("bad.nml"))
    # the command line's words, the numbers in Python's format (9.8696044010893586 there)
    assert str(caught.value) in _capi.python_numbers(message) and "&chart" in str(caught.value)
    assert "alpha_max" in str(caught.value) and "pi**2 = 9.869604401089358 " in str(caught.value)
    assert not list(__import__("pathlib").Path(cli.directory).glob("bad_chart*"))
    with pytest.raises(ValueError, match="missing.nml"):
        hillstab.run_scene(cli.path("missing.nml"))


def test_roundoff_status_is_flagged(cli):
    # beta ~ 0 with alpha -> pi^2 at tolerance 1e-12: round-off limited (status 1), never NaN
    alpha = np.array([9.86, 9.869, 5.0])
    beta = np.array([1e-6, 1e-8, 2.0])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = hillstab.floquet(alpha, beta, tolerance=1e-13)
    assert np.all(np.isfinite(r.trace)) and np.all(np.isfinite(r.error_estimate))
    assert r.status[0] == 1 and r.status[2] == 0
    assert any(issubclass(w.category, hillstab.HillstabWarning) for w in caught)
    with open(cli.path("hard.txt"), "w") as handle:
        for a, b in zip(alpha, beta):
            handle.write("{!r} {!r}\n".format(float(a), float(b)))
    cli.run("hard", "&scene task = 'points', tolerance = 1e-13, output = 'hard', format = 'binary' /\n"
                    "&points file = 'hard.txt' /\n")
    out = hillstab.read_output(cli.path("hard_points.bin"))
    assert same_bits(out["status"], r.status) and same_bits(out["S"], r.trace)


def test_threads_do_not_change_results():
    grid = ((0.0, 9.8, 10), (-2.0, 12.0, 50))
    charts = [hillstab.chart(*grid, model="elastic", threads=n) for n in (1, 2, 3, 5)]
    verdicts = [hillstab.chart(*grid, model="elastic", values=("stable",), threads=n) for n in (1, 2, 3, 5)]
    for c in charts[1:]:
        for name in c.names:
            assert same_bits(getattr(c, name), getattr(charts[0], name)), name
    for c in verdicts[1:]:
        assert same_bits(c.stable, verdicts[0].stable)
    rng = np.random.default_rng(1)
    alpha, beta = rng.uniform(0, 9.8, 400), rng.uniform(-2, 40, 400)
    points = [hillstab.floquet(alpha, beta, model="elastic", threads=n) for n in (1, 2, 4)]
    for r in points[1:]:
        assert same_bits(r.trace, points[0].trace) and same_bits(r.exponent, points[0].exponent)
    curves = [hillstab.transition_curves(np.linspace(0, 9.5, 7), -2, 40, threads=n) for n in (1, 3)]
    assert same_bits(curves[0].beta, curves[1].beta)


def test_transition_curves_closed_form():
    # alpha = 0: Q = beta, the curves are beta = (n pi/2)^2, every tongue closed
    c = hillstab.transition_curves(0.0, -2.0, 100.0, tolerance=1e-12)
    assert c.count[0] == 13
    assert np.allclose(c.beta, (c.order * math.pi / 2) ** 2, rtol=1e-13, atol=1e-13)
    assert np.all(c.trace_sign == np.where(c.order % 2 == 0, 2, -2))
    # the curves bound the tongues: S = +-2 there to the tolerance
    d = hillstab.transition_curves([3.0, 7.0], -2.0, 30.0)
    s = hillstab.trace(d.alpha, d.beta, model="elastic", tolerance=1e-12)
    assert np.allclose(s, d.trace_sign, atol=1e-7)
    with pytest.raises(ValueError):
        hillstab.transition_curves(10.0, -2.0, 30.0)


def test_mathieu_characteristic_values():
    # published values (as the Fortran suite's hill_method test)
    assert abs(hillstab.mathieu_a(0, 1.0) - -0.455138604107) < 1e-11
    assert abs(hillstab.mathieu_b(1, 1.0) - -0.110248816992) < 1e-11
    assert abs(hillstab.mathieu_a(1, 1.0) - 1.859108072514) < 1e-11
    assert abs(hillstab.mathieu_b(2, 1.0) - 3.917024772998) < 1e-11
    q = np.array([10.0, 25.0])
    assert np.allclose(hillstab.mathieu_a(0, q), [-13.936979956659, -40.256779546567], atol=1e-10)
    assert abs(hillstab.mathieu_a(1, 25.0) - -21.314899690666) < 1e-10
    # q = 0: m^2; each branch stays on itself as q grows (a_m < b_{m+1} < a_{m+1} ordering of the
    # periodic/antiperiodic families) and the coexisting pairs approach each other
    assert np.allclose(hillstab.mathieu_a(3, 0.0), 9.0)
    big = np.linspace(0.0, 200.0, 21)
    a2, b3 = hillstab.mathieu_a(2, big), hillstab.mathieu_b(3, big)
    assert np.all(a2 < b3 + 1e-9)
    with pytest.raises(ValueError):
        hillstab.mathieu_b(0, 1.0)


def test_help_is_everywhere():
    """Every public module, function, class, method and property has a docstring."""
    import inspect
    modules = [hillstab] + [getattr(hillstab, name) for name in ("models", "floquet", "curves", "spring", "scenes",
                                                                 "errors")]
    missing = []
    for module in modules:
        if not module.__doc__:
            missing.append(module.__name__)
        for name, obj in vars(module).items():
            if name.startswith("_") or not getattr(obj, "__module__", "").startswith("hillstab"):
                continue
            if inspect.isfunction(obj) or inspect.isclass(obj):
                if not obj.__doc__:
                    missing.append(module.__name__ + "." + name)
                for member, value in (vars(obj).items() if inspect.isclass(obj) else ()):
                    if not member.startswith("_") and (inspect.isfunction(value) or isinstance(value, property)) \
                            and not value.__doc__:
                        missing.append(module.__name__ + "." + name + "." + member)
    assert not missing
    for name in hillstab.__all__:
        assert getattr(hillstab, name).__doc__, name


def test_concurrent_calls_from_python_threads():
    """Calls from several Python threads at once (ctypes releases the GIL: they run inside the
    library together) give the serial values, and each thread gets its own error message."""
    from concurrent.futures import ThreadPoolExecutor
    grid = ((0.0, 9.8, 12), (-2.0, 12.0, 30))
    serial = hillstab.chart(*grid, model="elastic", threads=1)

    def good(_):
        return hillstab.chart(*grid, model="elastic", threads=1).trace

    def bad(k):
        try:
            hillstab.floquet([1.0, 10.0 + k], [1.0, 1.0])
        except ValueError as error:
            return str(error)
        return ""

    with ThreadPoolExecutor(max_workers=4) as pool:
        traces = list(pool.map(good, range(4)))
        messages = list(pool.map(bad, range(4)))
    assert all(same_bits(t, serial.trace) for t in traces)
    for k, message in enumerate(messages):
        assert message.startswith("point 1 (alpha = {!r}".format(10.0 + k)), message
