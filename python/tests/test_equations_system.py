"""Equations systems from Python (`hillstab.Equations`): Bolotin's column of
docs/guide/your-problem.md, written with numpy matrices and a dict of parameters, equals the
command line's binary chart and points files (model 'equations') to the bit, every column,
its axes named after the parameters Om and P1 too; arrays of any shapes that broadcast equal
the points one by one; at points of data/reference/physical_set.dat (set 3: the monodromy of
the physical column by Taylor series in 45 digits) the trace and all six multipliers lie
within the tolerance; the texts of the scene give the same system; the axes swapped (the
frequency and with it the damping along beta, each point alone) equal the command line's
chart to the bit and the chart over (Om, P1) within 1e-9; bad input raises
ValueError naming the variable (epsilon too: the damping is the system's own)."""
import math
import os

import numpy as np
import pytest

import hillstab

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MATRICES = {"W": np.diag([1.0, 16.0, 81.0]), "S": [[1, 0.3, 0.1], [0.3, 4, 0.4], [0.1, 0.4, 9]],
            "Z": np.diag([1.0, 4.0, 9.0])}
COLUMN = dict(stiffness="W - (P0 + P1*cos(Om*t))*S", frequency="Om", damping="2*zeta*Z", matrices=MATRICES,
              parameters={"P0": 0.3, "P1": 0.0, "Om": 2.0, "zeta": 0.01}, alpha="Om", beta="P1")
GROUP = """&equations n = 3, parameters = 'P0 = 0.3, P1 = 0, Om = 2, zeta = 0.01',
  matrices = 'W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [1, 0.3, 0.1; 0.3, 4, 0.4; 0.1, 0.4, 9], Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]',
  stiffness = 'W - (P0 + P1*cos(Om*t))*S', damping = '2*zeta*Z', frequency = 'Om', alpha = 'Om', beta = 'P1' /
"""
SCENE = ("&scene task = '{task}', model = 'equations', method = '{method}', tolerance = 1e-10, output = '{name}', "
         "format = 'binary' /\n" + GROUP + "{group}\n")
POINTS = [(1.6726, 0.0), (1.6, 0.4), (4.68, 0.3), (10.0, 0.0), (0.84, 0.8), (7.69, 0.5), (2.34, 1.0)]


def same_bits(a, b):
    a = np.ascontiguousarray(a, dtype=np.float64).ravel()
    b = np.ascontiguousarray(b, dtype=np.float64).ravel()
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


@pytest.fixture(scope="module")
def column():
    return hillstab.Equations(**COLUMN)


def test_the_column(column):
    assert column.n == 3 and column.axes == ("Om", "P1")
    assert column.column_names()[:3] == ("Om", "P1", "trace")
    assert repr(column) == "hillstab.Equations(n=3, alpha='Om', beta='P1')"
    f = column.floquet(1.6, 0.4)
    assert f.verdict == 0 and f.kind_name == "parametric at -1" and f.multipliers.shape == (6,)


def test_chart_equals_the_command_line(cli, column):
    cli.run("col", SCENE.format(task="chart", method="auto", name="col", group="&chart alpha_min = 1.2, "
                                "alpha_max = 2.1, n_alpha = 7, beta_min = 0.0, beta_max = 1.2, n_beta = 6 /"))
    out = hillstab.read_output(cli.path("col_chart.bin"))
    c = column.chart((1.2, 2.1, 7), (0.0, 1.2, 6), threads=2)
    assert out.grid_shape == (7, 6) and list(c.names) == out.columns
    for name in out.columns:
        assert same_bits(c[name], out.grid(name)), name
    assert same_bits(c.Om, c.alpha) and same_bits(c.P1, c.beta)
    assert same_bits(c.Om, out.axes[0]) and same_bits(c.P1, out.axes[1])
    assert set(np.unique(c.stable)) == {0, 1}


@pytest.mark.parametrize("method", ["auto", "magnus6"])
def test_points_equal_the_command_line(cli, column, method):
    with open(cli.path("col.pts"), "w") as handle:
        handle.write("".join("{!r} {!r}\n".format(om, p1) for om, p1 in POINTS))
    cli.run("pts", SCENE.format(task="points", method=method, name="pts", group="&points file = 'col.pts' /"))
    out = hillstab.read_output(cli.path("pts_points.bin"))
    om, p1 = np.array(POINTS).T
    r = column.points(om, p1, method=method, threads=2)
    assert list(r.names) == out.columns
    for name in out.columns:
        assert same_bits(r[name], out[name]), name
    assert same_bits(r.Om, om) and same_bits(r.P1, p1)
    assert np.all(r.status == 0)


def test_arrays_equal_points_one_by_one(column):
    om = np.array([[1.6, 4.68], [7.69, 10.0]])
    p1 = np.array([0.0, 0.3, 0.9])[:, np.newaxis, np.newaxis]
    r = column.floquet(om, p1)
    assert r.trace.shape == (3, 2, 2) and r.exponents.shape == (3, 2, 2, 3)
    for index in np.ndindex(r.trace.shape):
        one = column.floquet(om[index[1:]], p1[index[0], 0, 0])
        assert same_bits(one.trace, r.trace[index]) and same_bits(one.a2, r.a2[index])
        assert same_bits(one.exponents, r.exponents[index])
        assert one.verdict == r.verdict[index] and one.kind == r.kind[index] and one.status == r.status[index]
    assert same_bits(r.Om, np.broadcast_to(om, r.trace.shape))


def test_against_the_physical_reference(column):
    rows = [line.split() for line in open(os.path.join(ROOT, "data", "reference", "physical_set.dat"))
            if line.startswith("3 ")]
    assert len(rows) == 50
    tolerance = 1e-10
    for row in rows[::7]:
        om, p1, trace = float(row[1]), float(row[2]), float(row[3])
        reference = np.array([float(row[4 + 2 * j]) + 1j * float(row[5 + 2 * j]) for j in range(6)])
        f = column.floquet(om, p1, tolerance=tolerance)
        phi, estimate, status = column.monodromy(om, p1, tolerance=tolerance)
        assert f.status == 0 and status == 0
        scale = max(1.0, float(np.abs(phi).max()))
        assert abs(f.trace - trace) <= 6 * tolerance * scale, (om, p1)
        computed = f.multipliers * np.exp(f.log_scale)
        for z in reference:
            assert np.min(np.abs(computed - z)) <= tolerance * max(1.0, abs(z)), (om, p1, z)


def test_texts_give_the_same_system(column):
    texts = hillstab.Equations("W - (P0 + P1*cos(Om*t))*S", frequency="Om", damping="2*zeta*Z", n=3,
                               matrices="W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [1, 0.3, 0.1; 0.3, 4, 0.4; "
                                        "0.1, 0.4, 9], Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]",
                               parameters="P0 = 0.3, P1 = 0, Om = 2, zeta = 0.01", alpha="Om", beta="P1")
    a = texts.points([1.6, 4.68], [0.4, 0.3])
    b = column.points([1.6, 4.68], [0.4, 0.3])
    assert all(same_bits(a[name], b[name]) for name in a.names)
    # a period instead of the frequency, a number for the mass
    period = hillstab.Equations(**dict(COLUMN, frequency=None, period="2*pi/Om", mass=1))
    assert same_bits(period.floquet(1.6, 0.4).trace, column.floquet(1.6, 0.4).trace)


def test_beta_anywhere_axes_swapped(cli, column):
    swapped = hillstab.Equations(**dict(COLUMN, alpha="P1", beta="Om"))
    assert swapped.axes == ("P1", "Om")
    scene = SCENE.format(task="chart", method="auto", name="swap", group="&chart alpha_min = 0.0, alpha_max = 1.2, "
                         "n_alpha = 6, beta_min = 1.2, beta_max = 2.1, n_beta = 7 /")
    cli.run("swap", scene.replace("alpha = 'Om', beta = 'P1'", "alpha = 'P1', beta = 'Om'"))
    out = hillstab.read_output(cli.path("swap_chart.bin"))
    c = swapped.chart((0.0, 1.2, 6), (1.2, 2.1, 7), threads=2)
    assert out.axis_names == ("P1", "Om") and list(c.names) == out.columns
    for name in out.columns:
        assert same_bits(c[name], out.grid(name)), name
    r = column.chart((1.2, 2.1, 7), (0.0, 1.2, 6), threads=2)
    for name in ("trace", "a2", "mu"):
        assert np.all(np.abs(c[name] - r[name].T) <= 1e-9 * np.maximum(1.0, np.abs(r[name].T))), name
    assert np.array_equal(c.stable, r.stable.T) and np.array_equal(c.kind, r.kind.T)
    p = swapped.points(np.array([0.4, 0.8]), np.array([1.6, 2.0]))
    q = column.points(np.array([1.6, 2.0]), np.array([0.4, 0.8]))
    assert np.all(np.abs(p.trace - q.trace) <= 1e-9 * np.maximum(1.0, np.abs(q.trace)))


@pytest.mark.parametrize("change, variable, words", [
    (dict(matrices="W = [1, 0, 0; 0, 16, 0; 0, 0, 81], S = [1, 0.3; 0.3, 4, 0.4; 0.1, 0.4, 9], "
                   "Z = [1, 0, 0; 0, 4, 0; 0, 0, 9]", n=3), "matrices", "S, row 1 has 2 entries"),
    (dict(matrices=dict(MATRICES, S=np.eye(2))), "matrices", "S: must be an n x n array, n = 3"),
    (dict(matrices=dict(MATRICES, S=[[1, 0, np.nan], [0, 1, 0], [0, 0, 1]])), "matrices", "finite"),
    (dict(stiffness="W - (P0 + P1*cos(Om*t))*Q"), "stiffness", "unknown name 'Q'"),
    (dict(stiffness="W - (P0 + P1*cos(Om*t)*S"), "stiffness", "column"),
    (dict(alpha="Omega"), "alpha", "'Omega' is no parameter"),
    (dict(mass="Om*Z"), "mass", "may not depend on the axes"),
    (dict(damping="2*zeta*Z*t"), "damping", ""),
    (dict(parameters={"P0": 0.3, "P1": 0.0, "Om": float("inf"), "zeta": 0.01}), "parameters: Om", "finite"),
    (dict(n=4), "matrices", "n = 4"),
])
def test_bad_input_named(change, variable, words):
    with pytest.raises(ValueError) as caught:
        hillstab.Equations(**dict(COLUMN, **change))
    message = str(caught.value)
    assert variable + ":" in message and words in message, message


@pytest.mark.parametrize("change, variable", [
    (dict(stiffness=3.0), "stiffness"),
    (dict(alpha=1), "alpha"),
    (dict(mass=1j), "mass"),
    (dict(matrices=dict(MATRICES, S=np.eye(3) * 1j)), "matrices: S"),
    (dict(matrices=[np.eye(3)]), "matrices"),
])
def test_wrong_types_named(change, variable):
    with pytest.raises(TypeError) as caught:
        hillstab.Equations(**dict(COLUMN, **change))
    assert str(caught.value).startswith(variable + ":"), str(caught.value)


def test_epsilon_refused(column):
    with pytest.raises(ValueError, match="epsilon: the equations system carries its own damping"):
        column.floquet(1.6, 0.4, epsilon=0.1)
    with pytest.raises(ValueError, match="epsilon: point 1: the equations system carries its own damping"):
        column.floquet([1.6, 1.7], [0.4, 0.4], epsilon=[0.0, 0.1])
    with pytest.raises(ValueError, match="epsilon: the grid: the equations system carries its own damping"):
        column.chart((1.2, 2.1, 3), (0.0, 1.2, 3), epsilon=0.05)


def test_chart_over_named_axes_equals_points(column):
    """A chart over (Om, P1) and the points task at its grid's points: the same verdicts and
    kinds, S and the exponents within the tolerance (a chart's row shares its nodes, a point
    is computed alone, so the values may differ within it)."""
    c = column.chart((1.4, 2.0, 5), (0.0, 0.8, 4), tolerance=1e-10)
    om, p1 = np.meshgrid(c.Om, c.P1, indexing="ij")
    r = column.points(om, p1, tolerance=1e-10)
    assert c.stable.shape == (5, 4) and np.array_equal(c.stable, r.stable) and np.array_equal(c.kind, r.kind)
    scale = np.maximum(1.0, np.abs(r.trace))
    assert np.all(np.abs(c.trace - r.trace) <= 2e-10 * scale * 6)
    assert np.all(np.abs(c.mu - r.mu) <= 1e-8)


FEEDBACK = dict(state="P + (g0 + g1*cos(Om*t))*G", frequency="Om", n=3,
                matrices="P = [0, 1, 0; -1, -2*zeta, 1; 0, 0, -1/Ta], G = [0, 0, 0; 0, 0, 0; -1/Ta, 0, 0]",
                parameters={"zeta": 0.05, "Ta": 0.2, "g0": 0.5, "g1": 0.0, "Om": 2.0}, alpha="Om", beta="g1")


def first_order_column():
    """The column of COLUMN in first-order form: y = (x, x'), A = [[0, I], [-W, -C]] + (P0 +
    P1 cos(Om t)) [[0, 0], [S, 0]]."""
    u = np.zeros((6, 6))
    u[:3, 3:] = np.eye(3)
    u[3:, :3] = -MATRICES["W"]
    u[3:, 3:] = -2 * 0.01 * MATRICES["Z"]
    v = np.zeros((6, 6))
    v[3:, :3] = MATRICES["S"]
    return hillstab.Equations(state="U + (P0 + P1*cos(Om*t))*V", frequency="Om", matrices={"U": u, "V": v},
                              parameters={"P0": 0.3, "P1": 0.0, "Om": 2.0, "zeta": 0.01}, alpha="Om", beta="P1")


def test_first_order_column_equals_the_second_order_form(column):
    """The column with six states: six multipliers, the same verdicts and kinds as the
    second-order form, its multipliers and the physical reference's within the tolerance."""
    first = first_order_column()
    assert first.n == 6 and first.states == 6 and column.states == 6
    for om, p1 in POINTS:
        a = first.floquet(om, p1, tolerance=1e-10)
        b = column.floquet(om, p1, tolerance=1e-10)
        assert a.multipliers.shape == (6,) and a.exponents.shape == (6,)
        assert a.verdict == b.verdict and a.kind == b.kind, (om, p1)
        for z in b.multipliers * np.exp(b.log_scale):
            assert np.min(np.abs(a.multipliers * np.exp(a.log_scale) - z)) <= 2e-10 * max(1.0, abs(z)), (om, p1)
    phi, estimate, status = first.monodromy(1.6, 0.4)
    assert phi.shape == (6, 6) and status == 0


def test_three_states_against_the_command_line(cli):
    """Three states, the shipped scene's plant: the chart equals the command line's file to
    the bit; at g1 = 0 the multipliers are exp(T lambda) of the constant A."""
    plant = hillstab.Equations(**FEEDBACK)
    assert plant.n == 3 and plant.states == 3
    a = np.array([[0, 1, 0], [-1, -0.1, 1], [-2.5, 0, -5]])
    for om in (0.7, 2.45, 3.3):
        f = plant.floquet(om, 0.0, tolerance=1e-10)
        exact = np.exp(np.linalg.eigvals(a) * 2 * np.pi / om)
        for z in exact:
            assert np.min(np.abs(f.multipliers - z)) <= 1e-10, (om, z)
    group = ("&equations n = 3, parameters = 'zeta = 0.05, Ta = 0.2, g0 = 0.5, g1 = 0, Om = 2',\n"
             "  matrices = 'P = [0, 1, 0; -1, -2*zeta, 1; 0, 0, -1/Ta], G = [0, 0, 0; 0, 0, 0; -1/Ta, 0, 0]',\n"
             "  state = 'P + (g0 + g1*cos(Om*t))*G', frequency = 'Om', alpha = 'Om', beta = 'g1' /\n")
    cli.run("fb", "&scene task = 'chart', model = 'equations', tolerance = 1e-8, output = 'fb', "
            "format = 'binary' /\n" + group + "&chart alpha_min = 1.0, alpha_max = 3.0, n_alpha = 5, "
            "beta_min = 0.0, beta_max = 1.5, n_beta = 4 /\n")
    out = hillstab.read_output(cli.path("fb_chart.bin"))
    c = plant.chart((1.0, 3.0, 5), (0.0, 1.5, 4), tolerance=1e-8, threads=2)
    assert list(c.names) == out.columns and "mu_3" in out.columns
    for name in out.columns:
        assert same_bits(c[name], out.grid(name)), name
    assert set(np.unique(c.stable)) == {0, 1}


@pytest.mark.parametrize("change, variable", [
    (dict(stiffness="P"), "stiffness, state"),
    (dict(damping="1"), "mass, damping, gyroscopic"),
    (dict(state="P + (g0 + g1*cos(Om*t))*Q"), "state"),
    (dict(state="P + (g0 + g1*cos(Om*t) + 0.1*cos(3*t))*G"), "state"),
    (dict(state="P + (g0 + g1*cos(3*t))*G"), "state"),
])
def test_first_order_bad_input_named(change, variable):
    with pytest.raises(ValueError) as caught:
        hillstab.Equations(**dict(FEEDBACK, **change))
    assert variable + ":" in str(caught.value), str(caught.value)


def test_first_order_methods_agree():
    """Every system method on the three states: Magnus on the full A, rk and gsl within the
    tolerance of one another; without a stiffness or a state the system is refused."""
    plant = hillstab.Equations(**FEEDBACK)
    reference = plant.monodromy(2.3, 0.8, method="rk", tolerance=1e-10)[0]
    for method in ("auto", "magnus4", "magnus6", "gsl"):
        phi, estimate, status = plant.monodromy(2.3, 0.8, method=method, tolerance=1e-10)
        assert status == 0 and np.abs(phi - reference).max() <= 2e-10 * max(1.0, np.abs(reference).max()), method
    with pytest.raises(ValueError, match="stiffness: give K"):
        hillstab.Equations(frequency="Om", matrices=FEEDBACK["matrices"], n=3, parameters=FEEDBACK["parameters"],
                           alpha="Om", beta="g1")


KAPITZA_ONE = dict(stiffness="-g/l + A*w^2/l*cos(w*t)", frequency="w", damping="kappa", n=1,
                   parameters={"g": 9.81, "l": 0.2, "kappa": 0.2, "A": 0.005, "w": 314.16}, alpha="w", beta="A")


def test_rates_per_unit_time():
    """mu times `tau_rate` is the exponent per unit of the system's own time t at each point's
    Omega: two damped modes K = diag(-1.5, 4.2) (P1 = 0, C = c I) grow as e^{rt}, r the largest
    -c/2 + Re sqrt(c^2/4 - k_i), whatever Om; with Om along alpha (rows shared) and along beta
    (each point alone); 0 outside the domain; the matrix system, in tau alone, has rate 0."""
    k, c = (-1.5, 4.2), 0.3
    r = max(-c / 2 + (math.sqrt(c * c / 4 - ki) if c * c / 4 > ki else 0.0) for ki in k)
    om = np.array([1.5, 3.0, 5.5])
    base = dict(stiffness="K - P1*cos(Om*t)*I", frequency="Om", damping="c*I",
                matrices={"K": np.diag(k), "I": np.eye(2)}, parameters={"P1": 0.0, "Om": 1.0, "c": c})
    for alpha, beta, a, b in (("Om", "P1", om, 0.0 * om), ("P1", "Om", 0.0 * om, om)):
        system = hillstab.Equations(**base, alpha=alpha, beta=beta)
        rate = system.tau_rate(a, b)
        assert np.allclose(rate, om / math.pi, rtol=1e-15, atol=0.0)
        mu = system.points(a, b)["mu"]
        assert np.all(np.abs(mu * rate - r) <= 1e-8), (mu * rate, r)
    assert system.tau_rate(0.0, -1.0) == 0.0
    plain = hillstab.System(k0=np.diag([1.0, 4.0]), b=np.eye(2), cos=np.diag([0.5, 0.5]))
    assert np.all(plain.tau_rate([0.1, 0.2], 1.0) == 0.0)


def test_one_equation_takes_the_scalar_path():
    """The Kapitza pendulum as a system of one equation: on method auto its chart, its points
    and its floquet at one point are the scalar equation's analysis (tr Phi = exp(-eps) S,
    a2 = det Phi = exp(-2 eps) with eps = kappa pi/w, the same verdicts), one point's numbers
    those of the same point in an array, and magnus6 (the system path) agrees within the
    tolerance."""
    one = hillstab.Equations(**KAPITZA_ONE)
    scalar = hillstab.Equation(**{k: v for k, v in KAPITZA_ONE.items() if k != "n"})
    w_axis, a_axis = (60.0, 700.0, 9), (0.0, 0.1, 8)
    c = one.chart(w_axis, a_axis, threads=2)
    s = hillstab.chart(w_axis, a_axis, model=scalar, threads=2)
    eps = 0.2 * np.pi / c.alpha[:, np.newaxis]
    assert np.all(c.status == 0) and set(np.unique(c.stable)) == {0, 1}
    assert np.allclose(c.trace, np.exp(-eps) * s.trace, rtol=1e-14, atol=1e-300)
    assert np.allclose(c.a2, np.exp(-2 * eps), rtol=1e-14)
    assert np.array_equal(c.stable, s.stable)
    assert np.all(c.defect == 0)
    slow = one.chart(w_axis, a_axis, method="magnus6", tolerance=1e-11, threads=2)
    assert np.all(np.abs(slow.trace - c.trace) <= 1e-8 * np.maximum(1.0, np.abs(slow.trace)))
    assert np.all(np.abs(slow.mu - c.mu) <= 1e-9)
    for i, j in ((0, 0), (3, 5), (8, 7)):
        f = one.floquet(c.alpha[i], c.beta[j])
        p = one.points([c.alpha[i]], [c.beta[j]])
        assert same_bits(f.trace, p.trace) and same_bits(f.trace, c.trace[i, j])
        assert f.verdict == c.stable[i, j] and f.defect == 0.0
        assert np.isclose(abs(f.multipliers[0]), c.lambda_max[i, j], rtol=1e-14)
