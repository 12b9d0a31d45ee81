"""The values of the Python package equal the command line's output files to the bit (same
model, method, tolerance): charts (rows in parallel and rows in chunks, verdicts only, damped,
Mathieu, every method), points, a spring in SI units, series, scenes run through the library.
The program is the one pip built beside the library (conftest.program)."""
import numpy as np
import pytest

import hillstab

#: the file columns a Result holds by the same name (one vocabulary), each with its earlier
#: name, an alias for this release (the same array)
FILE_VALUES = {"S": "trace", "stable": "stable", "lambda_max": "lambda_max", "mu": "exponent",
               "log10_abs_S": "log10_abs_trace", "overflow": "overflow", "error_estimate": "error_estimate",
               "stable_paper": "stable_paper", "kind": "kind", "argument": "argument"}


def same_as_file(out, result, column):
    """The file's column equals the result's value of that name, and its alias, to the bit."""
    return same_bits(out[column], getattr(result, column)) and \
        same_bits(out[column], getattr(result, FILE_VALUES[column])) and \
        same_bits(out[column], result[column])


def same_bits(a, b):
    """Equal as doubles, bit for bit (so -0.0 differs from 0.0 and NaN is never equal)."""
    a = np.ascontiguousarray(a, dtype=np.float64).ravel()
    b = np.ascontiguousarray(b, dtype=np.float64).ravel()
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def chart_scene(name, grid, model="elastic", method="auto", tolerance=1e-10, epsilon=0.0, columns="",
                fmt="binary", n_segments=2, sampling="endpoint"):
    (a0, a1, na), (b0, b1, nb) = grid
    return ("&scene task = 'chart', model = '{}', method = '{}', tolerance = {!r}, epsilon = {!r}, "
            "n_segments = {}, sampling = '{}', output = '{}', format = '{}', columns = '{}' /\n"
            "&chart alpha_min = {!r}, alpha_max = {!r}, n_alpha = {}, beta_min = {!r}, beta_max = {!r}, n_beta = {} /\n"
            .format(model, method, tolerance, epsilon, n_segments, sampling, name, fmt, columns,
                    a0, a1, na, b0, b1, nb))


def compare_chart(cli, name, grid, threads=2, **options):
    columns = options.pop("columns", "")
    fmt = options.pop("fmt", "binary")
    cli.run(name, chart_scene(name, grid, columns=columns, fmt=fmt, **options), threads=threads)
    out = hillstab.read_output(cli.path(name + "_chart." + ("bin" if fmt == "binary" else "dat")))
    wanted = tuple(c for c in out.columns if c in FILE_VALUES)
    options.setdefault("model", "elastic")
    c = hillstab.chart(grid[0], grid[1], values=wanted, threads=threads, **options)
    na, nb = grid[0][2], grid[1][2]
    assert same_bits(out["alpha"], np.repeat(c.alpha, nb))
    assert same_bits(out["beta"], np.tile(c.beta, na))
    assert same_bits(out["status"], c.status)
    assert c.names == wanted
    for column in out.columns:
        if column in FILE_VALUES:
            assert same_as_file(out, c, column), column
    return out, c


def test_chart_rows_in_parallel(cli):
    # 16 rows >= 4 per thread on 2 threads: whole rows in parallel
    out, c = compare_chart(cli, "rows", ((0.0, 9.8, 16), (-2.0, 12.0, 40)))
    assert set(np.unique(c.stable)) <= {0.0, 0.5, 1.0}
    assert np.all(c.status == 0)


def test_chart_rows_in_chunks(cli):
    # 3 rows < 4 per thread: each row in chunks sharing its meshes
    compare_chart(cli, "chunks", ((1.0, 9.5, 3), (-2.0, 30.0, 200)))


def test_chart_verdicts_only(cli):
    out, c = compare_chart(cli, "verdicts", ((0.0, 9.8, 16), (-2.0, 12.0, 40)), columns="alpha beta stable status")
    assert c.names == ("stable",)
    with pytest.raises(AttributeError):
        c.S
    with pytest.raises(AttributeError):
        c.trace
    # the verdicts agree with those of the full chart
    full = hillstab.chart((0.0, 9.8, 16), (-2.0, 12.0, 40), model="elastic")
    assert np.array_equal(full.stable, c.stable)


def test_chart_verdicts_text(cli):
    # the text file's verdict lines are written by their own loop: the same verdicts
    compare_chart(cli, "vtext", ((0.0, 9.8, 9), (-2.0, 12.0, 30)), columns="alpha beta stable status", fmt="text")


def test_chart_growth(cli):
    compare_chart(cli, "growth", ((0.0, 9.8, 8), (-2.0, 12.0, 30)), columns="alpha beta stable mu lambda_max status")


def test_chart_kind_and_argument(cli):
    # the file's kind and argument (written when named) equal the library's to the bit, for the
    # full computation and the verdicts alone; Mathieu at alpha = 0 is x'' + beta x = 0, S = 2 cos 2 sqrt(beta)
    grid = ((0.0, 4.0, 3), (-1.0, 12.0, 40))
    out, c = compare_chart(cli, "kinds", grid, model="mathieu", tolerance=1e-12,
                           columns="alpha beta kind argument S status")
    assert c.names == ("kind", "argument", "S")
    row = c.beta > 0
    root = 2.0 * np.sqrt(c.beta[row])
    inside = np.abs(np.cos(root)) < 0.999
    assert np.allclose(c.argument[0, row][inside], np.arccos(np.cos(root[inside])) / np.pi, rtol=0, atol=1e-9)
    assert np.all(c.kind[0, c.beta < 0] == 1) and np.all(c.argument[0, c.beta < 0] == 0.0)
    assert {0.0, 1.0, 2.0} <= set(np.unique(c.kind))
    assert np.all(c.argument[c.kind == 2] == 1.0)
    out, v = compare_chart(cli, "vkinds", grid, model="mathieu", tolerance=1e-12, columns="alpha beta kind status",
                           fmt="text")
    assert v.names == ("kind",)
    assert np.array_equal(v.kind[c.kind != 5], c.kind[c.kind != 5])


def test_chart_damped_mathieu(cli):
    compare_chart(cli, "damped", ((0.0, 12.0, 8), (-2.0, 20.0, 30)), model="mathieu", epsilon=0.2)
    compare_chart(cli, "dverdict", ((0.0, 12.0, 8), (-2.0, 20.0, 30)), model="mathieu", epsilon=0.2,
                  columns="alpha beta stable stable_paper status")


@pytest.mark.parametrize("method,options", [
    ("formula", {}), ("segments", {"n_segments": 16, "sampling": "average"}), ("magnus4", {}),
    ("magnus6", {}), ("rk", {}), ("gsl", {})])
def test_chart_methods(cli, method, options):
    compare_chart(cli, "m_" + method, ((0.5, 9.0, 4), (-1.0, 8.0, 7)), method=method, tolerance=1e-9,
                  **options)


def test_points(cli):
    rng = np.random.default_rng(5)
    alpha = rng.uniform(0.0, 9.8, 300)
    beta = rng.uniform(-5.0, 30.0, 300)
    with open(cli.path("pts.txt"), "w") as handle:
        for a, b in zip(alpha, beta):
            handle.write("{!r} {!r}\n".format(float(a), float(b)))
    cli.run("pts", "&scene task = 'points', output = 'pts', format = 'binary' /\n&points file = 'pts.txt' /\n")
    out = hillstab.read_output(cli.path("pts_points.bin"))
    r = hillstab.floquet(alpha, beta, model="elastic")
    assert same_bits(out["alpha"], alpha) and same_bits(out["beta"], beta)
    assert same_bits(out["status"], r.status)
    for column in out.columns:
        if column in FILE_VALUES:
            assert same_as_file(out, r, column), column
    # the multipliers: ln|lambda_max| is the first log modulus, mu its half
    assert np.allclose(np.log(r.lambda_max), r.log_moduli[:, 0], rtol=1e-12, atol=1e-12)
    assert same_bits(r.mu, 0.5 * r.log_moduli[:, 0] + 0.0)
    # trace() gives the same S
    assert same_bits(hillstab.trace(alpha, beta, model="elastic"), r.S)


def test_points_shapes_and_damping():
    r = hillstab.floquet(np.full((2, 3), 4.0), [1.0, 2.0, 3.0], epsilon=0.1)
    assert r.S.shape == (2, 3) and r.log_moduli.shape == (2, 3, 2) and r.status.shape == (2, 3)
    # damped and stable: lambda_max = exp(-epsilon) exactly where |S1| < 2
    inside = np.abs(r.S) < 2
    assert np.all(r.lambda_max[inside] == np.exp(-0.1))


def test_spring_units(cli):
    cli.run("spring", "&scene task = 'points', output = 'spring', format = 'binary' /\n"
                      "&physical k = 25, m = 0.25, g = 9.81, r0 = 0.3, a = 0.002, 0.02, 0.05 /\n")
    out = hillstab.read_output(cli.path("spring_points.bin"))
    s = hillstab.Spring(k=25, m=0.25, r0=0.3, g=9.81)
    a = [0.002, 0.02, 0.05]
    assert same_bits(out["a"], a)
    assert same_bits(out["alpha"], s.alpha(a))
    assert same_bits(out["beta"], np.full(3, s.beta))
    assert same_bits(out["mu_per_s"], s.growth_per_second(a))
    assert same_bits(out["stable"], s.stable(a))
    # the README's spring: 0.185 and 0.473 per second at 2 and 5 cm
    assert np.allclose(s.growth_per_second([0.02, 0.05]), [0.185, 0.473], atol=5e-4)


def test_spring_critical_amplitudes():
    s = hillstab.Spring(k=25, m=0.25, r0=0.3, g=9.81)
    critical = s.critical_amplitudes()
    assert critical.shape == (1,) and abs(critical[0] - 0.003811) < 1e-6
    assert s.stable([critical[0] / 2])[0] == 1.0
    assert s.stable([(critical[0] + s.rho) / 2])[0] == 0.0


def test_series_equals_program(cli):
    cli.run("fig4e", "&scene task = 'series', tolerance = 1e-10, output = 'fig4e' /\n"
                     "&series alpha = 7.88, beta = 3.95, phi0 = 0.017, periods = 5, r0 = 0.1, g = 9.81 /\n")
    out = hillstab.read_output(cli.path("fig4e_series.dat"))
    s = hillstab.series(7.88, 3.95, phi0=0.017, periods=5, r0=0.1, g=9.81)
    assert s.t.size == 501
    for column, array in (("t", s.t), ("r", s.r), ("phi", s.phi), ("x", s.x), ("z", s.z), ("E", s.energy)):
        assert same_bits(out[column], array), column


def test_run_scene_equals_program(cli):
    text = chart_scene("lib", ((0.0, 9.8, 6), (-2.0, 12.0, 11)), fmt="text")
    cli.run("lib", text)
    by_program = open(cli.path("lib_chart.dat")).read()
    path = cli.scene("lib2", text.replace("output = 'lib'", "output = '{}'".format(cli.path("lib2"))))
    out = hillstab.run_scene(path)
    by_library = open(out.path).read()
    data = lambda text: [line for line in text.splitlines() if not line.startswith("#")]
    assert data(by_library) == data(by_program) and len(data(by_program)) == 6 * 11 + 5
    assert "&chart alpha_min = 0.0, alpha_max = 9.8, n_alpha = 6" in out.scene
    assert out.columns[:4] == ["alpha", "beta", "S", "stable"]


def test_read_output_text_and_binary(cli):
    cli.run("t", chart_scene("t", ((0.0, 9.8, 5), (-2.0, 12.0, 7)), fmt="text"))
    cli.run("b", chart_scene("b", ((0.0, 9.8, 5), (-2.0, 12.0, 7)), fmt="binary"))
    text = hillstab.read_output(cli.path("t_chart.dat"))
    binary = hillstab.read_output(cli.path("b_chart.bin"))
    assert text.columns == binary.columns and text.data.shape == binary.data.shape == (35, len(text.columns))
    # 17 digits read back to the same double
    assert same_bits(text["S"], binary["S"]) and same_bits(text["beta"], binary["beta"])
    assert text.scene.replace("'text'", "'binary'").replace("'t'", "'b'") == binary.scene


def test_fourier_model_equals_program(cli):
    # a model with data: the scene's &fourier group and Model.set give the same file to the bit
    m = hillstab.Model("fourier").set("cos", [0.5, 0.0, 0.25]).set("sin", [0.0, 0.3])
    grid = ((0.0, 6.0, 8), (-2.0, 20.0, 30))
    cli.run("fourier", chart_scene("fourier", grid, model="fourier", epsilon=0.1)
            + "&fourier cos = 0.5, 0, 0.25, sin = 0, 0.3 /\n")
    out = hillstab.read_output(cli.path("fourier_chart.bin"))
    c = hillstab.chart(grid[0], grid[1], model=m, epsilon=0.1,
                       values=tuple(FILE_VALUES[k] for k in out.columns if k in FILE_VALUES))
    assert same_bits(out["status"], c.status)
    for column in out.columns:
        if column in FILE_VALUES:
            assert same_bits(out[column], getattr(c, FILE_VALUES[column])), column


def test_fourier_mathieu_limit_and_period():
    # f = -cos(pi tau) is Mathieu's coefficient: S agrees to the tolerance
    rng = np.random.default_rng(11)
    alpha = rng.uniform(0.0, 20.0, 200)
    beta = rng.uniform(-10.0, 60.0, 200)
    fourier = hillstab.Model("fourier").set("cos", [-1.0])
    s_fourier = hillstab.trace(alpha, beta, model=fourier, tolerance=1e-12)
    s_mathieu = hillstab.trace(alpha, beta, model="mathieu", tolerance=1e-12)
    assert np.all(np.abs(s_fourier - s_mathieu) <= 1e-9 * np.maximum(1.0, np.abs(s_mathieu)))
    # over a period 4 the exponent is ln|lambda_max| / 4, and damping costs epsilon P/2 a period
    slow = hillstab.Model("fourier").set("cos", [1.0, 0.3]).set("period", [4.0])
    r = hillstab.floquet(np.full(50, 0.8), np.linspace(0.2, 3.0, 50), model=slow, epsilon=0.05)
    assert np.allclose(r.exponent, r.log_moduli[:, 0] / 4.0, rtol=0, atol=1e-15)
    inside = np.abs(r.trace) < 2
    assert inside.any() and np.allclose(r.lambda_max[inside], np.exp(-0.1), rtol=1e-15)


def test_modulated_bounce_model():
    # the swing about r = rho - a cos(wt) cos(wt/2): registered, period 4, undriven at alpha = 0
    assert "modulated" in hillstab.model_names()
    beta = np.linspace(-3.0, 40.0, 30)
    s0 = hillstab.trace(np.zeros(30), beta, model="modulated", tolerance=1e-12)
    k = np.sqrt(np.abs(beta))
    closed = np.where(beta >= 0, 2.0 * np.cos(4.0 * k), 2.0 * np.cosh(4.0 * k))
    assert np.all(np.abs(s0 - closed) <= 1e-12 * np.maximum(1.0, np.abs(closed)))
    # auto (shared meshes carrying the offset) against magnus6 at a tighter tolerance
    rng = np.random.default_rng(5)
    alpha = rng.uniform(0.0, 9.7, 200)
    beta = rng.uniform(-5.0, 30.0, 200)
    s_auto = hillstab.trace(alpha, beta, model="modulated", tolerance=1e-10)
    s_ref = hillstab.trace(alpha, beta, model="modulated", method="magnus6", tolerance=1e-12)
    assert np.all(np.abs(s_auto - s_ref) <= 1e-10 * np.maximum(1.0, np.abs(s_ref)))
    # a >= rho (alpha >= pi^2) is refused, naming the domain
    with pytest.raises(ValueError, match="alpha < pi"):
        hillstab.trace(np.array([np.pi**2]), np.array([1.0]), model="modulated")
