"""Elastic–perfectly-plastic segments: the pressure and force limits of an analysis.

A segment whose Hertz line contact would exceed its material's contact-pressure limit p₀
(:mod:`geometry.core.materials`: the shakedown limit by default) carries at most the force
F_max = L π R_eq p₀²/E* at which it reaches it (Johnson 1985 Eq. 4.43–4.45), and the
load beyond passes to its neighbours: the bound F ≤ F_max of the contact QP
(:class:`contact.qp.ContactProblem`'s ``upper_bound``). The edge segments have this limit
by default (``LTCAOptions.edge_pressure_limit``), the contact-curve (flank) segments on
request (``LTCAOptions.flank_pressure_limit``).

Public functions
----------------
pressure_limits  the (edge, flank) contact-pressure limits an analysis uses [MPa]
force_limits     the segments' force limits F_max at those limits [N]
"""

from __future__ import annotations

import math

import numpy as np

from contact.ltca.options import LTCAOptions
from geometry.core.hertz import hertz_line_load
from geometry.core.materials import contact_pressure_limit, material

__all__ = ["force_limits", "pressure_limits"]


def pressure_limits(case, opts: LTCAOptions) -> tuple[float, float]:
    """(edge, flank) contact-pressure limits of an analysis.

    Parameters
    ----------
    case : geometry.case.Case
        Its members' ``material`` names the material table's entries.
    opts : LTCAOptions
        ``edge_pressure_limit`` and ``flank_pressure_limit`` (names of
        :data:`geometry.core.materials.CONTACT_PRESSURE_LIMITS`, or None).

    Returns
    -------
    (float, float) — [MPa]
        The peak Hertz pressure p₀ of a line contact at each limit, the lower of the two
        members' materials (both surfaces carry the same Hertz stresses); ``inf`` where a
        limit is off.

    Notes
    -----
    Johnson (1985) ch. 6 and §9.3 (:func:`geometry.core.materials.contact_pressure_limit`).
    """
    members = (material(case.pinion.material), material(case.gear.material))
    edge, flank = (
        math.inf if name is None else min(contact_pressure_limit(m, name) for m in members)
        for name in (opts.edge_pressure_limit, opts.flank_pressure_limit))
    return edge, flank


def force_limits(kind: np.ndarray, length: np.ndarray, r_eq: np.ndarray,
                 limits: tuple[float, float], modulus: float) -> np.ndarray | None:
    """The force limits F_max of segments: the force at which their Hertz line contact
    reaches the pressure limit, F_max = L π R_eq p₀²/E*.

    Parameters
    ----------
    kind : ndarray (...) of int
        Segment kind (0: contact curve, else an edge: ``Segments.kind``), broadcast
        against ``length``.
    length, r_eq : ndarray (...) — [mm]
        Segment length and equivalent radius (NaN where a segment has none).
    limits : (float, float) — [MPa]
        The (edge, flank) pressure limits p₀ (``inf``: none; :func:`pressure_limits`).
    modulus : float — [MPa]
        Contact modulus E* (:func:`geometry.core.hertz.contact_modulus`).

    Returns
    -------
    ndarray (...) — [N] or None
        ``inf`` where a segment's kind has no limit (NaN where it has no geometry); None
        where no kind has a limit.

    Notes
    -----
    Johnson (1985) Eq. 4.43–4.45 (:func:`geometry.core.hertz.hertz_line_load`).
    """
    if not (math.isfinite(limits[0]) or math.isfinite(limits[1])):
        return None
    length, r_eq = np.asarray(length, float), np.asarray(r_eq, float)
    p0 = np.broadcast_to(np.where(np.asarray(kind) == 0, limits[1], limits[0]), length.shape)
    bound = np.full(length.shape, np.inf)
    fin = np.isfinite(p0)
    ok = fin & np.isfinite(r_eq) & (r_eq > 0) & np.isfinite(length)
    bound[fin & ~ok] = np.nan
    bound[ok] = length[ok] * hertz_line_load(p0[ok], r_eq[ok], modulus)
    return bound
