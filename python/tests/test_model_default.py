"""Nothing silent about the model: floquet, trace and chart without ``model=`` use the
elastic pendulum and warn when points lie outside its physical domain 0 <= alpha < pi^2,
0 <= beta < pi^2 — the points whose ``physical`` column the command line writes 0."""
import warnings

import numpy as np
import pytest

import hillstab

ALPHA = np.array([1.0, 2.0, 3.0, 0.0, 9.8, 4.0, 5.0])
BETA = np.array([-1.0, 2.0, 12.0, 0.0, 9.86, np.pi ** 2, -1e-300])


def quiet(call):
    """The call's result, failing on any warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return call()


def test_domain_is_the_files_physical_column(cli):
    with open(cli.path("m.pts"), "w") as handle:
        handle.write("".join("{!r} {!r}\n".format(float(a), float(b)) for a, b in zip(ALPHA, BETA)))
    cli.run("p", "&scene task = 'points', model = 'elastic', output = 'p', columns = 'alpha beta physical' /\n"
                 "&points file = 'm.pts' /\n")
    physical = hillstab.read_output(cli.path("p_points.dat"))["physical"]
    from hillstab.floquet import in_physical_domain
    assert np.array_equal(in_physical_domain(ALPHA, BETA), physical == 1)
    assert physical.tolist() == [0, 1, 0, 1, 1, 0, 0]
    for k in range(ALPHA.size):
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            hillstab.floquet(ALPHA[k], BETA[k])
        said = [w for w in caught if "no model given" in str(w.message)]
        assert len(said) == (0 if physical[k] == 1 else 1), (ALPHA[k], BETA[k])


def test_warning_says_which_model_why_and_how():
    with pytest.warns(hillstab.HillstabWarning) as caught:
        r = hillstab.floquet([1.0, 2.0, 3.0], [2.0, -1.5, 12.0])
    text = str(caught[0].message)
    assert "elastic pendulum (model='elastic')" in text
    assert "2 of 3 point(s)" in text and "alpha = 2.0, beta = -1.5: beta < 0" in text
    assert "model='mathieu'" in text
    # warned at the caller's line, not inside the package
    assert caught[0].filename == __file__
    # the values are the elastic model's all the same (backwards compatible)
    assert np.array_equal(r.trace, hillstab.floquet([1.0, 2.0, 3.0], [2.0, -1.5, 12.0], model="elastic").trace)


def test_trace_and_chart_warn_too():
    with pytest.warns(hillstab.HillstabWarning, match=r"beta >= pi\*\*2") as caught:
        hillstab.trace(1.0, 12.0)
    assert caught[0].filename == __file__
    with pytest.warns(hillstab.HillstabWarning, match=r"10 of 35 point\(s\)") as caught:
        hillstab.chart((0.0, 9.8, 5), (-2.0, 12.0, 7), values=("stable",))
    assert caught[0].filename == __file__


def test_no_warning_inside_the_domain_or_with_a_model():
    quiet(lambda: hillstab.floquet([0.0, 9.8], [0.0, 9.8]))
    quiet(lambda: hillstab.trace(3.7, 2.47))
    quiet(lambda: hillstab.chart((0.0, 9.8, 5), (0.0, 9.8, 7), values=("stable",)))
    quiet(lambda: hillstab.floquet(2.0, -1.0, model="elastic"))
    quiet(lambda: hillstab.floquet(2.0, -1.0, model=hillstab.Model("elastic")))
    quiet(lambda: hillstab.trace(20.0, -5.0, model="mathieu"))
    quiet(lambda: hillstab.chart((0.0, 9.8, 5), (-2.0, 12.0, 7), model="elastic", values=("stable",)))


def test_spring_names_its_model():
    s = hillstab.Spring(k=25, m=0.25, r0=0.3)
    quiet(lambda: s.floquet([0.002, 0.05]))
