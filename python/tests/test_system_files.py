"""System charts and points in every format read back alike: numpy on the text, Python's
read_output on text and binary, with the chosen columns only."""
import numpy as np

import hillstab

SYSTEM = ("&system n = 2, b = 1.0, 0.0, 0.0, 16.0, cos = -1.0, -0.6, -0.6, -4.0 /\n"
          "&chart alpha_min = 0.0, alpha_max = 1.0, n_alpha = 3, beta_min = -5.0, beta_max = 3.0, n_beta = 4 /\n")


def chart(cli, name, fmt, columns=""):
    chosen = ", columns = '{}'".format(columns) if columns else ""
    cli.run(name, "&scene task = 'chart', model = 'system', output = '{}', format = '{}'{} /\n".format(
        name, fmt, chosen) + SYSTEM)
    return hillstab.read_output(cli.path(name + "_chart." + ("bin" if fmt == "binary" else "dat")))


def test_system_chart_binary_reads_as_text(cli):
    text = chart(cli, "t", "text")
    binary = chart(cli, "b", "binary")
    assert text.columns == binary.columns
    assert text.data.shape == binary.data.shape == (12, len(text.columns))
    # the text keeps 17 significant digits
    assert np.allclose(text.data, binary.data, rtol=1e-15, atol=0)
    assert np.array_equal(np.loadtxt(cli.path("t_chart.dat"), ndmin=2), text.data)


def test_system_chart_binary_chosen_columns(cli):
    full = chart(cli, "f", "binary")
    some = chart(cli, "s", "binary", "alpha beta mu_2 status")
    assert some.columns == ["alpha", "beta", "mu_2", "status"]
    for k, name in enumerate(some.columns):
        assert np.array_equal(some.data[:, k], full.data[:, full.columns.index(name)])


def test_system_points_binary(cli):
    with open(cli.path("m.pts"), "w") as handle:
        handle.write("1.012481 -237.313324\n0.5 1.0\n")
    cli.run("p", "&scene task = 'points', model = 'system', output = 'p', format = 'binary' /\n"
            "&system n = 2, b = 1.0, 0.0, 0.0, 16.0, cos = -1.0, -0.6, -0.6, -4.0 /\n&points file = 'm.pts' /\n")
    out = hillstab.read_output(cli.path("p_points.bin"))
    assert out.data.shape == (2, len(out.columns))
    # Mettler's column far out: both exponents (a 150-bit reference: 61.6199050, 15.4049582)
    assert abs(out["mu_1"][0] - 61.6199050) < 1e-6 and abs(out["mu_2"][0] - 15.4049582) < 1e-6
    assert out["status"][0] == 0 and out["steps"][0] > 0
