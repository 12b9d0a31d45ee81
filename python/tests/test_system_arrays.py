"""Systems over arrays: `System.floquet` and `System.points` at points of any shapes that
broadcast equal the one-point calls and the command line's points file to the bit,
`System.chart` equals its chart file; statuses 1 and 2 warn as for a scalar model; bad
arrays raise naming the argument."""
import numpy as np
import pytest

import hillstab

GROUP = ("&system n = 2, mass = 1.0, 0.0, 0.0, 0.64, b = 1.1, -0.1, -0.1, 0.9, damping = 0.02, 0.0, 0.0, 0.01, "
         "gyroscopic = 0.0, 0.3, -0.3, 0.0, cos = -1.0, -0.2, -0.2, -0.8, sin = 0.0, 0.1, 0.1, 0.3 /\n")


def system():
    return hillstab.System(mass=np.diag([1.0, 0.64]), b=[[1.1, -0.1], [-0.1, 0.9]], damping=np.diag([0.02, 0.01]),
                           gyroscopic=[[0.0, 0.3], [-0.3, 0.0]], cos=[[-1.0, -0.2], [-0.2, -0.8]],
                           sin=[[0.0, 0.1], [0.1, 0.3]])


@pytest.mark.parametrize("method", ["auto", "magnus4", "rk"])
def test_arrays_equal_one_by_one(method):
    s = system()
    alpha = np.array([[0.2], [0.7], [1.3]])
    beta = np.linspace(0.3, 2.5, 4)
    epsilon = np.array([0.0, 0.05, 0.0, 0.05])
    r = s.floquet(alpha, beta, epsilon, method=method, tolerance=1e-9, threads=2)
    assert isinstance(r, hillstab.system.SystemResult)
    assert r.trace.shape == (3, 4) and r.exponents.shape == (3, 4, 2) and r.status.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            one = s.floquet(float(alpha[i, 0]), float(beta[j]), float(epsilon[j]), method=method, tolerance=1e-9)
            assert r.trace[i, j] == one.trace and r.a2[i, j] == one.a2
            assert r.verdict[i, j] == one.verdict and r.kind[i, j] == one.kind
            assert np.array_equal(r.exponents[i, j], one.exponents)
            assert r.defect[i, j] == one.defect and r.error_estimate[i, j] == one.error_estimate
            assert r.status[i, j] == one.status
            assert r.alpha[i, j] == alpha[i, 0] and r.beta[i, j] == beta[j]


def test_points_equal_command_line(cli):
    s = system()
    alpha = np.full(25, 0.7)
    beta = np.round(np.linspace(0.3, 2.7, 25), 4)
    np.savetxt(cli.path("q.pts"), np.column_stack([alpha, beta]), fmt="%.4f")
    cli.run("q", "&scene task = 'points', model = 'system', method = 'magnus6', tolerance = 1e-9, epsilon = 0.03, "
            "output = 'q' /\n" + GROUP + "&points file = 'q.pts' /\n")
    file = hillstab.read_output(cli.path("q_points.dat"))
    r = s.points(alpha, beta, 0.03, method="magnus6", tolerance=1e-9)
    assert list(r.names) == list(file.columns)
    for k, name in enumerate(file.columns):
        assert np.array_equal(file.data[:, k], getattr(r, name)), name


def test_chart_equals_command_line(cli):
    s = system()
    cli.run("c", "&scene task = 'chart', model = 'system', epsilon = 0.02, output = 'c', format = 'binary' /\n" + GROUP +
            "&chart alpha_min = 0.0, alpha_max = 1.2, n_alpha = 4, beta_min = 0.2, beta_max = 2.6, n_beta = 9 /\n")
    file = hillstab.read_output(cli.path("c_chart.bin"))
    r = s.chart((0.0, 1.2, 4), (0.2, 2.6, 9), epsilon=0.02)
    assert r.trace.shape == (4, 9) and r.alpha.shape == (4,) and r.beta.shape == (9,)
    for k, name in enumerate(file.columns):
        assert np.array_equal(file.data[:, k], np.ravel(r[name])), name
    assert np.array_equal(r["alpha"][:, 0], r.alpha) and np.array_equal(r["beta"][0], r.beta)


def test_status_one_warns():
    s = system()
    with pytest.warns(hillstab.HillstabWarning, match="round-off level"):
        r = s.floquet([0.3, 0.6], 1.0, tolerance=2e-15)
    assert np.all(r.status == 1)
    with pytest.warns(hillstab.HillstabWarning, match="round-off level"):
        one = s.floquet(0.3, 1.0, tolerance=2e-15)
    assert one.status == 1


def test_bad_arrays_named():
    s = system()
    with pytest.raises(ValueError, match="epsilon: point 1"):
        s.points([0.1, 0.2], 1.0, [0.0, -0.5])
    with pytest.raises(ValueError, match="alpha: point 0: must be finite"):
        s.points([np.nan, 0.2], 1.0)
    with pytest.raises(TypeError, match="alpha"):
        s.points(np.array([0.1 + 1j]), 1.0)
    with pytest.raises(ValueError, match="shape mismatch|broadcast"):
        s.points(np.zeros(3), np.zeros(2))
    with pytest.raises(ValueError, match="threads"):
        s.points([0.1], 1.0, threads=-1)
    with pytest.raises(ValueError, match="beta"):
        s.chart((0.0, 1.0, 2), (0.0, 1.0, 0))
    fortran = np.asfortranarray(np.array([[0.1, 0.2], [0.3, 0.4]]))
    r = s.points(fortran, 1.0)
    assert np.array_equal(r.alpha, fortran)
    strided = np.linspace(0.1, 0.8, 8)[::2]
    assert np.array_equal(s.points(strided, 1.0).alpha, strided)
