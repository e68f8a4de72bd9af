"""The basic data of a gear pair as the report's table, from the case file as run.

Public functions
----------------
basic_data_rows   (quantity, pinion, gear) rows: teeth, hands, process, blank, cutter,
                  blade (pressure) angles and the flanks' spiral angles at the mean point
flank_spiral_angle  the spiral angle of a generated flank at the mean point of its pitch cone
"""

from __future__ import annotations

import logging
import math

import numpy as np

from geometry.case import Case, Member
from geometry.core.errors import LTCAError

__all__ = ["basic_data_rows", "flank_spiral_angle"]

log = logging.getLogger(__name__)


def flank_spiral_angle(member: Member, flank: str, step: float = 0.5) -> float:
    """[rad] The spiral angle of a generated flank where it crosses the pitch cone at the
    mean cone distance.

    Parameters
    ----------
    member : geometry.case.Member
    flank : str
        ``"concave"`` or ``"convex"``.
    step : float — [mm]
        Half the distance along the pitch-cone generatrix between the two flank points.

    Returns
    -------
    float
        |β| = atan(ρ_m dθ/dR): θ the flank's azimuth about the member axis at the two points
        of the pitch cone R_m ± step, ρ_m the pitch radius there (the angle between the
        flank's trace on the pitch cone and the generatrix, ISO 23509's spiral angle, taken
        on the flank rather than on the tooth's centre line, so concave and convex differ by
        the taper of the slot).

    Raises
    ------
    InputError
        If the flank is not generated at those points.
    """
    from geometry.machine.flank import blank_outline
    from geometry.machine.flank_point import flank_points

    blank = member.blank
    pm = blank_outline(blank).mean_point
    d = blank.pitch_angle
    along = np.array([math.cos(d), math.sin(d)])
    pts = np.array([pm - step * along, pm + step * along])
    tool = getattr(member, flank)
    fp = flank_points(tool.blade, tool.machine, blank, member.hand, pts[:, 0], pts[:, 1])
    theta = np.unwrap(np.arctan2(fp.r[:, 1], fp.r[:, 0]))
    return math.atan(abs(float(pm[1]) * float(theta[1] - theta[0]) / (2.0 * step)))


def _deg(x: float, digits: int = 2) -> str:
    return f"{math.degrees(x):.{digits}f}"


def _spiral(member: Member) -> str:
    try:
        c, v = (flank_spiral_angle(member, f) for f in ("concave", "convex"))
    except (LTCAError, ValueError, FloatingPointError) as exc:
        log.info("spiral angle of the %s not computed: %s", member.name, exc)
        return "–"
    return f"{math.degrees(c):.2f} / {math.degrees(v):.2f}"


def basic_data_rows(case: Case) -> dict:
    """The pair's basic data for the report's table.

    Parameters
    ----------
    case : geometry.case.Case
        The case as run (``case_from_dict`` of the file's ``inputs``).

    Returns
    -------
    dict
        ``pair``: (quantity, value) rows of the pair (method, shaft angle [deg], offset
        [mm], drive flank); ``members``: (quantity, pinion, gear) rows (teeth, hand,
        process, face width, outer cone distance [mm], pitch angle [deg], spiral angle of
        the concave / convex flank at the mean point [deg], blade angle of the concave /
        convex blade [deg], cutter: point radii or blade groups and radius [mm]).
    """
    p = case.pair
    pair = [("method", "face hobbing (FH)" if p.method.upper() == "FH" else
             "face milling (FM)" if p.method.upper() == "FM" else p.method),
            ("shaft angle Σ [°]", f"{math.degrees(p.shaft_angle):g}"),
            ("offset a [mm]", f"{p.offset:g}"),
            ("drive flank (pinion)", p.drive_flank)]
    pin, gear = case.pinion, case.gear

    def row(name: str, fn) -> tuple[str, str, str]:
        return (name, fn(pin), fn(gear))

    def cutter(m: Member) -> str:
        radii = f"{m.concave.blade.point_radius:.2f} / {m.convex.blade.point_radius:.2f}"
        if m.blade_groups:
            return (f"{m.blade_groups} blade groups, r_c0 {m.cutter_radius:.2f}; point radii "
                    f"{radii}")
        return f"point radii {radii}"

    members = [
        row("teeth z", lambda m: str(m.blank.teeth)),
        row("hand", lambda m: m.hand),
        row("process", lambda m: m.process),
        row("face width b [mm]", lambda m: f"{m.blank.face_width:.2f}"),
        row("outer cone distance R_e [mm]", lambda m: f"{m.blank.outer_cone_distance:.2f}"),
        row("pitch angle δ [°]", lambda m: _deg(m.blank.pitch_angle)),
        row("spiral angle at the mean point, concave / convex flank [°]", _spiral),
        row("blade (pressure) angle, concave / convex blade [°]",
            lambda m: f"{_deg(m.concave.blade.blade_angle)} / {_deg(m.convex.blade.blade_angle)}"),
        row("cutter [mm]", cutter),
    ]
    return {"pair": pair, "members": members}
