"""Equations in physical time from Python (`hillstab.Equation`): the Kapitza pendulum written
as its user writes it equals the built-in Mathieu model at the hand-made mapping
alpha = A pi^2/l, beta = -g pi^2/(l w^2), epsilon = kappa pi/w (within the tolerance); a chart
over the equation's own axes equals the command line's chart file to the bit, with its axes
named after the parameters both in the result and in `read_output`; arrays of any shape that
broadcast equal the points one by one; the frequency and the damping along the beta axis (each
point alone) equal the unswapped chart and the command line's file; bad input raises ValueError
naming the variable."""
import math

import numpy as np
import pytest

import hillstab

G, L, KAPPA = 9.81, 0.2, 0.2
KAPITZA = dict(stiffness="-g/l + A*w^2/l*cos(w*t)", frequency="w", damping="kappa",
               parameters={"g": G, "l": L, "kappa": KAPPA, "A": 0.005, "w": 314.16}, alpha="w", beta="A")
SCENE = """&scene task = 'chart', model = 'equation', tolerance = 1e-10, output = '{name}', format = '{fmt}' /
&equation parameters = 'g = 9.81, l = 0.2, kappa = 0.2, A = 0.005, w = 314.16',
  stiffness = '-g/l + A*w^2/l*cos(w*t)', damping = 'kappa', frequency = 'w', alpha = 'w', beta = 'A' /
&chart alpha_min = 60.0, alpha_max = 700.0, n_alpha = 12, beta_min = 0.0, beta_max = 0.1, n_beta = 9 /
"""


def same_bits(a, b):
    a = np.ascontiguousarray(a, dtype=np.float64).ravel()
    b = np.ascontiguousarray(b, dtype=np.float64).ravel()
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def test_kapitza_equals_mathieu_mapped_by_hand():
    kapitza = hillstab.Equation(**KAPITZA)
    w = np.linspace(60.0, 700.0, 9)[:, np.newaxis]
    a = np.linspace(0.0, 0.1, 7)[np.newaxis, :]
    r = hillstab.floquet(w, a, model=kapitza)
    assert r.trace.shape == (9, 7)
    m = hillstab.floquet(a * math.pi ** 2 / L, -G * math.pi ** 2 / (L * w ** 2), model="mathieu",
                         epsilon=KAPPA * math.pi / w)
    assert np.all(np.abs(r.trace - m.trace) <= 2e-10 * np.maximum(1.0, np.abs(m.trace)))
    assert np.array_equal(r.stable, m.stable)
    # the least stabilising amplitude at 50 Hz lies between 6.30 and 6.31 mm (6.30680 mm)
    s = hillstab.floquet(2 * math.pi * 50, [6.30e-3, 6.31e-3], model=kapitza).stable
    assert list(s) == [0, 1]


def test_chart_equals_the_command_line(cli):
    kapitza = hillstab.Equation(**KAPITZA)
    cli.run("kapitza", SCENE.format(name="kapitza", fmt="binary"))
    out = hillstab.read_output(cli.path("kapitza_chart.bin"))
    assert out.columns[:2] == ["w", "A"]
    assert out.axis_names == ("w", "A")
    c = hillstab.chart((60.0, 700.0, 12), (0.0, 0.1, 9), model=kapitza, threads=2)
    assert same_bits(c.trace, out.grid("S"))
    assert same_bits(c.stable, out.grid("stable"))
    assert same_bits(c.w, c.alpha) and same_bits(c.A, c.beta)
    assert same_bits(c.w, out.axes[0]) and same_bits(c.A, out.axes[1])


def test_arrays_equal_points_one_by_one():
    kapitza = hillstab.Equation(**KAPITZA)
    w = np.array([[100.0, 314.16], [500.0, 650.0]])
    a = np.array([0.004, 0.02, 0.09])[:, np.newaxis, np.newaxis]
    r = hillstab.floquet(w, a, model=kapitza)
    assert r.trace.shape == (3, 2, 2)
    for index in np.ndindex(r.trace.shape):
        one = hillstab.floquet(w[index[1:]], a[index[0], 0, 0], model=kapitza)
        assert same_bits(one.trace, r.trace[index])


def test_beta_anywhere_axes_swapped(cli):
    """The axes swapped (alpha = 'A', beta = 'w': the frequency and the damping kappa pi/w along
    beta, each point alone): the chart equals the command line's file to the bit, and the chart
    over (w, A), whose rows share their meshes, within twice the tolerance; its verdicts alike."""
    swapped = hillstab.Equation(**dict(KAPITZA, alpha="A", beta="w"))
    kapitza = hillstab.Equation(**KAPITZA)
    scene = SCENE.format(name="swapped", fmt="binary").replace("alpha = 'w', beta = 'A'", "alpha = 'A', beta = 'w'")
    scene = scene.replace("alpha_min = 60.0, alpha_max = 700.0, n_alpha = 12, beta_min = 0.0, beta_max = 0.1, n_beta = 9",
                          "alpha_min = 0.0, alpha_max = 0.1, n_alpha = 9, beta_min = 60.0, beta_max = 700.0, n_beta = 12")
    cli.run("swapped", scene)
    out = hillstab.read_output(cli.path("swapped_chart.bin"))
    assert out.axis_names == ("A", "w")
    c = hillstab.chart((0.0, 0.1, 9), (60.0, 700.0, 12), model=swapped, threads=2)
    assert same_bits(c.trace, out.grid("S")) and same_bits(c.stable, out.grid("stable"))
    r = hillstab.chart((60.0, 700.0, 12), (0.0, 0.1, 9), model=kapitza, threads=2)
    assert np.all(np.abs(c.trace - r.trace.T) <= 2e-10 * np.maximum(1.0, np.abs(r.trace.T)))
    assert np.array_equal(c.stable, r.stable.T)
    p = hillstab.floquet(np.array([0.004, 0.05]), np.array([300.0, 650.0]), model=swapped)
    assert np.all(np.abs(p.trace - hillstab.floquet(np.array([300.0, 650.0]), np.array([0.004, 0.05]),
                                                    model=kapitza).trace) <= 2e-10 * np.maximum(1.0, np.abs(p.trace)))


def test_rates_per_unit_time(cli):
    """mu times `tau_rate` is the exponent per unit of the equation's time t at each point's
    Omega: at A = 0 the inverted pendulum's g/l - kappa theta' alone grows as e^{rt},
    r = -kappa/2 + sqrt(kappa^2/4 + g/l), whatever w; with the axes swapped too (w along beta);
    and it is the command line's column mu_per_s. A model in tau alone has rate 0."""
    r = -KAPPA / 2 + math.sqrt(KAPPA ** 2 / 4 + G / L)
    w = np.array([60.0, 250.0, 700.0])
    for model, alpha, beta in ((hillstab.Equation(**KAPITZA), w, 0.0 * w),
                               (hillstab.Equation(**dict(KAPITZA, alpha="A", beta="w")), 0.0 * w, w)):
        rate = model.tau_rate(alpha, beta)
        assert np.allclose(rate, w / math.pi, rtol=1e-15, atol=0.0)
        mu = hillstab.floquet(alpha, beta, model=model, values=("mu",)).mu
        assert np.all(np.abs(mu * rate - r) <= 1e-9)
    assert model.tau_rate(0.0, np.array([[1.0], [-1.0]])).tolist() == [[1.0 / math.pi], [0.0]]
    assert np.all(hillstab.Model("mathieu").tau_rate([1.0, 2.0], 0.5) == 0.0)
    scene = SCENE.format(name="rates", fmt="text").replace("output", "columns = 'w A mu mu_per_s', output")
    cli.run("rates", scene)
    out = hillstab.read_output(cli.path("rates_chart.dat"))
    kapitza = hillstab.Equation(**KAPITZA)
    rows = np.loadtxt(cli.path("rates_chart.dat"))
    ours = hillstab.floquet(rows[:, 0], rows[:, 1], model=kapitza, values=("mu",)).mu * kapitza.tau_rate(rows[:, 0],
                                                                                                          rows[:, 1])
    assert out.grid("mu_per_s").size == rows.shape[0]
    assert np.all(np.abs(ours - rows[:, 3]) <= 1e-10 * np.maximum(1.0, np.abs(rows[:, 3])))


def test_parameters_as_text_and_formula():
    kapitza = hillstab.Equation("-g/l + A*w^2/l*cos(w*t)", frequency="w", damping=0.2,
                                parameters="g = 9.81, l = 0.2, A = 0.005, w = 314.16", alpha="w", beta="A")
    assert kapitza.name == "equation"
    assert "k(t) = -g/l + A*w^2/l*cos(w*t)" in kapitza.formula
    assert kapitza.axes == ("w", "A")


@pytest.mark.parametrize("change, variable, words", [
    (dict(stiffness="-g/l + B*cos(w*t)"), "stiffness", "g, l, kappa, A, w"),
    (dict(stiffness="-g/l + A*cos(w*t"), "stiffness", "column"),
    (dict(stiffness="-g/l + A*cos(3*t)"), "stiffness", "not of period"),
    (dict(alpha="omega"), "alpha", "no parameter"),
    (dict(alpha="A", beta="A"), "alpha, beta", "one parameter"),
    (dict(mass="-1"), "mass", "> 0"),
    (dict(stiffness=3.0), "stiffness", "a string"),
])
def test_bad_equations_named(change, variable, words):
    arguments = dict(KAPITZA, **change)
    with pytest.raises(ValueError) as caught:
        hillstab.Equation(**arguments)
    assert variable + ":" in str(caught.value) and words in str(caught.value)


def test_epsilon_refused_for_an_equation():
    kapitza = hillstab.Equation(**KAPITZA)
    with pytest.raises(ValueError) as caught:
        hillstab.floquet(314.16, 0.01, model=kapitza, epsilon=0.1)
    assert "epsilon" in str(caught.value) and "own" in str(caught.value)


def test_critical_amplitude_at_a_frequency():
    """Along the equation's beta axis: the least stabilising amplitude at 50 Hz is the
    Mathieu model's at the hand-made mapping (6.30680 mm), named after the axis."""
    kapitza = hillstab.Equation(**KAPITZA)
    w = 2 * math.pi * 50
    d = hillstab.critical_drives((0.0, 0.1), w, model=kapitza, tolerance=1e-12)
    m = hillstab.critical_drives(-G * math.pi ** 2 / (L * w ** 2), (0.0, 0.1 * math.pi ** 2 / L), model="mathieu",
                                 epsilon=KAPPA * math.pi / w, tolerance=1e-12)
    assert d.axis == "beta" and len(d) == len(m) >= 2
    assert np.all(np.abs(d.A - m.alpha * L / math.pi ** 2) <= d.beta_error + m.alpha_error * L / math.pi ** 2 + 1e-15)
    assert abs(d.A[0] - 6.30680e-3) < 5e-9 and list(d.direction) == list(m.direction)
    with pytest.raises(ValueError) as caught:
        hillstab.critical_drives((0.0, 0.1), w, model=kapitza, epsilon=0.1)
    assert "epsilon" in str(caught.value)
