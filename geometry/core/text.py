"""Numbers in the texts users read: plain digits, four significant figures.

A torque printed ``f"{t:.4g}"`` read "1.044e+04 N m" for an industrial pair's 10440 N·m,
and one printed ``f"{t:g}"`` read "72.8667 / 120.533 N m" (issue 71, round 19). Every
layer (geometry, friction, contact) may import this module: it is part of the toolkit's
low layer and imports nothing else of the toolkit.
"""

from __future__ import annotations

import math

__all__ = ["plain_number"]

#: the decimal exponents (of the value rounded to its significant figures) printed in plain
#: digits: 0.0001 up to below 10¹² — every torque [N·m], pressure [MPa], angle [µrad] or
#: length [mm] a user meets; outside it, only a wrong or degenerate value, an exponent
PLAIN_EXPONENTS = range(-4, 12)


def plain_number(value: float, digits: int = 4) -> str:
    """A number as users read it in a line of text: plain digits, ``digits`` significant
    figures, never an exponent for the values users meet.

    The rule (units agnostic: the caller writes the unit): the value is rounded to
    ``digits`` significant figures and written in positional notation with no trailing
    zeros after the decimal point and no trailing point — 10440 → ``"10440"``, 852.24 →
    ``"852.2"``, 72.8667 → ``"72.87"``, 0.04520 → ``"0.0452"``, 1234567 → ``"1235000"``
    (the digits past the significant figures are zeros, not an exponent); negative values
    keep their sign, -0.0 reads ``"0"``. Only a value whose rounded magnitude is below
    10⁻⁴ or at least 10¹² (never a torque, pressure, angle or length of a gear set) is
    written with an exponent, ``"1.5e-07"``, as :func:`format` with ``.4g`` would. NaN reads
    ``"NaN"``, the infinities ``"inf"`` and ``"-inf"``.

    Parameters
    ----------
    value : float
        The number, in the unit the caller prints beside it — [any].
    digits : int, optional
        The significant figures, ≥ 1 (default 4).

    Returns
    -------
    str
        The text of the number.

    Raises
    ------
    ValueError
        If ``digits`` is below 1.

    Notes
    -----
    A tool, no physics: the rounding is Python's correctly rounded decimal conversion
    (:func:`format` with ``.{digits-1}e``), half to even on the binary value's exact decimal
    expansion.
    """
    if digits < 1:
        raise ValueError(f"digits: must be >= 1, got {digits}")
    x = float(value)
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "inf" if x > 0 else "-inf"
    if x == 0.0:
        return "0"
    # the exponent after rounding to the significant figures (9.99996 → 1.000e+01)
    mantissa, _, exponent = f"{x:.{digits - 1}e}".partition("e")
    exp = int(exponent)
    if exp not in PLAIN_EXPONENTS:
        return f"{x:.{digits}g}"
    if exp >= digits - 1:
        # whole digits beyond the significant ones are zeros: build them from the mantissa
        return mantissa.replace(".", "") + "0" * (exp - (digits - 1))
    text = f"{x:.{digits - 1 - exp}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text
