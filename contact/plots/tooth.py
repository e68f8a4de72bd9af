"""The gear tooth as the figures draw it: the normalised flank and the projection plane.

The normalised tooth is the gear's (u, v) grid: u lengthwise from toe (0) to heel (1),
v in profile from root to tip (1) — every analysis has the same outline there, so
patterns of different torques, misalignments or cases are compared on one frame (the
view of the seed's Figs. 2.8, 3.7, 4.6–4.14 and of commercial TCA tools). The projection
plane is the gear's axial position × radius [mm] (seed Fig. 2.7).

Segment results of the LTCA (``(roll, pair, segment)``) are drawn as short pieces of
their contact line, each from halfway to its neighbour on one side to halfway on the
other, coloured by the segment's value (one ``LineCollection`` per panel whose paths are the
pieces grouped by their colour map entry, not thousands of markers or paths). Edge
segments (``segment_kind`` not ``curve``) sit on the flank boundary;
they are drawn just outside it (gear tip, heel, toe) or beneath the flank's lines
(pinion edge), in their own colour scale, so they never hide the flank's pattern.

Public functions
----------------
draw_tooth            outline, masked nodes (hatched, with their reason) and toe/heel/root/tip
draw_projection_outline  the same in the projection plane, labels outside the flank
segment_pieces        contact-line pieces (N, 3, 2) of segment values, in (u, v)
edge_points           places (u, v) of edge segments, moved just outside the flank
masked_reasons        why the masked nodes are masked (their flag meanings)
require               InputError naming the variables a dataset lacks
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.patches import Patch

from geometry.core.errors import InputError

__all__ = [
    "EDGE_OFFSET",
    "PROFILE_LABEL",
    "TOE_HEEL_LABEL",
    "draw_projection_outline",
    "draw_tooth",
    "edge_points",
    "masked_reasons",
    "require",
    "segment_pieces",
]

#: axis labels of the normalised tooth
TOE_HEEL_LABEL = "face width, toe → heel [1]"
PROFILE_LABEL = "profile, root → tip [1]"
#: how far outside the flank the edge contact is drawn [1] (fraction of the face width)
EDGE_OFFSET = 0.035
_MARGIN = 0.14


def require(ds: xr.Dataset, names, what: str) -> None:
    """Raise InputError naming the variables ``ds`` lacks."""
    missing = [n for n in names if n not in ds.variables]
    if missing:
        raise InputError(f"{what}: dataset lacks {missing} (not the toolkit's {what} group)")


def masked_reasons(easeoff: xr.Dataset) -> str:
    """The reasons (``mask_reason`` flag meanings) of the masked nodes, as text."""
    if "mask_reason" not in easeoff:
        return "no contact possible"
    reason = easeoff["mask_reason"]
    codes = np.unique(reason.values[reason.values != 0])
    values = list(np.atleast_1d(reason.attrs.get("flag_values", [])))
    words = str(reason.attrs.get("flag_meanings", "")).split()
    names = [words[values.index(c)].replace("_", " ") if c in values and
             values.index(c) < len(words) else f"reason {int(c)}" for c in codes]
    return ", ".join(names) or "no contact possible"


def _masked(easeoff: xr.Dataset) -> np.ndarray | None:
    if "mask" in easeoff:
        m = easeoff["mask"].values == 0
    elif "ease_off" in easeoff:
        m = ~np.isfinite(easeoff["ease_off"].values)
    else:
        return None
    return m if m.any() else None


def draw_tooth(ax, easeoff: xr.Dataset, *, labels: bool = True) -> list:
    """The normalised tooth on ``ax``: outline, masked nodes hatched, edge names outside.

    Parameters
    ----------
    ax : matplotlib Axes
    easeoff : xarray.Dataset
        ``/easeoff`` (its ``u``, ``v`` and ``mask``/``mask_reason``).
    labels : bool
        Write toe/heel/root/tip outside the outline and the axis labels.

    Returns
    -------
    list
        Legend handles (the masked nodes' key, if any are masked).
    """
    u, v = easeoff["u"].values, easeoff["v"].values
    u0, u1, v0, v1 = float(u[0]), float(u[-1]), float(v[0]), float(v[-1])
    ax.plot([u0, u1, u1, u0, u0], [v0, v0, v1, v1, v0], color="0.2", lw=0.9, zorder=3)
    handles = []
    masked = _masked(easeoff)
    if masked is not None:
        ax.contourf(u, v, masked.T.astype(float), levels=[0.01, 1.5], colors=["0.9"],
                    hatches=["////"], zorder=0.5)
        handles.append(Patch(facecolor="0.9", hatch="////", edgecolor="0.5",
                             label=f"masked: {masked_reasons(easeoff)}"))
    ax.set_xlim(u0 - _MARGIN, u1 + _MARGIN)
    ax.set_ylim(v0 - _MARGIN, v1 + _MARGIN)
    if labels:
        style = dict(fontsize=7, color="0.3", ha="center", va="center", clip_on=False)
        mid_u, mid_v = 0.5 * (u0 + u1), 0.5 * (v0 + v1)
        out = EDGE_OFFSET + 0.055
        ax.text(u0 - out, mid_v, "toe", rotation=90, **style)
        ax.text(u1 + out, mid_v, "heel", rotation=90, **style)
        ax.text(mid_u, v0 - out, "root", **style)
        ax.text(mid_u, v1 + out, "tip", **style)
        ax.set_xlabel(TOE_HEEL_LABEL)
        ax.set_ylabel(PROFILE_LABEL)
    return handles


def draw_projection_outline(ax, easeoff: xr.Dataset) -> list:
    """The flank in its projection plane (axial position × radius [mm]): outline, masked
    nodes hatched, toe/heel/root/tip written outside each edge along its outward normal.

    Returns
    -------
    list
        Legend handles (the masked nodes' key, if any).
    """
    z = easeoff["axial_position"].values
    r = easeoff["radial_position"].values
    edges = {"toe": (z[0, :], r[0, :]), "heel": (z[-1, :], r[-1, :]),
             "root": (z[:, 0], r[:, 0]), "tip": (z[:, -1], r[:, -1])}
    ring = np.concatenate([np.c_[z[:, 0], r[:, 0]], np.c_[z[-1, :], r[-1, :]],
                           np.c_[z[::-1, -1], r[::-1, -1]], np.c_[z[0, ::-1], r[0, ::-1]]])
    ax.plot(ring[:, 0], ring[:, 1], color="0.2", lw=0.9, zorder=3)
    handles = []
    masked = _masked(easeoff)
    if masked is not None:
        ax.contourf(z, r, masked.astype(float), levels=[0.01, 1.5], colors=["0.9"],
                    hatches=["////"], zorder=0.5)
        handles.append(Patch(facecolor="0.9", hatch="////", edgecolor="0.5",
                             label=f"masked: {masked_reasons(easeoff)}"))
    centre = np.array([np.mean(ring[:, 0]), np.mean(ring[:, 1])])
    for name, (ez, er) in edges.items():
        mid = np.array([ez[ez.size // 2], er[er.size // 2]])
        tangent = np.array([ez[-1] - ez[0], er[-1] - er[0]])
        normal = np.array([tangent[1], -tangent[0]]) / max(np.hypot(*tangent), 1e-12)
        if np.dot(normal, mid - centre) < 0:
            normal = -normal
        ax.annotate(name, mid, xytext=tuple(16 * normal), textcoords="offset points",
                    ha="center", va="center", fontsize=8, color="0.25")
    ax.set_xlabel("gear axial position [mm]")
    ax.set_ylabel("gear radius [mm]")
    ax.set_aspect("equal")
    pad = 0.08 * max(np.ptp(ring[:, 0]), np.ptp(ring[:, 1]))
    ax.set_xlim(ring[:, 0].min() - pad, ring[:, 0].max() + pad)
    ax.set_ylim(ring[:, 1].min() - pad, ring[:, 1].max() + pad)
    return handles


def _is_curve(ltca: xr.Dataset) -> np.ndarray:
    if "segment_kind" in ltca.coords or "segment_kind" in ltca:
        return np.asarray(ltca["segment_kind"].values) == "curve"
    return np.ones(ltca.sizes["segment"], bool)


def segment_pieces(ltca: xr.Dataset, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Contact-line pieces of the flank's (curve) segments with a finite, non-zero value.

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca`` (``segment_u``, ``segment_v`` (roll, pair, segment) [1], ``segment_kind``).
    values : ndarray (roll, pair, segment)
        A value per segment (e.g. ``pressure_max`` at one torque); NaN or 0 is not drawn.

    Returns
    -------
    pieces : ndarray (N, 3, 2) — [1]
        Each drawn segment as a 3-point polyline in (u, v): halfway to the previous
        segment's midpoint, its midpoint, halfway to the next.
    colours : ndarray (N,)
        The segments' values.
    """
    curve = _is_curve(ltca)
    u = ltca["segment_u"].values[..., curve]
    v = ltca["segment_v"].values[..., curve]
    val = np.asarray(values)[..., curve]
    p = np.stack([u, v], axis=-1)
    if p.shape[-2] < 2:
        keep = np.isfinite(val) & (val != 0) & np.isfinite(p).all(-1)
        return np.repeat(p[keep][:, None, :], 3, axis=1), val[keep]
    prev = np.concatenate([2 * p[..., :1, :] - p[..., 1:2, :], p[..., :-1, :]], axis=-2)
    nxt = np.concatenate([p[..., 1:, :], 2 * p[..., -1:, :] - p[..., -2:-1, :]], axis=-2)
    prev = np.where(np.isfinite(prev), prev, p)
    nxt = np.where(np.isfinite(nxt), nxt, p)
    pieces = np.stack([0.5 * (p + prev), p, 0.5 * (p + nxt)], axis=-2)
    keep = np.isfinite(val) & (val != 0) & np.isfinite(p).all(-1)
    order = np.argsort(val[keep], kind="stable")  # the largest drawn last, on top
    return pieces[keep][order], val[keep][order]


#: outward direction (du, dv) of each gear edge kind (pinion edges are drawn in place)
_EDGE_OUT = {"gear_tip": (0.0, 1.0), "gear_heel": (1.0, 0.0), "gear_toe": (-1.0, 0.0)}


def edge_points(ltca: xr.Dataset, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Places of the loaded edge segments, moved :data:`EDGE_OFFSET` outside the flank.

    Parameters
    ----------
    ltca : xarray.Dataset
    values : ndarray (roll, pair, segment)
        A value per segment; edges with NaN or 0 are left out.

    Returns
    -------
    points : ndarray (N, 2) — [1]
        (u, v) of the edge segments: gear tip/heel/toe edges just outside the outline,
        pinion edges at their place on the flank.
    colours : ndarray (N,)
    """
    if "segment_kind" not in ltca.coords and "segment_kind" not in ltca:
        return np.empty((0, 2)), np.empty(0)
    kind = np.asarray(ltca["segment_kind"].values)
    u = ltca["segment_u"].values.copy()
    v = ltca["segment_v"].values.copy()
    val = np.asarray(values, float)
    for name, (du, dv) in _EDGE_OUT.items():
        k = kind == name
        u[..., k] += du * EDGE_OFFSET
        v[..., k] += dv * EDGE_OFFSET
    edge = (kind != "curve")[None, None, :]
    keep = edge & np.isfinite(val) & (val != 0) & np.isfinite(u) & np.isfinite(v)
    order = np.argsort(val[keep], kind="stable")
    return np.c_[u[keep], v[keep]][order], val[keep][order]
