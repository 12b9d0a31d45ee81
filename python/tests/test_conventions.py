"""The conventions the docstrings state: with damping, trace is S1 of chi = e^{eps tau/2} x
and lambda_max, exponent are of x — a factor e^{-eps} per period 2 between their multipliers."""
import numpy as np

import hillstab


def test_damped_values_are_of_x_and_the_trace_of_chi():
    rng = np.random.default_rng(11)
    alpha, beta = rng.uniform(0.0, 9.5, 400), rng.uniform(0.0, 9.5, 400)
    epsilon = rng.uniform(0.0, 0.6, 400)
    for model in ("elastic", "mathieu"):
        r = hillstab.floquet(alpha, beta, model=model, epsilon=epsilon, tolerance=1e-12)
        s1 = r.trace
        chi = np.where(np.abs(s1) > 2.0, (np.abs(s1) + np.sqrt(np.maximum(s1 * s1 - 4.0, 0.0))) / 2.0, 1.0)
        assert np.allclose(r.lambda_max, np.exp(-epsilon) * chi, rtol=1e-8)
        assert np.allclose(r.exponent, np.log(r.lambda_max) / 2.0, rtol=1e-12, atol=1e-15)
        inside = (np.abs(s1) < 2.0) & (r.stable == 1.0)
        # e^{-eps} as the library's exp gives it: within one unit in the last place of numpy's
        # (the two exp need not round alike: numpy's vectorised exp differs by CPU)
        expected = np.exp(-epsilon[inside])
        assert inside.sum() > 20 and np.all(np.abs(r.lambda_max[inside] - expected) <= np.spacing(expected))



def test_docstrings_say_so():
    for documented in (hillstab.floquet, hillstab.chart, hillstab.trace):
        assert "χ = e^{ετ/2} x" in documented.__doc__
    assert "e^{−ε}" in hillstab.Result.__doc__
