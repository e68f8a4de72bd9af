"""Tests of geometry.core.hertz: the one Hertz line contact, in Johnson's contact modulus E*.

Checked against closed forms written independently here (Johnson, *Contact Mechanics*,
1985, Eq. 4.22 and 4.43–4.45), in E* and in the EHL literature's E′ = 2E* that the
friction stage used before, to 1e-14 relative; and the deprecated E′ wrappers of
friction.hertz against it.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from geometry.core.errors import InputError
from geometry.core.hertz import STEEL, contact_modulus, hertz_line_contact

E, NU = STEEL
# a spread of gear contacts: light to heavy loads, small to large radii
W = np.array([1e-3, 1.0, 50.0, 500.0, 2000.0, 1e4])
R = np.array([2.0, 5.0, 20.0, 40.0, 80.0, 300.0])


def test_steel_and_contact_modulus():
    assert STEEL == (206_000.0, 0.3)
    # Johnson Eq. 4.22 for equal bodies: E* = E / (2 (1 − ν²)); 113 187 MPa for steel
    assert contact_modulus(E, NU, E, NU) == pytest.approx(E / (2 * (1 - NU**2)), rel=1e-15)
    assert contact_modulus(E, NU, E, NU) == pytest.approx(113_187, abs=0.5)
    # dissimilar bodies, written out
    got = contact_modulus(206e3, 0.3, 70e3, 0.33)
    assert got == pytest.approx(1 / ((1 - 0.09) / 206e3 + (1 - 0.33**2) / 70e3), rel=1e-15)


def test_equal_materials_give_the_old_e_prime_bit_for_bit():
    # the friction stage computed E′ = 2 / (2 (1 − ν²)/E); 2 E* equals it exactly for
    # equal materials (a sum x + x and a scaling by 2 are exact), so its results stay
    # bit-identical
    old = 2.0 / (2 * (1 - NU**2) / E)
    assert 2.0 * contact_modulus(E, NU, E, NU) == old


def test_line_contact_agrees_with_johnsons_closed_forms():
    e_star = contact_modulus(E, NU, E, NU)
    hz = hertz_line_contact(W, R, e_star)
    # Johnson Eq. 4.43: b² = 4 w′ R / (π E*)
    np.testing.assert_allclose(hz.half_width, np.sqrt(4 * W * R / (math.pi * e_star)),
                               rtol=1e-14, atol=0)
    # Johnson Eq. 4.44–4.45: p₀ = 2 w′ / (π b) = √(w′ E* / (π R))
    np.testing.assert_allclose(hz.peak_pressure, np.sqrt(W * e_star / (math.pi * R)),
                               rtol=1e-14, atol=0)
    # the same in the EHL literature's E′ = 2E* (Hamrock 1991): b = √(8 w′ R/(π E′)),
    # p_h = √(w′ E′/(2π R)) — the forms friction.hertz used
    e_prime = 2 * e_star
    np.testing.assert_allclose(hz.half_width, np.sqrt(8 * W * R / (math.pi * e_prime)),
                               rtol=1e-14, atol=0)
    np.testing.assert_allclose(hz.peak_pressure, np.sqrt(W * e_prime / (2 * math.pi * R)),
                               rtol=1e-14, atol=0)
    # the elliptical pressure carries the load: ∫ p₀ √(1 − x²/b²) dx = π b p₀ / 2 = w′
    np.testing.assert_allclose(math.pi * hz.half_width * hz.peak_pressure / 2, W, rtol=1e-14)


def test_no_load_and_broadcasting():
    hz = hertz_line_contact([0.0, 100.0], 10.0, 1e5)
    assert hz.half_width[0] == 0.0 and hz.peak_pressure[0] == 0.0
    assert hz.half_width.shape == hz.peak_pressure.shape == (2,)
    hz = hertz_line_contact(W[:, None], R[None, :], np.array([1e5, 2e5])[:, None, None])
    assert hz.half_width.shape == (2, W.size, R.size)
    scalar = hertz_line_contact(100.0, 10.0, 1e5)
    assert scalar.half_width.shape == ()


@pytest.mark.parametrize(
    ("args", "field"),
    [
        ((-1.0, 10.0, 1e5), "load_per_length"),
        ((1.0, 0.0, 1e5), "radius"),
        ((1.0, 10.0, math.nan), "modulus"),
        ((np.ones(3), np.ones(2), 1e5), "load_per_length, radius, modulus"),
    ],
)
def test_bad_input_names_the_field(args, field):
    with pytest.raises(InputError, match=rf"^{field}: must"):
        hertz_line_contact(*args)


def test_deprecated_friction_wrappers_agree_and_warn():
    from friction.hertz import combined_modulus, half_width, peak_pressure

    e_prime = 2 * contact_modulus(E, NU, E, NU)
    hz = hertz_line_contact(W, R, e_prime / 2)
    with pytest.warns(DeprecationWarning, match="geometry.core.hertz.contact_modulus"):
        assert combined_modulus(E, NU, E, NU) == e_prime
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        np.testing.assert_array_equal(half_width(W, R, e_prime), hz.half_width)
        np.testing.assert_array_equal(peak_pressure(W, R, e_prime), hz.peak_pressure)
        assert isinstance(peak_pressure(100.0, 10.0, e_prime), float)
        np.testing.assert_allclose(combined_modulus([E, 70e3], NU, E, [NU, 0.33]),
                                   [e_prime, 2 * contact_modulus(70e3, NU, E, 0.33)],
                                   rtol=1e-15)
    with pytest.warns(DeprecationWarning, match=r"hertz_line_contact\(w, R, E\*\)\.half_width"):
        half_width(1.0, 1.0, e_prime)


def test_hertz_line_contact_of_checked_inputs_is_the_same_arithmetic():
    """The LTCA's unchecked Hertz line contact gives the checked one's numbers to the bit
    (zero loads included: p0 = 0 there), with the modulus as a float or an array.
    Milliseconds."""
    from geometry.core.hertz import hertz_line_contact_of_checked

    rng = np.random.default_rng(5)
    w = np.concatenate([rng.uniform(0.0, 3000.0, 200), [0.0, 1e-300, 5e4]])
    r = rng.uniform(0.5, 80.0, w.size)
    e = contact_modulus(210e3, 0.3, 206e3, 0.29)
    ref = hertz_line_contact(w, r, e)
    for modulus in (float(e), np.full(w.size, e)):
        got = hertz_line_contact_of_checked(w, r, modulus)
        assert np.array_equal(got.half_width, ref.half_width)
        assert np.array_equal(got.peak_pressure, ref.peak_pressure)
