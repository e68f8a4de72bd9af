"""What a development says where every design it tried stopped on the basic data's own
synthesis error (issue 71, round 23).

The face-hobbed spiral bevel 19x57 by ISO 23509 Method 3 (rc0 100 mm, z0 5) stopped
``ltca synthesize`` with "the pinion convex flank could not be given the required
curvature at the mean point (residual 0.000534 1/mm); change the path angle, the TE
level or the ellipse length": its six development designs had varied the path angle and
the ellipse length, each stopping on that error with the same residual. The levers the
message names were tried; the basic data is what changes it (rc0 88 or 120 mm, z0 7 or
beta_m 30 deg each synthesised, docs/own_gear_set.md "Round 23").
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence


def levers_tried_text(error: BaseException, reasons: Sequence[str],
                      values: Sequence[Mapping[str, float]]) -> str:
    """The clause added to the basic design's synthesis error where every design of the
    development stopped on that same error.

    Parameters
    ----------
    error : BaseException
        The basic design's own synthesis error (the prescriptions as given).
    reasons : sequence of str
        Each development design's failure, ``"<ExceptionType>: <first line>"`` ("" for a
        design that was analysed), as :class:`DevelopmentEvaluation.reason` holds it.
    values : sequence of mapping
        Each design's development variables (name → value; units of
        :class:`~contact.optimize.development_targets.DevelopmentTargets`' bounds).

    Returns
    -------
    str
        ``"; the development's N designs, varying a, b, each stopped on this same error:
        the basic data changes it (design.rc0, design.beta_m; design.z0 for face
        hobbing)"``, or ``""`` where fewer than two designs were tried, one was analysed
        or stopped otherwise, or no variable varied.
    """
    said = f"{type(error).__name__}: {error}".splitlines()[0]
    if len(reasons) < 2 or any(r != said for r in reasons):
        return ""
    names = sorted({k for v in values for k in v
                    if len({round(float(w.get(k, float("nan"))), 9) for w in values}) > 1})
    if not names:
        return ""
    return (f"; the development's {len(reasons)} designs, varying {', '.join(names)}, each "
            "stopped on this same error: the basic data changes it (design.rc0, "
            "design.beta_m; design.z0 for face hobbing)")
