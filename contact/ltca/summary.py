"""Summaries of an ``/ltca`` dataset that more than one layer reports.

Public functions
----------------
edge_load_share   the share of the gear torque the edge segments carry, per torque
certification     whether every roll position of every torque has a certified contact
                  solution: the analysis' status and the sentence that says why not
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import xarray as xr

from geometry.core.errors import InputError

__all__ = ["ANALYSIS_STATUS", "Certification", "certification", "edge_load_share"]

#: an analysis' ``analysis_status`` (root attribute of its file, :func:`certification`):
#: every roll position of every torque certified; some torque with rolls uncertified; some
#: torque without one certified roll (no contact solution at that torque: the analysis failed)
ANALYSIS_STATUS = ("ok", "uncertified", "failed")


def edge_load_share(ltca: xr.Dataset) -> np.ndarray:
    """[1] Per torque, the share of the gear torque carried by the edge segments over the
    mesh cycles: Σ F·R over the edge segments / Σ F·R over all (seed Eq. 3.14's moments;
    :mod:`contact.ltca.edges`).

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca``: ``force`` (torque, roll, pair, segment) [N], ``moment_arm`` (roll, pair,
        segment) [mm], ``segment_kind`` (segment).

    Returns
    -------
    ndarray (NT,)
        In [0, 1]: the arms are positive on either flank (the sense the gear torque loads
        it; a pinion edge's on the coast flank since issue 60: files written before carry
        negative ones there and give a negative share). NaN where no segment carries load.

    Raises
    ------
    InputError
        If ``ltca`` lacks one of the variables.
    """
    missing = [k for k in ("force", "moment_arm", "segment_kind") if k not in ltca.variables]
    if missing:
        raise InputError(f"ltca: lacks {', '.join(missing)} (not an /ltca dataset)")
    moment = (np.nan_to_num(ltca.variables["force"].values)
              * np.nan_to_num(ltca.variables["moment_arm"].values)[None])
    edge = np.asarray(ltca.variables["segment_kind"].values != "curve")
    total = moment.sum(axis=(1, 2, 3))
    on_edges = moment[..., edge].sum(axis=(1, 2, 3))
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(total > 0, on_edges / total, np.nan)


class Certification(NamedTuple):
    """What :func:`certification` finds: ``status`` one of :data:`ANALYSIS_STATUS`,
    ``reason`` one sentence (empty for ``"ok"``), ``certified`` and ``rolls`` (NT,) the
    certified and all roll positions per torque.

    Notes
    -----
    A roll position is certified when its solution satisfies seed Eq. (3.12)–(3.14) —
    compatibility with the slack Y, complementarity F·Y = 0 and the torque equilibrium
    RᵀF = T — within the residual tolerances, computed by the toolkit (DESIGN.md, the loaded
    contact problem).
    """

    status: str
    reason: str
    certified: np.ndarray
    rolls: int


def certification(ltca: xr.Dataset) -> Certification:
    """Whether the loaded contact of an analysis is certified at every roll and torque.

    A roll position's solution is certified when the toolkit's own residuals of the four
    contact conditions (primal and dual feasibility, complementarity, torque equilibrium;
    DESIGN "The loaded contact problem", seed Eq. 3.12–3.14) are within the tolerance
    (:func:`contact.qp.solve_contact`, ``/ltca/found``). A torque none of whose rolls is
    certified has no contact solution at all: its LTE, pressures and efficiency are not
    results, and the analysis has *failed*. A torque with some rolls uncertified has
    no LTE summary over the mesh cycle (NaN): the analysis is *uncertified*.

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca``: ``found`` (torque, roll) int8 0/1, ``status`` (torque, roll) text,
        ``torque`` [N·m].

    Returns
    -------
    Certification
        The reason names the torques and the first uncertified roll's solver status,
        e.g. ``"no certified contact solution at T_p 250 N m (0 of 16 roll positions;
        roll 0: failed: backend raised RuntimeError: …)"``.

    Raises
    ------
    InputError
        If ``ltca`` lacks ``found``.
    """
    if "found" not in ltca.variables:
        raise InputError("ltca: lacks found (not an /ltca dataset)")
    found = np.asarray(ltca.variables["found"].values) > 0
    found = found.reshape(found.shape[0] if found.ndim > 1 else 1, -1)
    torques = np.atleast_1d(np.asarray(ltca.variables["torque"].values, float))
    status = (np.asarray(ltca.variables["status"].values, dtype=object).reshape(found.shape)
              if "status" in ltca.variables else np.full(found.shape, "", dtype=object))
    certified = found.sum(axis=1)
    rolls = found.shape[1]
    if bool(found.all()):
        return Certification("ok", "", certified, rolls)
    none = [i for i in range(found.shape[0]) if certified[i] == 0]
    which = none or [i for i in range(found.shape[0]) if certified[i] < rolls]
    first = which[0]
    j = int(np.argmin(found[first]))
    why = str(status[first, j]).strip()
    where = ", ".join(f"T_p {torques[i]:g} N m ({certified[i]} of {rolls} roll positions "
                      "certified)" for i in which)
    detail = f"; roll {j}: {why}" if why else ""
    if none:
        return Certification("failed", f"no certified contact solution at {where}{detail}",
                             certified, rolls)
    return Certification("uncertified", f"roll positions without a certified contact "
                         f"solution at {where}{detail}; the LTE summary over the mesh cycle "
                         "is undefined there (NaN)", certified, rolls)
