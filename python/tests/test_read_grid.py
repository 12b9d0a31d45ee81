"""read_output of a chart file gives its columns as 2-D arrays [i_alpha, i_beta] with the
axes, the shape of hillstab.chart / System.chart: equal to them to the bit (binary) and to
the 17 digits of the text (S, alpha, beta; the columns written with 11 digits to those)."""
import numpy as np
import pytest

import hillstab
from hillstab.scenes import grid_values

GRID = ((0.1, 9.7, 7), (-2.3, 11.9, 13))
# the files' names of Result's values
SCALAR = {"S": "trace", "stable": "stable", "lambda_max": "lambda_max", "mu": "exponent",
          "log10_abs_S": "log10_abs_trace", "overflow": "overflow", "error_estimate": "error_estimate",
          "status": "status"}
SYSTEM = ("&system n = 2, mass = 1.0, 0.0, 0.0, 0.64, b = 1.1, -0.1, -0.1, 0.9, cos = -1.0, 0.0, 0.0, -0.8 /\n")


def scene(name, fmt, model="mathieu", columns="", epsilon=0.05, extra=""):
    (a0, a1, na), (b0, b1, nb) = GRID
    return ("&scene task = 'chart', model = '{}', epsilon = {!r}, output = '{}', format = '{}', columns = '{}' /\n"
            "{}&chart alpha_min = {!r}, alpha_max = {!r}, n_alpha = {}, beta_min = {!r}, beta_max = {!r}, "
            "n_beta = {} /\n".format(model, epsilon, name, fmt, columns, extra, a0, a1, na, b0, b1, nb))


def run(cli, name, fmt, **options):
    cli.run(name, scene(name, fmt, **options), threads=2)
    return hillstab.read_output(cli.path(name + "_chart." + ("bin" if fmt == "binary" else "dat")))


def bits(a, b):
    return a.shape == b.shape and np.array_equal(np.asarray(a, dtype=np.float64).view(np.uint64),
                                                 np.asarray(b, dtype=np.float64).view(np.uint64))


@pytest.mark.parametrize("fmt", ["binary", "text"])
def test_scalar_chart_as_grid(cli, fmt):
    out = run(cli, "c" + fmt, fmt)
    c = hillstab.chart(GRID[0], GRID[1], model="mathieu", epsilon=0.05, threads=2)
    assert out.is_grid and out.grid_shape == (7, 13) and out.axis_names == ("alpha", "beta")
    alpha, beta = out.axes
    assert bits(alpha, c.alpha) and bits(beta, c.beta)
    for column, value in SCALAR.items():
        grid = out.grid(column)
        assert grid.shape == (7, 13)
        if fmt == "binary" or column in ("S", "stable", "overflow", "status"):
            assert bits(grid, getattr(c, value)), column
        else:
            # written with 11 digits (error_estimate with 4)
            rtol = 1e-3 if column == "error_estimate" else 1e-10
            assert np.allclose(grid, getattr(c, value), rtol=rtol, atol=1e-300), column
    # the flat columns are as they were: one entry a row of the file
    assert out["S"].shape == (91,) and out.data.shape == (91, len(out.columns))
    assert bits(out["S"], c.trace.ravel())


@pytest.mark.parametrize("fmt", ["binary", "text"])
def test_system_chart_as_grid(cli, fmt):
    out = run(cli, "s" + fmt, fmt, model="system", extra=SYSTEM, epsilon=0.0)
    pair = hillstab.System(mass=np.diag([1.0, 0.64]), b=[[1.1, -0.1], [-0.1, 0.9]], cos=-np.diag([1.0, 0.8]))
    c = pair.chart(GRID[0], GRID[1], threads=2)
    assert out.grid_shape == (7, 13) and list(out.columns) == list(c.names)
    assert bits(out.axes[0], c.alpha) and bits(out.axes[1], c.beta)
    for name in c.names:
        if fmt == "binary" or name in ("alpha", "beta", "trace", "a2", "stable", "kind", "status", "steps"):
            assert bits(out.grid(name), c[name]), name
        else:
            rtol = 1e-3 if name in ("error_estimate", "defect") else 1e-10
            assert np.allclose(out.grid(name), c[name], rtol=rtol, atol=1e-300), name


def test_axes_without_their_columns(cli):
    # columns 'S status': the axes come from the header's grid, as the library computes them
    out = run(cli, "few", "binary", model="elastic", columns="S status", epsilon=0.0)
    c = hillstab.chart(GRID[0], GRID[1], model="elastic", values=("trace",), threads=2)
    assert "alpha" not in out.columns
    assert bits(out.axes[0], c.alpha) and bits(out.axes[1], c.beta)
    assert bits(out.grid("S"), c.trace)


def test_spring_chart_axes(cli):
    cli.run("spring", "&scene task = 'chart', output = 'spring' /\n"
                      "&physical g = 9.81, r0 = 0.3, a_min = 0.0, a_max = 0.3, n_a = 4, omega_min = 6.0, "
                      "omega_max = 20.0, n_omega = 5 /\n")
    out = hillstab.read_output(cli.path("spring_chart.dat"))
    assert out.axis_names == ("a", "omega") and out.grid_shape == (4, 5)
    a, omega = out.axes
    assert np.allclose(a, [0.0, 0.1, 0.2, 0.3], rtol=1e-15) and omega[0] == 6.0 and omega[-1] == 20.0
    assert np.array_equal(out.grid("omega")[2], omega) and np.array_equal(out.grid("a")[:, 3], a)


def test_not_a_chart(cli):
    with open(cli.path("m.pts"), "w") as handle:
        handle.write("1.0 2.0\n3.0 4.0\n")
    cli.run("p", "&scene task = 'points', model = 'mathieu', output = 'p' /\n&points file = 'm.pts' /\n")
    out = hillstab.read_output(cli.path("p_points.dat"))
    assert not out.is_grid and out.grid_shape is None and out.axis_names is None
    with pytest.raises(ValueError, match="not a chart"):
        out.grid("S")
    with pytest.raises(ValueError, match="not a chart"):
        out.axes
    assert out["S"].shape == (2,)


def test_to_pandas(cli):
    pandas = pytest.importorskip("pandas")
    out = run(cli, "pd", "binary")
    table = out.to_pandas()
    assert isinstance(table, pandas.DataFrame)
    assert list(table.columns) == list(out.columns) and len(table) == 91
    assert np.array_equal(table["S"].to_numpy(), out["S"])


LOG = ((0.02, 9.5, 6), (0.01, 100.0, 9))
LOG_CHART = ("&chart alpha_min = 0.02, alpha_max = 9.5, n_alpha = 6, alpha_scale = 'log', beta_min = 0.01, "
             "beta_max = 100.0, n_beta = 9, beta_scale = 'log' /\n")


@pytest.mark.parametrize("columns", ["", "S status"])
def test_log_chart_as_grid(cli, columns):
    # &chart alpha_scale = beta_scale = 'log': chart(..., alpha_scale='log') is the task's file to
    # the bit, and read_output's axes are geometric, from the columns or from the header alike
    cli.run("lg", "&scene task = 'chart', model = 'elastic', format = 'binary', output = 'lg', columns = '{}' /\n"
            .format(columns) + LOG_CHART, threads=2)
    out = hillstab.read_output(cli.path("lg_chart.bin"))
    c = hillstab.chart(LOG[0], LOG[1], model="elastic", alpha_scale="log", beta_scale="LOG", threads=2)
    assert out.grid_shape == (6, 9) and out.axis_scales == ("log", "log")
    alpha, beta = out.axes
    assert bits(alpha, c.alpha) and bits(beta, c.beta)
    assert alpha[0] == 0.02 and alpha[-1] == 9.5 and beta[0] == 0.01 and beta[-1] == 100.0
    assert np.array_equal(beta[::2], [0.01, 0.1, 1.0, 10.0, 100.0])  # a decade every two steps
    assert np.allclose(np.diff(np.log(alpha)), np.log(9.5 / 0.02) / 5, rtol=1e-12)
    assert bits(out.grid("S"), c.trace) and bits(out.grid("status").astype(np.int8), c.status)
    assert bits(grid_values(0.02, 9.5, 6, "log"), c.alpha)
    # linear is the default and what a file without the scales says
    linear = hillstab.chart(LOG[0], LOG[1], model="elastic", values=("trace",), alpha_scale="linear")
    assert bits(linear.alpha, grid_values(0.02, 9.5, 6)) and linear.beta[1] == 0.01 + (100.0 - 0.01) / 8


def test_log_system_chart_as_grid(cli):
    cli.run("ls", "&scene task = 'chart', model = 'system', output = 'ls' /\n" + SYSTEM +
            LOG_CHART.replace("alpha_max = 9.5", "alpha_max = 1.2"), threads=2)
    out = hillstab.read_output(cli.path("ls_chart.dat"))
    pair = hillstab.System(mass=np.diag([1.0, 0.64]), b=[[1.1, -0.1], [-0.1, 0.9]], cos=-np.diag([1.0, 0.8]))
    c = pair.chart((0.02, 1.2, 6), LOG[1], threads=2, alpha_scale="log", beta_scale="log")
    assert out.axis_scales == ("log", "log")
    for name in ("alpha", "beta", "trace", "stable", "kind", "status"):
        assert bits(out.grid(name), c[name]), name
    assert bits(out.axes[0], c.alpha) and bits(out.axes[1], c.beta)


def test_log_scale_refused():
    with pytest.raises(ValueError, match="alpha_scale must be 'linear' or 'log', got 'logarithmic'"):
        hillstab.chart((0.1, 1.0, 3), (0.1, 1.0, 3), model="mathieu", alpha_scale="logarithmic")
    with pytest.raises(ValueError, match="a log beta axis needs beta_min and beta_max in"):
        hillstab.chart((0.1, 1.0, 3), (0.0, 1.0, 3), model="mathieu", beta_scale="log")
    pair = hillstab.System(mass=np.diag([1.0, 0.64]), b=[[1.1, -0.1], [-0.1, 0.9]], cos=-np.diag([1.0, 0.8]))
    with pytest.raises(ValueError, match="a log alpha axis needs"):
        pair.chart((-1.0, 1.0, 3), (0.1, 1.0, 3), alpha_scale="log")
    with pytest.raises(ValueError, match="beta_scale must be 'linear' or 'log'"):
        pair.chart((0.1, 1.0, 3), (0.1, 1.0, 3), beta_scale=None)
