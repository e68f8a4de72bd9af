"""What a development says where every design it tried stopped on the basic data's own
synthesis error (issue 71, round 23).

The face-hobbed spiral bevel 19x57 by ISO 23509 Method 3 (rc0 100 mm, z0 5) stopped
``ltca synthesize`` with "the pinion convex flank could not be given the required
curvature at the mean point (residual 0.000534 1/mm); change the path angle, the TE
level or the ellipse length": its six development designs had varied the path angle and
the ellipse length, each stopping on that error with the same residual. The levers the
message names were tried; the basic data is what changes it (rc0 88 or 120 mm, z0 7 or
beta_m 30 deg each synthesised, docs/own_gear_set.md "Round 23").

A tapered depth is basic data too (round 36, branch unseen98): the FM spiral bevel 14x19
at Sigma 60 deg by Method 0 with theta_a2 1, theta_f2 4 deg stopped on "the gear flank
is not generated along the working depth at the mean cone distance" with every gear
process; rc0 50.8 or 76.2 mm (the fields the clause named) stopped the same, theta_f2 2
or 3 deg too; theta_a2 = theta_f2 = 0 (uniform depth) or beta_m 30 deg synthesised with
the Formate gear (whose tapered design had stopped on its tip relief; the generated gear
stopped on the same error at uniform depth too, and the Formate gear's development cut
its design torque from 110.7 to 3.2 N m).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence


def levers_tried_text(error: BaseException, reasons: Sequence[str],
                      values: Sequence[Mapping[str, float]], tapered: bool = False) -> str:
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
    tapered : bool, optional
        Default False. True where the basic design gives a tapered depth (``theta_a2`` or
        ``theta_f2`` not 0): the clause names those fields too (0 and 0, uniform depth,
        synthesised the 14x19 at Sigma 60 deg with its Formate gear, where rc0 did not).

    Returns
    -------
    str
        ``"; the development's N designs, varying a, b, each stopped on this same error:
        the basic data changes it (design.rc0, design.beta_m; design.z0 for face
        hobbing)"`` (with ``tapered`` "design.rc0, design.beta_m, design.theta_a2 and
        design.theta_f2 (0 and 0: uniform depth); …"), or ``""`` where fewer than two
        designs were tried, one was analysed or stopped otherwise, or no variable varied.
    """
    said = f"{type(error).__name__}: {error}".splitlines()[0]
    if len(reasons) < 2 or any(r != said for r in reasons):
        return ""
    names = sorted({k for v in values for k in v
                    if len({round(float(w.get(k, float("nan"))), 9) for w in values}) > 1})
    if not names:
        return ""
    depth = (", design.theta_a2 and design.theta_f2 (0 and 0: uniform depth)" if tapered
             else "")
    return (f"; the development's {len(reasons)} designs, varying {', '.join(names)}, each "
            "stopped on this same error: the basic data changes it (design.rc0, "
            f"design.beta_m{depth}; design.z0 for face hobbing)")
