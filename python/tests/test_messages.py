"""The library's messages carried by ValueError give their numbers in Python's format (the
value passed, as repr shows it), never Fortran's E edit descriptors; the words are the
library's."""
import re

import numpy as np
import pytest

import hillstab
from hillstab._capi import python_numbers

FORTRAN = re.compile(r"\d\.\d+E[-+]\d")


def message(call):
    with pytest.raises(ValueError) as caught:
        call()
    text = str(caught.value)
    assert not FORTRAN.search(text), text
    return text


def test_alpha_outside_the_elastic_domain():
    text = message(lambda: hillstab.floquet([1.0, -0.1], 1.0, model="elastic"))
    assert text == ("point 1 (alpha = -0.1, beta = 1.0, epsilon = 0.0): elastic model needs 0 <= alpha < "
                    "pi**2 = 9.869604401089358 (amplitude a < rho), got alpha = -0.1")
    assert "got alpha = 10.0" in message(lambda: hillstab.chart((0.5, 10.0, 3), (0.0, 1.0, 3), model="elastic"))
    assert "got alpha = -1.0" in message(lambda: hillstab.transition_curves([1.0, -1.0], 0.0, 1.0))


def test_negative_damping_shows_the_value_passed():
    # the library writes it to 6 digits (-1.23457E-01): the message gives the value passed
    text = message(lambda: hillstab.floquet(1.0, 1.0, model="elastic", epsilon=-0.123456789))
    assert text.endswith("epsilon must be >= 0, got -0.123456789")
    text = message(lambda: hillstab.chart((0.5, 1.0, 3), (0.0, 1.0, 3), model="mathieu", epsilon=-0.25))
    assert text.endswith("epsilon must be >= 0, got -0.25")


def test_tolerance_of_a_method():
    assert message(lambda: hillstab.floquet(1.0, 1.0, model="elastic", method="rk", tolerance=-1.0)).endswith(
        "tolerance must be > 0, got -1.0")
    assert message(lambda: hillstab.floquet(1.0, 1.0, model="elastic", method="gsl", tolerance=-2.5e-3)).endswith(
        "got -0.0025")


def test_spring_checks_first():
    assert message(lambda: hillstab.Spring(k=-25, m=0.25, r0=0.3)) == "k: the spring constant must be > 0, got -25.0"
    assert message(lambda: hillstab.Spring(k=25, m=0.0, r0=0.3)) == "m: the mass must be > 0, got 0.0"


def test_python_numbers():
    assert python_numbers("got -1.00000E-01") == "got -0.1"
    assert python_numbers("got -1.23457E-01") == "got -0.123457"            # only the digits printed
    assert python_numbers("got -1.23457E-01", [-0.1234567]) == "got -0.1234567"
    assert python_numbers("pi**2 = 9.8696044010893586, x = 1.0E+01, 0.0000000000000000E+000") == \
        "pi**2 = 9.869604401089358, x = 10.0, 0.0"
    # numbers already short, words and names with digits stay
    assert python_numbers("got 10.5 at 1.0e-30; mu_1.5, x1.0E+00y") == "got 10.5 at 1.0e-30; mu_1.5, x1.0E+00y"
    assert float(python_numbers("1.0000000000000001E-01")) == 0.1
    x = np.nextafter(0.1, 1.0)
    assert float(python_numbers("{:.16E}".format(x))) == x                # 17 digits: the double itself
