"""Systems of Hill equations from Python (hillstab.System over the hillstab_system_* C
functions): one degree of freedom is the scalar Mathieu equation, a decoupled pair has the
multipliers of its two scalar equations, and bad input raises ValueError naming the argument."""
import numpy as np
import pytest

import hillstab

POINTS = [(0.3, 1.2), (2.5, 4.0), (0.9, 0.25), (6.0, 0.5), (1.0, 2.47)]


def mathieu_as_system(**options):
    # x'' + (beta - alpha cos pi tau) x = 0: B = 1, K_1c = -1
    return hillstab.System(mass=[[1.0]], b=[[1.0]], cos=[[[-1.0]]], **options)


def scalar_multipliers(s):
    root = np.sqrt(complex(s * s - 4.0))
    return np.array([(s + root) / 2.0, (s - root) / 2.0])


@pytest.mark.parametrize("alpha, beta", POINTS)
def test_one_dof_is_mathieu_trace(alpha, beta):
    system = mathieu_as_system()
    expected = hillstab.trace(alpha, beta, model="mathieu", tolerance=1e-12)
    f = system.floquet(alpha, beta, tolerance=1e-11)
    assert f.trace == pytest.approx(float(expected), rel=1e-9, abs=1e-9)
    phi, estimate, status = system.monodromy(alpha, beta, tolerance=1e-11)
    assert phi.shape == (2, 2)
    assert status in (0, 1) and estimate < 1e-9
    assert np.trace(phi) == pytest.approx(float(expected), rel=1e-9, abs=1e-9)
    # Hamiltonian: det Phi = 1
    assert np.linalg.det(phi) == pytest.approx(1.0, abs=1e-8 * max(1.0, np.abs(phi).max() ** 2))
    assert f.stable == (abs(float(expected)) < 2.0)


def test_one_dof_damped_trace():
    # with damping eps the trace of Phi is exp(-eps P/2) S1 (S1 of the chi equation)
    system = mathieu_as_system()
    for alpha, beta in POINTS[:3]:
        s1 = hillstab.trace(alpha, beta, model="mathieu", epsilon=0.3, tolerance=1e-12)
        f = system.floquet(alpha, beta, epsilon=0.3, tolerance=1e-11)
        assert f.trace == pytest.approx(np.exp(-0.3) * float(s1), rel=1e-9, abs=1e-9)


def test_decoupled_pair_has_the_scalar_multipliers():
    a, b = np.array([1.0, 0.5]), np.array([1.0, 3.0])
    pair = hillstab.System(b=np.diag(b), cos=-np.diag(a))
    assert pair.n == 2
    for alpha, beta in POINTS:
        f = pair.floquet(alpha, beta, tolerance=1e-11)
        assert f.multipliers.shape == (4,) and f.exponents.shape == (2,)
        expected = np.concatenate([scalar_multipliers(float(hillstab.trace(a[i] * alpha, b[i] * beta,
                                                                           model="mathieu", tolerance=1e-13)))
                                   for i in range(2)])
        computed = f.multipliers * np.exp(f.log_scale)
        for lam in expected:
            assert np.min(np.abs(computed - lam)) <= 1e-7 * max(1.0, abs(lam))
        # by decreasing modulus, their sum the trace
        assert np.all(np.diff(np.abs(f.multipliers)) <= 1e-12 * np.abs(f.multipliers).max())
        assert f.trace == pytest.approx(computed.sum().real, rel=1e-9, abs=1e-9)
        unstable = np.abs(expected).max() > 1.0 + 1e-6
        if f.verdict != hillstab.system.VERDICT_MARGINAL:
            assert f.stable == (not unstable)


def test_monodromy_methods_agree():
    pair = hillstab.System(mass=np.diag([1.0, 0.64]), b=[[1.1, -0.1], [-0.1, 0.9]], cos=-np.diag([1.0, 0.8]),
                           gyroscopic=[[0.0, 0.3], [-0.3, 0.0]])
    reference, _, _ = pair.monodromy(0.9, 0.25, method="rk", tolerance=1e-11)
    for method in ("auto", "magnus4", "magnus6", "gsl"):
        phi, estimate, status = pair.monodromy(0.9, 0.25, method=method, tolerance=1e-10)
        assert phi.shape == (4, 4) and status == 0
        assert np.abs(phi - reference).max() <= 1e-8 * max(1.0, np.abs(reference).max())


def test_damped_pair_is_damped():
    pair = hillstab.System(mass=np.diag([1.0, 0.64]), b=[[1.1, -0.1], [-0.1, 0.9]], cos=-np.diag([1.0, 0.8]))
    f = pair.floquet(0.3, 1.2, epsilon=0.5)
    assert f.verdict == hillstab.system.VERDICT_STABLE and f.kind == hillstab.system.KIND_DAMPED
    assert np.all(f.exponents < 0)


def test_mass_not_positive_definite_names_mass():
    with pytest.raises(ValueError, match="mass"):
        hillstab.System(mass=[[1.0, 0.0], [0.0, -1.0]], cos=np.eye(2))
    with pytest.raises(ValueError, match="mass: M must be positive definite"):
        hillstab.System(mass=[[1.0, 2.0], [2.0, 1.0]], cos=np.eye(2))


@pytest.mark.parametrize("options, word", [
    (dict(damping=[[1.0, 0.5], [0.0, 1.0]]), "damping"),
    (dict(gyroscopic=[[0.0, 1.0], [1.0, 0.0]]), "gyroscopic"),
    (dict(mass=np.eye(2), k0=np.eye(3)), "k0"),
    (dict(period=3.0), "period"),
])
def test_bad_matrices_named(options, word):
    with pytest.raises(ValueError, match=word):
        hillstab.System(cos=np.eye(2), **options)


def test_bad_point_and_method_named():
    system = mathieu_as_system()
    with pytest.raises(ValueError, match="tolerance"):
        system.floquet(0.3, 1.0, tolerance=0.0)
    with pytest.raises(ValueError, match="tolerance"):
        system.monodromy(0.3, 1.0, tolerance=1e-16)
    with pytest.raises(ValueError, match="method"):
        system.floquet(0.3, 1.0, method="segments")
    with pytest.raises(ValueError, match="alpha"):
        system.floquet(float("nan"), 1.0)
    with pytest.raises(ValueError, match="beta"):
        system.monodromy(0.3, float("inf"))
    with pytest.raises(ValueError, match="epsilon"):
        system.floquet(0.3, 1.0, epsilon=-0.1)
    # still usable
    assert system.floquet(0.3, 1.0).status == 0
