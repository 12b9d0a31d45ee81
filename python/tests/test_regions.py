"""Resonance regions from Python: the damped Mathieu equation written as an Equation,
x'' + 2ζx' + (1 + h cos Wt) x = 0, has its principal region's tip at W ≈ 2, h = 4ζ (first
order; within 1e-3 relative at ζ = 0.01), the same through Equations and a System of one
degree of freedom; the undamped Mathieu model's tips are its resonances β = (kπ/2)² at drive 0
(status 'theory'); bad input raises naming the argument."""
import math

import numpy as np
import pytest

import hillstab
from hillstab import curves

ZETA = 0.01


def damped_mathieu():
    return hillstab.Equation("1 + h*cos(W*t)", frequency="W", damping="2*zeta",
                             parameters="zeta = 0.01, h = 0, W = 2", alpha="W", beta="h")


def principal(r):
    """The index of the simple region of order 1."""
    hits = np.flatnonzero((r.kind == hillstab.curves.REGION_SIMPLE) & (r.order == 1))
    assert hits.size == 1
    return int(hits[0])


def check_principal(r):
    k = principal(r)
    assert r.status_name[k] == "found" and r.status[k] == curves.REGION_FOUND
    assert abs(r.drive[k] - 4 * ZETA) < 1e-3 * 4 * ZETA
    assert abs(r.frequency[k] - 2.0) < 1e-2
    assert r.drive_error[k] < 1e-3 * r.drive[k]
    assert r.window[k, 0] < r.frequency[k] < r.window[k, 1]
    # open at the top drive around its tip
    assert r.edges[k, 0] < r.frequency[k] < r.edges[k, 1]
    return k


def test_equation_principal_tip():
    r = hillstab.regions(damped_mathieu(), frequency=(0.5, 3.0), drive=(0.0, 0.5), order=3)
    assert r.drive_axis == 2
    assert len(r) >= 3 and np.all(np.diff(r.predicted) >= 0)
    assert set(r.kind_name) == {"simple"} and np.all(r.modes == 1)
    # orders 1, 2, 3 at W = 2/k (the damped frequency's), each predicted once
    assert sorted(r.order.tolist()) == [1, 2, 3]
    k = check_principal(r)
    # the tips by the equation's axes: W the frequency, h the drive; and by alpha, beta
    assert r.W[k] == r.frequency[k] == r.alpha[k] and r.h[k] == r.drive[k] == r.beta[k]
    assert r.modes.shape == (len(r), 2) and r.edges.shape == (len(r), 2) and r.clipped.dtype == bool


def test_equations_and_system_of_one_degree():
    e = hillstab.regions(damped_mathieu(), frequency=(0.5, 3.0), drive=(0.0, 0.5), order=3)
    k = principal(e)
    one = hillstab.Equations("1 + h*cos(W*t)", frequency="W", damping="2*zeta",
                             parameters={"zeta": ZETA, "h": 0.0, "W": 2.0}, alpha="W", beta="h", n=1)
    for r in (one.regions((0.5, 3.0), (0.0, 0.5), order=3), hillstab.regions(one, (0.5, 3.0), (0.0, 0.5), order=3)):
        assert r.drive_axis == 2
        j = check_principal(r)
        assert r.W[j] == r.frequency[j] and r.h[j] == r.drive[j]
        assert abs(r.drive[j] - e.drive[k]) < 1e-6 * e.drive[k]
        assert abs(r.frequency[j] - e.frequency[k]) < 1e-4
    # a matrix system, x'' + c x' + (β + α cos πτ) x = 0 (k0 = 0, b = 1, the drive on α): the
    # drive is α, the frequency β; resonant at β = (π/2)² + c²/4, its tip α ≈ 2c√β (first order)
    c = 0.05
    s = hillstab.System(damping=[[c]], cos=[[1.0]])
    r = s.regions(frequency=(1.5, 3.5), drive=(0.0, 1.0), order=1)
    assert r.drive_axis == 1 and len(r) == 1
    assert abs(r.predicted[0] - (math.pi ** 2 + c * c) / 4) < 1e-9
    assert r.status_name[0] == "found"
    assert abs(r.drive[0] - 2 * c * math.sqrt(r.frequency[0])) < 0.01 * r.drive[0] + 1e-3
    assert r.alpha[0] == r.drive[0] and r.beta[0] == r.frequency[0]


def test_mathieu_theory_tips():
    r = hillstab.regions("mathieu", frequency=(0.5, 25.0), drive=(0.0, 1.0), order=3)
    assert r.drive_axis == 1
    assert r.order.tolist() == [1, 2, 3]
    assert list(r.status_name) == ["theory"] * 3 and np.all(r.status == curves.REGION_THEORY)
    for k in range(3):
        assert abs(r.frequency[k] - ((k + 1) * math.pi / 2) ** 2) < 1e-9
        assert r.drive[k] == 0.0 and r.drive_error[k] == 0.0
    # the model's coordinates: the drive is alpha, the frequency beta
    assert np.all(r.beta == r.frequency) and np.all(r.alpha == r.drive)


def test_bad_input_named():
    e = damped_mathieu()
    with pytest.raises(ValueError, match="frequency"):
        hillstab.regions(e, frequency=(3.0, 0.5), drive=(0.0, 0.5))
    with pytest.raises(ValueError, match="frequency"):
        hillstab.regions(e, frequency=3.0, drive=(0.0, 0.5))
    with pytest.raises(ValueError, match="drive"):
        hillstab.regions(e, frequency=(0.5, 3.0), drive=(0.5, 0.5))
    with pytest.raises(ValueError, match="order"):
        hillstab.regions(e, frequency=(0.5, 3.0), drive=(0.0, 0.5), order=9)
    with pytest.raises(TypeError, match="order"):
        hillstab.regions(e, frequency=(0.5, 3.0), drive=(0.0, 0.5), order=2.5)
    with pytest.raises(ValueError, match="n_samples"):
        hillstab.regions(e, frequency=(0.5, 3.0), drive=(0.0, 0.5), n_samples=1)
    with pytest.raises(ValueError, match="drive_axis"):
        hillstab.regions(e, frequency=(0.5, 3.0), drive=(0.0, 0.5), drive_axis=3)
    with pytest.raises(ValueError, match="method"):
        hillstab.regions(e, frequency=(0.5, 3.0), drive=(0.0, 0.5), method="nope")
    with pytest.raises(ValueError, match="tolerance"):
        hillstab.regions(e, frequency=(0.5, 3.0), drive=(0.0, 0.5), tolerance=2.0)
    with pytest.raises(ValueError, match="epsilon"):
        hillstab.regions(e, frequency=(0.5, 3.0), drive=(0.0, 0.5), epsilon=0.1)
    with pytest.raises(ValueError, match="epsilon"):
        hillstab.regions("mathieu", frequency=(0.5, 3.0), drive=(0.0, 0.5), epsilon=-0.1)
    with pytest.raises(TypeError, match="epsilon"):
        hillstab.regions("mathieu", frequency=(0.5, 3.0), drive=(0.0, 0.5), epsilon="x")
    with pytest.raises(ValueError, match="frequency"):
        hillstab.regions("mathieu", frequency=(math.nan, 3.0), drive=(0.0, 0.5))
    s = hillstab.System(damping=[[0.05]], cos=[[1.0]])
    with pytest.raises(ValueError, match="hillstab_system_regions: .*drive"):
        s.regions(frequency=(1.5, 3.5), drive=(1.0, 0.0))
    with pytest.raises(ValueError, match="method"):
        s.regions(frequency=(1.5, 3.5), drive=(0.0, 1.0), method="formula")
    with pytest.raises(ValueError, match="hillstab_system_regions: tolerance"):
        s.regions(frequency=(1.5, 3.5), drive=(0.0, 1.0), tolerance=1e-17)
