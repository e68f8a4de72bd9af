"""What a design study keeps of one analysis: the summaries gear engineers compare.

A sweep of a thousand points cannot keep a thousand ``/ltca`` groups (each a few MB);
it keeps, per point and torque, the numbers a sensitivity map or a tolerance histogram
is drawn from. :func:`point_summary` computes them from one :func:`contact.run_analysis`
tree, so a study's numbers are exactly those of the single analysis at the same inputs.

Public functions
----------------
point_summary      the summaries (per torque, and per speed for efficiency) of one tree
failed_summary     the same variables, NaN, for a point that has no result
summary_dims       the dims of a summary variable after the point's
summary_variable   a summary variable with its units and long name
plausibility_bits  the ``plausibility`` flag of one analysis (the causes' bits, per torque)
pattern_dimensions the loaded pattern's centre and extent (fractions and mm), per torque
SUMMARY_VARIABLES  their names
STATUS_MEANINGS    the meaning of the per-point ``status`` flag
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import xarray as xr

from contact.ltca.plausibility import (
    CAUSES,
    misalignment_warnings,
    plausibility_flags,
)
from contact.ltca.summary import edge_load_share
from geometry.case import Case
from geometry.core.conventions import binary_flag, data_var
from geometry.machine.flank import blank_outline
from geometry.pair.assembly import Misalignment

__all__ = ["STATUS_MEANINGS", "SUMMARY_VARIABLES", "failed_summary", "pattern_dimensions",
           "plausibility_bits", "point_summary", "summary_dims", "summary_variable"]

#: ``status`` flag values of a study point: 0 every roll position certified, 1 some roll
#: positions of some torque without a certified solution (their summaries are NaN or
#: taken over the certified rolls, see the variables), 2 the analysis failed (``reason``
#: says why; every summary NaN).
STATUS_MEANINGS = ("ok", "uncertified", "failed")

#: (name, dims after the point's, units, long name) of every summary variable
_VARIABLES: tuple[tuple[str, tuple[str, ...], str, str], ...] = (
    ("lte_mean", ("torque",), "urad", "mean loaded transmission error"),
    ("lte_peak_to_peak", ("torque",), "urad", "peak-to-peak loaded transmission error"),
    ("lte_harmonics", ("torque", "harmonic"), "urad",
     "amplitude of the first three mesh harmonics of the loaded transmission error"),
    ("ute_peak_to_peak", (), "urad", "peak-to-peak unloaded transmission error"),
    ("pressure_max_flank", ("torque",), "MPa",
     "peak Hertzian pressure of the flank (contact-curve) segments"),
    ("pressure_max_edge", ("torque",), "MPa",
     "peak Hertzian pressure of the edge-contact segments (0 where none)"),
    ("edge_load_share", ("torque",), "1",
     "share of the gear torque carried by edge contact, over the mesh cycles"),
    ("pattern_centre_u", ("torque",), "1",
     "pressure-weighted centre of the loaded pattern on the gear flank, fraction of the "
     "face width (toe 0, heel 1)"),
    ("pattern_centre_v", ("torque",), "1",
     "pressure-weighted centre of the loaded pattern on the gear flank, fraction of the "
     "whole depth from root cone (0) to face cone (1)"),
    ("pattern_toe_u", ("torque",), "1", "toe end of the loaded pattern (fraction of face width)"),
    ("pattern_heel_u", ("torque",), "1",
     "heel end of the loaded pattern (fraction of face width)"),
    ("pattern_root_v", ("torque",), "1",
     "root end of the loaded pattern (fraction of the whole depth)"),
    ("pattern_tip_v", ("torque",), "1",
     "tip end of the loaded pattern (fraction of the whole depth)"),
    ("pattern_centre_lengthwise", ("torque",), "mm",
     "centre of the loaded pattern from the toe, along the face width"),
    ("pattern_centre_profile", ("torque",), "mm",
     "centre of the loaded pattern from the root cone, along the depth at the centre"),
    ("pattern_length", ("torque",), "mm", "lengthwise extent of the loaded pattern"),
    ("pattern_height", ("torque",), "mm", "profile extent of the loaded pattern"),
    ("certified", ("torque",), "1", "every roll position has a certified contact solution"),
    ("efficiency", ("torque", "speed"), "1",
     "mechanical mesh efficiency, mean over the mesh cycles"),
    ("power_loss", ("torque", "speed"), "W", "mesh power loss, mean over the mesh cycles"),
    ("root_stress_max", ("torque", "member"), "MPa",
     "peak tensile tooth-root stress over the mesh cycles (pinion, gear; FE influence "
     "coefficients, contact.ltca.root_stress)"),
    ("plausibility", ("torque",), "1",
     "causes for which the point's results are implausible, as ltca run warns "
     "(contact.ltca.plausibility; 0 none)"),
)

SUMMARY_VARIABLES: tuple[str, ...] = tuple(v[0] for v in _VARIABLES)


def _pattern(envelope: np.ndarray, u: np.ndarray, v: np.ndarray) -> dict[str, np.ndarray]:
    """Centre (pressure-weighted) and extent of the pattern (NT, nu, nv) [MPa] on the
    gear grid fractions u (nu,), v (nv,); NaN for a torque with no loaded node."""
    NT = envelope.shape[0]
    out = {k: np.full(NT, np.nan) for k in ("cu", "cv", "u0", "u1", "v0", "v1")}
    for it in range(NT):
        p = np.nan_to_num(envelope[it])
        loaded = p > 0.0
        if not loaded.any():
            continue
        w = p / p.sum()
        out["cu"][it] = float((w.sum(axis=1) * u).sum())
        out["cv"][it] = float((w.sum(axis=0) * v).sum())
        iu = np.flatnonzero(loaded.any(axis=1))
        iv = np.flatnonzero(loaded.any(axis=0))
        out["u0"][it], out["u1"][it] = u[iu[0]], u[iu[-1]]
        out["v0"][it], out["v1"][it] = v[iv[0]], v[iv[-1]]
    return out


def _depth_at(case: Case, u: np.ndarray) -> np.ndarray:
    """Whole depth [mm] of the gear blank between root and face cones at the face-width
    fractions u, in its projection plane (blank corners interpolated)."""
    c = blank_outline(case.gear.blank).corners  # [toe, heel][root, tip] (z, rho)
    uu = np.nan_to_num(np.asarray(u, float))[:, None]
    root = (1.0 - uu) * c[0, 0] + uu * c[1, 0]
    tip = (1.0 - uu) * c[0, 1] + uu * c[1, 1]
    return np.linalg.norm(tip - root, axis=-1)


def pattern_dimensions(ltca: xr.Dataset, case: Case) -> dict[str, np.ndarray]:
    """The loaded pattern's centre and extent on the gear flank, per torque.

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca`` with ``pressure_envelope`` (torque, u, v) [MPa] on the gear grid
        fractions ``u`` (toe 0, heel 1) and ``v`` (root cone 0, face cone 1).
    case : geometry.case.Case
        The analysed case: its gear blank converts the fractions to mm.

    Returns
    -------
    dict of str to ndarray, shape (torque,)
        ``pattern_centre_u``, ``pattern_centre_v`` (pressure-weighted centre),
        ``pattern_toe_u``, ``pattern_heel_u``, ``pattern_root_v``, ``pattern_tip_v``
        (outermost loaded nodes) [1]; ``pattern_centre_lengthwise`` (from the toe along
        the face width), ``pattern_centre_profile`` (from the root cone along the depth at
        the centre), ``pattern_length``, ``pattern_height`` [mm]. NaN at a torque with no
        loaded node.

    Notes
    -----
    Seed §3.5, Fig. 3.7 (the pattern on the gear flank): the fractions are of the face
    width on the pitch-cone generator and of the whole depth between root and face cones
    (the blank's outline, corners interpolated), so lengths are those of the projection
    plane; the grid's node spacing (``u``, ``v``) bounds the extents' resolution.
    """
    u, v = ltca["u"].values, ltca["v"].values
    pat = _pattern(ltca["pressure_envelope"].values, u, v)
    face = float(case.gear.blank.face_width)
    depth_centre = _depth_at(case, pat["cu"])
    return {
        "pattern_centre_u": pat["cu"],
        "pattern_centre_v": pat["cv"],
        "pattern_toe_u": pat["u0"],
        "pattern_heel_u": pat["u1"],
        "pattern_root_v": pat["v0"],
        "pattern_tip_v": pat["v1"],
        "pattern_centre_lengthwise": pat["cu"] * face,
        "pattern_centre_profile": pat["cv"] * depth_centre,
        "pattern_length": (pat["u1"] - pat["u0"]) * face,
        "pattern_height": (pat["v1"] - pat["v0"]) * depth_centre,
    }


def _tree_misalignment(tree: xr.DataTree, case: Case) -> Misalignment:
    """The misalignment an analysis ran at: its root attributes
    (``misalignment_delta_E_mm`` …, :data:`contact.pipeline.MISALIGNMENT_ATTRS`), else the
    case's."""
    a = tree.attrs
    try:
        return Misalignment(
            delta_E=float(a["misalignment_delta_E_mm"]),
            delta_P=float(a["misalignment_delta_P_mm"]),
            delta_G=float(a["misalignment_delta_G_mm"]),
            delta_Sigma=math.radians(float(a["misalignment_delta_Sigma_deg"])))
    except KeyError:
        return case.misalignment


def plausibility_bits(ltca: xr.Dataset | None, case: Case, misalignment: Misalignment,
                      n_torque: int) -> np.ndarray:
    """The ``plausibility`` flag of one analysis: per torque, the sum of 2**k over the
    causes k of :data:`contact.ltca.plausibility.CAUSES` that occur.

    Parameters
    ----------
    ltca : xarray.Dataset or None
        The ``/ltca`` dataset (:func:`contact.ltca.plausibility.plausibility_flags`); None
        for a point whose analysis failed (only its input is judged).
    case : geometry.case.Case
        Its blanks bound the misalignment (:func:`contact.ltca.plausibility.
        misalignment_limits`).
    misalignment : geometry.pair.assembly.Misalignment
        The point's ΔE, ΔP, ΔG [mm], ΔΣ [rad].
    n_torque : int

    Returns
    -------
    ndarray of int8, shape (n_torque,)
        0 where the point is plausible at that torque.
    """
    bits = np.zeros(n_torque, np.int8)
    if ltca is not None:
        for k, flag in enumerate(plausibility_flags(ltca).values()):
            bits |= np.where(flag, np.int8(1 << k), np.int8(0))
    if misalignment_warnings(case, misalignment):
        bits |= np.int8(1 << CAUSES.index("misalignment_beyond_blank"))
    return bits


def point_summary(tree: xr.DataTree, case: Case,
                  friction: Sequence[xr.Dataset] = ()) -> dict[str, np.ndarray]:
    """The study summaries of one analysis.

    Parameters
    ----------
    tree : xarray.DataTree
        A :func:`contact.run_analysis` result (``/utca``, ``/ltca``; ``/friction``
        optional) — with deviations, the deviated surfaces' results (main groups).
    case : geometry.case.Case
        The analysed case (its gear blank converts pattern fractions to mm).
    friction : sequence of xarray.Dataset
        The ``/friction`` datasets (:func:`friction.efficiency.efficiency_analysis` of the
        tree's ``/ltca``) at each swept pinion speed, in order; empty: the tree's own
        ``/friction`` if it has one (one speed), else efficiency NaN.

    Returns
    -------
    dict of str to ndarray
        One array per name of :data:`SUMMARY_VARIABLES`, shaped by the dims after the
        point's (:func:`summary_dims`): ``torque`` (NT,), ``harmonic`` (3,), ``speed``
        (len(friction), at least 1), ``member`` (2: pinion, gear; ``root_stress_max``,
        NaN where the tree has no root stress). ``plausibility`` (torque,) int8: the bits
        of the causes ``ltca run`` warns of (:func:`plausibility_bits`, at the tree's own
        misalignment).

    Notes
    -----
    LTE summaries are :mod:`contact.ltca`'s own (seed Table 3.1 layout). The edge load
    share is Σ F·arm over the edge segments / Σ F·arm over all segments and roll positions
    (the torque equilibrium makes the denominator the gear torque times the number of
    rolls). The loaded pattern is the envelope of the maximum pressure on the gear grid
    (``/ltca/pressure_envelope``); its centre is the pressure-weighted mean of the grid
    fractions, its ends the outermost loaded nodes; mm along the face width (the
    fractions are of the face width on the pitch-cone generator) and along the whole depth
    at the centre (seed §3.5, Fig. 3.7: pattern on the gear flank).
    """
    ltca = tree["/ltca"].to_dataset()
    utca = tree["/utca"].to_dataset()
    found = ltca["found"].values > 0
    NT = found.shape[0]
    out = {
        "lte_mean": ltca["lte_mean"].values,
        "lte_peak_to_peak": ltca["lte_peak_to_peak"].values,
        "lte_harmonics": ltca["lte_harmonics"].values,
        "ute_peak_to_peak": np.asarray(float(utca["peak_to_peak_transmission_error"])),
        "pressure_max_flank": ltca["pressure_max_flank"].values,
        "pressure_max_edge": ltca["pressure_max_edge"].values,
        "edge_load_share": edge_load_share(ltca),
        **pattern_dimensions(ltca, case),
        "certified": found.all(axis=1).astype(np.int8),
    }
    if not friction and "/friction" in tree.groups:
        friction = (tree["/friction"].to_dataset(),)
    if friction:
        out["efficiency"] = np.stack([f["efficiency_mean"].values for f in friction], -1)
        out["power_loss"] = np.stack([f["power_loss_mean"].values for f in friction], -1)
    else:
        out["efficiency"] = np.full((NT, 1), np.nan)
        out["power_loss"] = np.full((NT, 1), np.nan)
    if "root_stress_max" in ltca:
        out["root_stress_max"] = ltca["root_stress_max"].transpose("torque", "member").values
    else:
        out["root_stress_max"] = np.full((NT, 2), np.nan)
    out["plausibility"] = plausibility_bits(ltca, case, _tree_misalignment(tree, case), NT)
    return {k: np.asarray(out[k], dtype=np.int8 if k in _INT8 else float)
            for k in SUMMARY_VARIABLES}


#: the summaries stored as int8 flags, not floats
_INT8 = ("certified", "plausibility")


def failed_summary(n_torque: int, n_speed: int = 1) -> dict[str, np.ndarray]:
    """The summary arrays of a point without result: NaN (``certified`` and
    ``plausibility`` 0: the caller sets the input's bit, :func:`plausibility_bits`)."""
    shapes = {"torque": n_torque, "harmonic": 3, "speed": n_speed, "member": 2}
    return {name: (np.zeros([shapes[d] for d in dims], np.int8) if name in _INT8
                   else np.full([shapes[d] for d in dims], np.nan))
            for name, dims, _, _ in _VARIABLES}


def summary_dims(name: str) -> tuple[str, ...]:
    """The dims of summary variable ``name`` after the point's (e.g. ``("torque",)``)."""
    for n, dims, _, _ in _VARIABLES:
        if n == name:
            return dims
    raise KeyError(name)


def summary_variable(name: str, point_dims: tuple[str, ...], data: np.ndarray) -> tuple:
    """``(dims, data, attrs)`` of summary variable ``name`` over ``point_dims`` + its own."""
    for n, dims, units, long_name in _VARIABLES:
        if n == name:
            attrs = {}
            if n == "certified":
                attrs = binary_flag("not_certified", "certified")
            elif n == "plausibility":
                attrs = {"flag_masks": np.array([1 << k for k in range(len(CAUSES))],
                                                dtype=np.int8),
                         "flag_meanings": " ".join(CAUSES)}
            return data_var((*point_dims, *dims), data, units, long_name, **attrs)
    raise KeyError(name)
