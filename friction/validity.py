"""The warning every friction/lubrication correlation raises outside its validity range.

Kept in its own module so that the model modules (:mod:`friction.coefficient`,
:mod:`friction.film`, :mod:`friction.mixed_ehl`) can all raise it without importing one
another; :mod:`friction.coefficient` re-exports it under the same name.
"""

from __future__ import annotations

__all__ = ["FrictionModelRangeWarning"]


class FrictionModelRangeWarning(UserWarning):
    """Inputs leave the range a friction/lubrication correlation was fitted on.

    The result is still finite (clipped where the formula breaks down, as the message
    says) but is an extrapolation.
    """
