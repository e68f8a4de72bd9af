"""Tests of geometry.core.validation: the one set of input validators and their one message style.

Every refusal is an :class:`InputError` reading ``<field>: must be <accepted> [<unit>], got
<value>``; each validator accepts its boundary values where the bound is closed and refuses
them where it is open, refuses bool and text, and the array validator reports how many
entries are outside.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from geometry.core.errors import InputError
from geometry.core.validation import (
    broadcast,
    integer,
    one_of,
    positive,
    real,
    real_array,
    scalar_or_array,
)

# the one style: field, colon, "must be", the accepted set, the unit in brackets, the value
STYLE = r"^{field}: must be {accepted} \[{unit}\], got {got}$"


# ----------------------------------------------------------------------------- real
@pytest.mark.parametrize(
    ("kwargs", "value"),
    [
        ({}, -1e300),
        ({"low": 0.0}, 0.0),
        ({"high": 1.0}, 1.0),
        ({"low": 0.0, "high": 0.5, "high_open": True}, 0.0),
        ({"low": -1.0, "high": 1.0}, -1.0),
        ({"low": -1.0, "high": 1.0}, 1.0),
    ],
)
def test_real_accepts_closed_bounds(kwargs, value):
    got = real("x", value, unit="mm", **kwargs)
    assert got == value and type(got) is float


@pytest.mark.parametrize(
    ("kwargs", "value", "accepted"),
    [
        ({"low": 0.0, "low_open": True}, 0.0, "finite and > 0"),
        ({"low": 0.0}, -1e-300, "finite and >= 0"),
        ({"high": 1.0, "high_open": True}, 1.0, "finite and < 1"),
        ({"high": 1.0}, 1.5, "finite and <= 1"),
        ({"low": 0.0, "high": 0.5, "high_open": True}, 0.5, r"in \[0, 0\.5\)"),
        ({"low": 0.0, "high": 0.5, "low_open": True}, 0.0, r"in \(0, 0\.5\]"),
        ({}, math.inf, "finite"),
        ({}, math.nan, "finite"),
    ],
)
def test_real_refuses_open_bounds_in_the_one_style(kwargs, value, accepted):
    with pytest.raises(InputError,
                       match=STYLE.format(field="x", accepted=accepted, unit="mm",
                                          got=re.escape(repr(value)))):
        real("x", value, unit="mm", **kwargs)


@pytest.mark.parametrize("value", [True, False, np.bool_(True), "1.0", b"1", None, [1.0]])
def test_real_refuses_bool_text_and_non_numbers(value):
    with pytest.raises(InputError, match=r"^speed: must be a real number, finite and > 0 "
                                         r"\[rpm\], got "):
        real("speed", value, unit="rpm", low=0.0, low_open=True)


def test_real_without_unit_has_no_brackets():
    with pytest.raises(InputError, match=r"^count: must be finite and >= 1, got 0\.5$"):
        real("count", 0.5, low=1.0)


def test_real_scale_shows_the_display_unit():
    # an angle held in rad, bounded and reported in deg; the value returned is not scaled
    deg = math.pi / 180
    assert real("Sigma", 1.0, unit="deg", low=0.0, high=math.pi, scale=deg) == 1.0
    with pytest.raises(InputError, match=r"^Sigma: must be in \(0, 180\) \[deg\], got 200$"):
        real("Sigma", 200 * deg, unit="deg", low=0.0, high=math.pi, low_open=True,
             high_open=True, scale=deg)


# ----------------------------------------------------------------------------- positive
def test_positive_boundaries():
    assert positive("w", 5e-324, "N/mm") == 5e-324
    assert positive("k", 1.0, "1", high=1.0) == 1.0
    with pytest.raises(InputError, match=STYLE.format(field="w", accepted="finite and > 0",
                                                      unit="N/mm", got="0.0")):
        positive("w", 0.0, "N/mm")
    with pytest.raises(InputError, match=STYLE.format(field="k", accepted=r"in \(0, 1\]",
                                                      unit="1", got="1.5")):
        positive("k", 1.5, "1", high=1.0)
    with pytest.raises(InputError, match=r"^w: must be a real number"):
        positive("w", True, "N/mm")


# ----------------------------------------------------------------------------- arrays
def test_real_array_accepts_bounds_and_returns_a_new_float_array():
    src = np.array([0, 1, 2])
    got = real_array("load", src, unit="N", low=0.0, high=2.0)
    assert got.dtype == float and np.array_equal(got, src)
    assert not np.shares_memory(got, src)
    assert real_array("load", 3.0, unit="N").shape == ()


def test_real_array_reports_the_count_of_values_outside():
    with pytest.raises(InputError, match=r"^load: must be finite and >= 0 \[N\], got 2 of 4 "
                                         r"value\(s\) outside, e\.g\. -1\.0$"):
        real_array("load", [1.0, -1.0, 2.0, -3.0], unit="N", low=0.0)
    with pytest.raises(InputError, match=r"^r: must be finite and > 0 \[mm\], got 1 of 3 "
                                         r"value\(s\) outside, e\.g\. nan$"):
        real_array("r", [1.0, math.nan, 2.0], unit="mm", low=0.0, low_open=True)


@pytest.mark.parametrize("value", [True, "1.0", ["a", "b"], [True, False], [[1.0], [1.0, 2.0]],
                                   object()])
def test_real_array_refuses_bool_text_and_non_numbers(value):
    with pytest.raises(InputError, match=r"^v: must be real numbers, finite \[m/s\], got "):
        real_array("v", value, unit="m/s")


def test_real_array_rank():
    assert real_array("C", np.eye(2), ndim=2).shape == (2, 2)
    with pytest.raises(InputError, match=r"^C: must be 2-dimensional, got shape \(3,\)$"):
        real_array("C", [1.0, 2.0, 3.0], ndim=2)


def test_broadcast_and_scalar_or_array():
    a, b = broadcast(x=np.ones(3), y=2.0)
    assert a.shape == b.shape == (3,)
    with pytest.raises(InputError, match=r"^x, y: must broadcast together, got shapes "
                                         r"\(3,\), \(2,\)$"):
        broadcast(x=np.ones(3), y=np.ones(2))
    assert scalar_or_array(np.array(2.5)) == 2.5 and type(scalar_or_array(np.array(2.5))) is float
    arr = np.ones(2)
    assert scalar_or_array(arr) is arr


# ----------------------------------------------------------------------------- integer
def test_integer_bounds_inclusive():
    assert integer("n", 3, 3, 500) == 3
    assert integer("n", np.int64(500), 3, 500) == 500
    for bad in (2, 501):
        with pytest.raises(InputError, match=rf"^n: must be an integer in \[3, 500\], got {bad}$"):
            integer("n", bad, 3, 500)
    with pytest.raises(InputError, match=r"^n: must be an integer in \[1, inf\], got 0$"):
        integer("n", 0, 1)


@pytest.mark.parametrize("value", [True, np.bool_(False), 3.0, 3.5, "3", None])
def test_integer_refuses_bool_floats_and_text(value):
    with pytest.raises(InputError, match=r"^n: must be an integer in \[0, 9\], got "):
        integer("n", value, 0, 9)


def test_integer_allow_float_takes_integral_floats_only():
    assert integer("z1", 11.0, 5, 500, allow_float=True) == 11
    for bad in (11.5, math.inf, math.nan, True):
        with pytest.raises(InputError, match=r"^z1: must be an integer in \[5, 500\]"):
            integer("z1", bad, 5, 500, allow_float=True)


# ----------------------------------------------------------------------------- one_of
def test_one_of():
    assert one_of("flank", "drive", ("drive", "coast")) == "drive"
    with pytest.raises(InputError, match=r"^flank: must be one of \['coast', 'drive'\], "
                                         r"got 'left'$"):
        one_of("flank", "left", ("drive", "coast"))
    with pytest.raises(InputError, match=r"^flank: must be one of"):
        one_of("flank", ["unhashable"], {"drive", "coast"})


def test_a_computed_value_out_of_range_is_said_short_but_never_inside():
    """A computed float (round 14: the standard's eps_alpha 0.9881414345523601 in the
    scuffing line) is said with the fewest digits that still read outside the range
    ("0.9881" against >= 1); a value just past its bound keeps the digits that show it
    (1.0000000123 against <= 1, not "1"); short values as typed."""
    with pytest.raises(InputError, match=r"got 0\.9881$"):
        real("eps_alpha", 0.9881414345523601, unit="1", low=1.0)
    with pytest.raises(InputError, match=r"got 1\.0000000123$"):
        real("x", np.float64(1.0000000123), high=1.0)
    with pytest.raises(InputError, match=r"got 0\.0$"):
        real("x", 0.0, low=0.0, low_open=True)
