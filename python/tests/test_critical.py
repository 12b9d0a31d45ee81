"""Critical drives from Python: the Kapitza pendulum's least stabilising amplitude at 50 Hz
(6.30680 mm, a 150-digit reference) and the end of its window near 91.0 mm; every change
confirmed by `floquet`'s own verdicts on both sides; bad input named."""
import math

import numpy as np
import pytest

import hillstab

G, L, KAPPA = 9.81, 0.2, 0.2


def kapitza(frequency, tolerance=1e-12):
    w = 2 * math.pi * frequency
    beta = -G * math.pi ** 2 / (L * w ** 2)
    epsilon = KAPPA * math.pi / w
    return hillstab.critical_drives(beta, (0.0, 0.1 * math.pi ** 2 / L), model="mathieu", epsilon=epsilon,
                                    tolerance=tolerance), beta, epsilon


def test_kapitza_least_amplitude():
    drives, beta, epsilon = kapitza(50.0)
    assert len(drives) >= 2
    amplitudes = drives.alpha * L / math.pi ** 2
    assert abs(amplitudes[0] - 6.30680e-3) < 5e-9
    assert drives.direction[0] == -1 and drives.direction[1] == 1
    assert abs(amplitudes[1] - 91.0e-3) < 0.6e-3
    assert np.all(drives.status == 0)
    # first order: A w = sqrt(2 g l), within the higher-order correction
    assert abs(amplitudes[0] * 2 * math.pi * 50 - math.sqrt(2 * G * L)) < 1e-3


def test_changes_confirmed_by_floquet():
    drives, beta, epsilon = kapitza(30.0, tolerance=1e-11)
    for alpha, error, direction in zip(drives.alpha, drives.alpha_error, drives.direction):
        delta = max(4 * error, 1e-9 * max(1.0, alpha))
        r = hillstab.floquet([alpha - delta, alpha + delta], beta, model="mathieu", epsilon=epsilon, values=("stable",))
        below, above = r.stable
        assert (below, above) == ((1, 0) if direction == 1 else (0, 1))


def test_bad_input_named():
    with pytest.raises(ValueError, match="alpha_min, alpha_max"):
        hillstab.critical_drives(1.0, (2.0, 1.0), model="mathieu")
    with pytest.raises(ValueError, match="n_samples"):
        hillstab.critical_drives(1.0, (0.0, 1.0), model="mathieu", n_samples=1)
    with pytest.raises(ValueError, match="method"):
        hillstab.critical_drives(1.0, (0.0, 1.0), model="mathieu", method="nope")
    with pytest.raises(ValueError, match="alpha"):
        hillstab.critical_drives(1.0, 3.0, model="mathieu")
    with pytest.raises(ValueError):
        hillstab.critical_drives(1.0, (0.0, 1.0), model="mathieu", epsilon=-0.1)
