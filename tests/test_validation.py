"""Argument checks of the Python functions (bearing_fem.validation and its users)."""
from __future__ import annotations

import pytest

from bearing_fem import analytic, units
from bearing_fem.validation import require_finite, require_positive


@pytest.mark.parametrize("value", ["1e8", b"1", True, None, [1.0, "x"]])
def test_numbers_only(value):
    """A string that parses as a number is refused too: it is a unit slip or a typo."""
    with pytest.raises(ValueError, match=r"force must be (a number in N|finite \(N\)), got "):
        require_positive("force", value, "N")


def test_helpers_name_the_argument_of_a_string():
    with pytest.raises(ValueError, match=r"force must be a number in N, got '100'"):
        units.hertz_point("100", 0.01, 0.01, 2.2e11)
    with pytest.raises(ValueError, match=r"p must be a number in Pa, got '1e8'"):
        analytic.reduced_from_barus("1e8", 1e-8)
    assert require_finite("x", 2, "m") == 2.0
