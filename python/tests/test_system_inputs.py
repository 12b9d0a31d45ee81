"""Hostile input to hillstab.System and to the C functions behind it: a monodromy beyond the
double range is ±inf (never an OverflowError, nan or a warning); n must be an integer; complex
matrices are refused, never truncated; every TypeError and ValueError names its argument;
types, shapes, dtypes and memory orders fuzzed with a seeded loop; the C API's size_t
arguments at the limits of size_t and int refused with HILLSTAB_ERR_INVALID_PARAMETER."""
import ctypes
import random
import warnings

import numpy as np
import pytest

import hillstab
from hillstab import _capi

PAIR = dict(mass=np.diag([1.0, 0.25]), b=[[2.0, -1.0], [-1.0, 1.5]], cos=-np.diag([1.0, 0.5]))


def test_monodromy_beyond_double_range_is_inf():
    # alpha = 0, beta = -3e4: ln |lambda_max| = 2 sqrt(3e4 mu_max) ~ 905, beyond 709
    pair = hillstab.System(**PAIR)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        phi, estimate, status = pair.monodromy(0.0, -3.0e4, method="magnus4", tolerance=1e-8)
        f = pair.floquet(0.0, -3.0e4, method="magnus4", tolerance=1e-8)
    assert f.log_scale > 709.0
    assert np.isinf(phi).any() and not np.isnan(phi).any()
    assert np.isposinf(phi).any() and np.isneginf(phi).any()
    assert status in (0, 1)
    # below the double range the scaled entries are exact products
    phi_mid, _, _ = pair.monodromy(0.0, -5.0e3, method="magnus4", tolerance=1e-8)
    f_mid = pair.floquet(0.0, -5.0e3, method="magnus4", tolerance=1e-8)
    assert np.isfinite(phi_mid).all()
    # its largest multiplier is e^(P mu), P = 2
    assert np.log(np.abs(np.linalg.eigvals(phi_mid)).max()) == pytest.approx(2.0 * f_mid.exponents[0], rel=1e-6)


@pytest.mark.parametrize("n", [2.7, 2.5, 1.0000001, float("nan"), float("inf"), np.float64(2.5)])
def test_non_integral_n_refused(n):
    with pytest.raises(ValueError, match=r"^n: the degrees of freedom must be an integer"):
        hillstab.System(n=n, cos=np.eye(2))


@pytest.mark.parametrize("n", [2, 2.0, np.int64(2), np.float32(2.0), np.array(2)])
def test_integral_n_accepted(n):
    assert hillstab.System(n=n, cos=np.eye(2)).n == 2


@pytest.mark.parametrize("n, error", [("2", TypeError), (True, TypeError), (None, ValueError), (2j, TypeError),
                                      ([2], TypeError)])
def test_n_of_another_type_named(n, error):
    with pytest.raises(error, match=r"^n: "):
        hillstab.System(n=n)


@pytest.mark.parametrize("name", ["mass", "damping", "gyroscopic", "k0", "b", "cos", "sin"])
def test_complex_matrix_refused(name):
    values = dict(PAIR)
    values[name] = np.asarray(values.get(name, np.zeros((2, 2))), dtype=np.complex128) + 0.0j
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(TypeError, match=r"^{}: must be real numbers, got complex".format(name)):
            hillstab.System(**values)


def test_empty_mass_blames_mass():
    with pytest.raises(ValueError, match=r"^mass: must be an n x n array"):
        hillstab.System(mass=np.zeros((0, 0)), cos=np.eye(2))
    with pytest.raises(ValueError, match=r"^cos: must be an \(H, n, n\) array"):
        hillstab.System(cos=np.zeros((0, 2, 2)))


@pytest.mark.parametrize("options, name, error", [
    (dict(mass="abc"), "mass", TypeError),
    (dict(k0=object()), "k0", TypeError),
    (dict(b=[["a", "b"], ["c", "d"]]), "b", TypeError),
    (dict(damping=np.eye(2, dtype=bool)), "damping", TypeError),
    (dict(gyroscopic={"a": 1}), "gyroscopic", TypeError),
    (dict(mass=[[1.0, 0.0], [0.0]]), "mass", ValueError),
    (dict(mass=np.array([[1.0, 0.0], [0.0, 1.0j]], dtype=object)), "mass", TypeError),
    (dict(mass=[1.0, 1.0]), "mass", ValueError),
    (dict(mass=np.ones((2, 3))), "mass", ValueError),
    (dict(sin=np.ones((2, 2, 2, 2))), "sin", ValueError),
    (dict(period="2"), "period", TypeError),
    (dict(period=2j), "period", TypeError),
    (dict(period=None), "period", TypeError),
])
def test_constructor_errors_name_the_argument(options, name, error):
    values = dict(cos=np.eye(2))
    values.update(options)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(error, match=r"^{}: ".format(name)):
            hillstab.System(**values)


@pytest.mark.parametrize("call, name", [
    (lambda s: s.floquet(1j, 1.0), "alpha"),
    (lambda s: s.monodromy(0.3, "1.0"), "beta"),
    (lambda s: s.floquet(0.3, 1.0, epsilon="0.1"), "epsilon"),
    (lambda s: s.monodromy(0.3, 1.0, tolerance=None), "tolerance"),
    (lambda s: s.floquet(0.3, 1.0, method=["auto"]), "method"),
    (lambda s: s.floquet(True, 1.0), "alpha"),
])
def test_call_type_errors_name_the_argument(call, name):
    system = hillstab.System(**PAIR)
    with pytest.raises(TypeError, match=r"^{}: ".format(name)):
        call(system)


def reference_floquet():
    return hillstab.System(**PAIR).floquet(0.7, 1.1, tolerance=1e-11)


@pytest.mark.parametrize("convert", [
    lambda a: np.asfortranarray(np.asarray(a, dtype=np.float64)),
    lambda a: np.repeat(np.repeat(np.asarray(a, dtype=np.float64), 2, axis=-1), 2, axis=-2)[..., ::2, ::2],
    lambda a: np.asarray(a, dtype=np.float32),
    lambda a: np.asarray(a, dtype=">f8"),
    lambda a: np.asarray(a, dtype=np.float64).astype(object),
    lambda a: np.asarray(a, dtype=np.float64).tolist(),
])
def test_orders_and_dtypes_give_the_same_system(convert):
    expected = reference_floquet()
    values = {name: convert(value) for name, value in PAIR.items()}
    f = hillstab.System(**values).floquet(0.7, 1.1, tolerance=1e-11)
    assert f.trace == expected.trace and f.a2 == expected.a2 and f.verdict == expected.verdict


def bad_or_good_value(rng, n):
    """A value for a matrix argument: good (of several dtypes and orders) or hostile."""
    good = np.eye(n) * rng.uniform(0.5, 2.0)
    choices = [
        lambda: good,
        lambda: np.asfortranarray(good),
        lambda: good.astype(np.float32),
        lambda: good.astype(np.int64),
        lambda: good.astype(">f8"),
        lambda: good.tolist(),
        lambda: good.astype(np.complex128),
        lambda: good.astype(bool),
        lambda: good.astype(str),
        lambda: np.zeros((0, 0)),
        lambda: np.zeros((n, n + 1)),
        lambda: np.zeros(n),
        lambda: np.full((n, n), np.nan),
        lambda: np.full((n, n), 1e308) * rng.choice([1.0, -1.0]),
        lambda: rng.uniform(-1.0, 1.0),
        lambda: "mass",
        lambda: None,
        lambda: object(),
        lambda: [[1.0] * n] * (n - 1) + [[1.0]],
        lambda: np.eye(n)[::-1],
        lambda: np.eye(2 * n)[::2, ::2],
    ]
    return choices[rng.randrange(len(choices))]()


def test_fuzz_constructor_and_calls():
    # seeded: the same 400 cases on every run
    rng = random.Random(4801)
    outcomes = {"built": 0, "refused": 0}
    arguments = ["mass", "damping", "gyroscopic", "k0", "b", "cos", "sin"]
    for case in range(400):
        n = rng.randint(1, 3)
        values = {"cos": np.eye(n)}
        for name in rng.sample(arguments, rng.randint(1, 3)):
            value = bad_or_good_value(rng, n)
            if value is not None:
                values[name] = value
        if rng.random() < 0.2:
            values["n"] = rng.choice([n, float(n), n + 0.5, "n", -1, 0, 21, True])
        if rng.random() < 0.1:
            values["period"] = rng.choice([2, 4.0, 3.0, "2", 1j, -2.0, float("inf")])
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            try:
                system = hillstab.System(**values)
            except (TypeError, ValueError) as error:
                message = str(error)
                named = [name for name in list(values) + ["n", "period"]
                         if message.startswith(name + ": ") or message.startswith("hillstab_system_set: " + name)
                         or message.startswith("hillstab_system_check: ")]
                assert named, "case {}: {!r} names no argument: {}".format(case, sorted(values), message)
                outcomes["refused"] += 1
                continue
            outcomes["built"] += 1
            alpha = rng.choice([0.3, -1.0, 1j, "x", np.float32(0.5), np.nan, 1e300])
            beta = rng.choice([1.0, 0.0, -4.0, np.int64(2), None])
            try:
                f = system.floquet(alpha, beta, tolerance=1e-8)
                phi, _, _ = system.monodromy(alpha, beta, tolerance=1e-8)
            except (TypeError, ValueError) as error:
                assert str(error).split(":")[0] in ("alpha", "beta") or "hillstab_system" in str(error), str(error)
                continue
            except hillstab.HillstabError as error:
                # a computation that failed (a system far outside what the methods integrate)
                assert str(error), "case {}: a failure without a message".format(case)
                continue
            assert f.verdict in (-1, 0, 1)
            assert not np.isnan(phi).any()
    assert outcomes["built"] > 20 and outcomes["refused"] > 100, outcomes


SIZE_MAX = ctypes.c_size_t(-1).value
# SIZE_MAX, SIZE_MAX - 1, 2^63, 2^63 - 1, 2^32, 2^32 - 1, INT_MAX + 1, INT_MAX
LIMITS = [SIZE_MAX, SIZE_MAX - 1, 2 ** 63, 2 ** 63 - 1, 2 ** 32, 2 ** 32 - 1, 2 ** 31, 2 ** 31 - 1]


def test_c_sizes_at_the_limits():
    lib = _capi.lib
    system = hillstab.System(**PAIR)
    before = system.floquet(0.7, 1.1).trace
    values = np.full(4, 4.0)
    model = _capi._model_p()
    assert lib.hillstab_model_new(b"fourier", ctypes.byref(model)) == 0
    out = np.full((3, _capi.VALUE_COUNT), -7.0)
    status = np.full(3, -7, dtype=_capi.INT)
    points = np.ones(3)
    rng = random.Random(4802)
    for size in LIMITS + [rng.randrange(2 ** 31, 2 ** 64) for _ in range(20)]:
        text = str(size)
        code = lib.hillstab_system_set(system.handle, b"mass", _capi.doubles(values), size)
        assert code == _capi.ERR_INVALID_PARAMETER, size
        assert _capi.last_error()[1].startswith("hillstab_system_set: count = " + text + " exceeds the limit ")
        code = lib.hillstab_model_set(model, b"cos", _capi.doubles(values), size)
        assert code == _capi.ERR_INVALID_PARAMETER
        assert _capi.last_error()[1].startswith("count = " + text + " exceeds the limit ")
        code = lib.hillstab_points(model, size, _capi.doubles(points), _capi.doubles(points), _capi.doubles(points),
                                   0, 2, 1, 1e-10, 3, 0, 0, _capi.doubles(out), _capi.ints(status))
        assert code == _capi.ERR_INVALID_PARAMETER
        assert _capi.last_error()[1].startswith("n = " + text + " exceeds the limit 100000000")
    assert np.all(out == -7.0) and np.all(status == -7)
    assert system.floquet(0.7, 1.1).trace == before
    buffer = ctypes.create_string_buffer(512)
    lib.hillstab_model_set(model, b"none", _capi.doubles(values), 1)
    assert lib.hillstab_last_error(buffer, SIZE_MAX) == _capi.ERR_INVALID_PARAMETER
    assert b"has no variable 'none'" in buffer.value
    lib.hillstab_model_free(model)


@pytest.mark.parametrize("call, name", [
    (lambda: hillstab.trace(1j, 2.47), "alpha"),
    (lambda: hillstab.floquet([3.7, 2.0 + 1j], 2.47), "alpha"),
    (lambda: hillstab.floquet(3.7, "2.47"), "beta"),
    (lambda: hillstab.trace(3.7, 2.47, epsilon=[True]), "epsilon"),
    (lambda: hillstab.trace(3.7, 2.47, tolerance="1e-10"), "tolerance"),
    (lambda: hillstab.chart((0.0, 1.0, 2), (0.0, 1.0, 2), epsilon=0.1j), "epsilon"),
    (lambda: hillstab.chart((0.0, 1j, 2), (0.0, 1.0, 2)), "alpha"),
])
def test_scalar_functions_name_their_arguments(call, name):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(TypeError, match=r"^{}: ".format(name)):
            call()
