"""Where the ease-off's grid lines cross a relief's corner: from the design (issue 71).

The ease-off's fields Q, ε and K (:class:`contact.utca.fields.EaseOffFields`) kink where
the mating points pass from one working section of a blade to the next — the start of a
tip or root relief (the blade's flankrem or toprem line, :mod:`geometry.machine.relief`)
on the pinion or the gear — and where the generated sheet ends and the fill
(:func:`contact.utca.easeoff.fill_missing`) continues it. A global interpolating spline
rings next to such a kink (30 µrad below flat node data on the FM 16×16 at Σ 60° with a
tip relief; docs/synthesis.md "The ease-off interpolant at a relief corner"), so the
fields' interpolant (:func:`contact.utca.corner_spline.corner_spline`) cuts its grid
lines there.

The cuts are read off the design, not the data: every node of the ease-off carries the
blade sections its two points lie on (``EaseOff.pinion_section``, ``gear_section``) and
whether it lies on the generated sheet (``valid | smooth``). A grid line crosses a relief
corner where two of its successive sheet nodes on working sections (``smooth``, with a
mate) lie on different sections, or where it holds a node of a corner's strip (``smooth``
without a mate, :func:`contact.utca.easeoff._corner_nodes`). Only such lines are cut, at
every change of the nodes' label along them (the pair of sections; the corner strip; the
fill): the two nodes of each cell where the label changes. A blade without relief has a
single working section (its profile), so no line is cut and the fields are the
interpolating splines as before; a measured deviation (wear, a CMM grid) added to the
ease-off changes neither the sections nor the sheet, so its own bends are never cut.

Public functions
----------------
relief_corners  the nodes at which the ease-off's lines along u and along v are cut
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from geometry.core.errors import InputError

if TYPE_CHECKING:
    from contact.utca.easeoff import EaseOff

__all__ = ["relief_corners"]

_FILL = -1  # label of a node off the sheet's working sections (filled or on an edge)
_STRIP = -2  # label of a node in a corner's strip (no mate on either face)


def _labels(eo: EaseOff) -> np.ndarray:
    """(nu, nv) int label of each node: the pair of sections of a sheet node with a mate
    on working sections, :data:`_STRIP` in a corner's strip, :data:`_FILL` elsewhere."""
    ps = np.asarray(eo.pinion_section)
    gs = np.asarray(eo.gear_section)
    if ps.shape != eo.reason.shape or gs.shape != eo.reason.shape:
        raise InputError(f"eo: pinion_section and gear_section must be {eo.reason.shape}, "
                         f"got {ps.shape} and {gs.shape}")
    mate = eo.reason != 2
    working = eo.smooth & mate
    out = np.full(eo.reason.shape, _FILL, dtype=np.int64)
    n_gear = int(gs[working].max()) + 1 if working.any() else 1
    out[working] = ps[working].astype(np.int64) * n_gear + gs[working]
    out[eo.smooth & ~mate] = _STRIP
    return out


def _line_cuts(labels: np.ndarray) -> np.ndarray:
    """Cuts along the first axis of ``labels`` (n, m): on the lines that cross a corner
    (two successive working-section labels differ, or a strip node), the two nodes of
    every cell whose labels differ."""
    out = np.zeros(labels.shape, dtype=bool)
    for line in range(labels.shape[1]):
        lab = labels[:, line]
        seen = lab[lab >= 0]
        if not (np.any(lab == _STRIP) or np.any(seen[1:] != seen[:-1])):
            continue
        change = lab[1:] != lab[:-1]
        out[1:, line] |= change
        out[:-1, line] |= change
    return out


def relief_corners(eo: EaseOff) -> tuple[np.ndarray, np.ndarray] | None:
    """The nodes at which the ease-off's grid lines are cut for a relief's corner.

    Parameters
    ----------
    eo : EaseOff
        The ease-off (:func:`contact.utca.easeoff.ease_off`), with its nodes' blade
        sections (``pinion_section``, ``gear_section``, (nu, nv) int) and ``smooth`` mask.

    Returns
    -------
    (cut_u, cut_v) : (ndarray of bool (nu, nv), ndarray of bool (nu, nv)) or None
        ``cut_u``: the nodes at which the lines along u (one per profile node) are cut;
        ``cut_v``: those of the lines along v (one per lengthwise node) —
        :func:`contact.utca.corner_spline.corner_spline`'s ``cut_x``, ``cut_y``. None
        where no line crosses a corner (no relief on either blade reaches the sheet, or
        the ease-off carries no sections): the fields keep the interpolating splines.

    Raises
    ------
    InputError
        Section arrays of another shape than the grid's.

    Notes
    -----
    Source: the module docstring (issue 71; docs/synthesis.md "The ease-off interpolant
    at a relief corner: corners from the design").
    """
    if eo.pinion_section is None or eo.gear_section is None:
        return None
    labels = _labels(eo)
    cut_u = _line_cuts(labels)
    cut_v = _line_cuts(labels.T).T
    if not (cut_u.any() or cut_v.any()):
        return None
    return cut_u, cut_v
