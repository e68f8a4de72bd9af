"""The solid of a member's teeth, meshed with quadratic hexahedra from its generated surfaces.

The solid holds ``teeth`` teeth (the loaded one in the middle and its neighbours), each
bounded by its two generated flanks and root fillets (:mod:`contact.compliance.fe.section`),
the face cone at the top, the front and back cones at the toe and the heel, and a rim under
the slots down to an inner cone parallel to the root cone; the sector is cut at the middle
of the outer slots' bottoms. It is meshed by :func:`contact.compliance.fe.mapped_mesh.mapped_mesh`
from a parameter box (A across the sector, B up from the rim's inner surface, W along the
face width) laid out per tooth as

* a **rim block** under each pitch: columns along the half slots (the lower part of each
  root fillet and half the slot bottom, finer towards the fillet, and towards the slot's
  middle too where two cuts meet there) and across the tooth's root, rows from the inner
  surface up to the slot bottom and fillet (finer at the top);
* a **tooth block** on it: columns across the tooth (finer towards both flanks), rows up
  the upper part of the fillets (from where they lean 45°) and up the flanks (finer next to
  the fillet) to the face cone.

Every node is placed in its transverse section (v, φ) and carried to the member frame by
the blank's projection-plane map; the sections are computed at the lengthwise fraction of
every node plane, so the curved flanks and fillets are followed by the quadratic geometry.
Every graded direction starts from the root element size h; the element counts are the
options' divisions, raised where a section needs more to keep the root fine
(:func:`mesh_layout`).

Public names
------------
SolidLayout        element counts and parameter ranges of the blocks
ToothSolid         the meshed solid with its sections and layout
build_tooth_solid  build it from a case
kept_tooth_solid   the same, the last four solids of the process kept (a re-synthesis's FE
                   reuse check and the build that may follow)
mesh_layout        the element counts: the options' divisions raised to keep the root fine
"""

from __future__ import annotations

import dataclasses
import logging
import math
import time
from dataclasses import dataclass

import numpy as np

from contact.compliance.fe.mapped_mesh import (
    MappedMesh,
    at_index,
    geometric_ratio,
    graded,
    mapped_mesh,
    size_exponents,
)
from contact.compliance.fe.options import FEOptions
from contact.compliance.fe.section import ToothSection, ToothSections, tooth_sections
from geometry.core.caches import Carried, memoised
from geometry.core.errors import InputError

__all__ = ["SOLID_CORE_FRACTION", "SolidLayout", "ToothSolid", "build_tooth_solid",
           "default_rim_depth", "kept_tooth_solid", "mesh_layout"]

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class SolidLayout:
    """Element counts of the solid's blocks and where they lie in parameter space.

    Parameter A runs across the sector, ``cell`` = 2 slot + across units per tooth (tooth
    m, offset m − neighbours from the loaded tooth, its tooth block over
    A ∈ [m cell + slot, m cell + slot + across]); B runs up, the rim block over
    [0, rim], the tooth block over [rim, rim + flank]; W runs along the face,
    toe 0 → heel ``face``.
    """

    teeth: int
    slot: int
    across: int
    flank: int
    rim: int
    face: int

    @classmethod
    def from_options(cls, opt: FEOptions) -> SolidLayout:
        return cls(opt.teeth, opt.slot_divisions, opt.across_divisions,
                   opt.flank_divisions, opt.rim_divisions, opt.face_divisions)

    @property
    def cell(self) -> int:
        return 2 * self.slot + self.across

    @property
    def rows(self) -> int:
        return self.rim + self.flank

    @property
    def shape(self) -> tuple[int, int, int]:
        return (self.teeth * self.cell, self.rows, self.face)

    @property
    def neighbours(self) -> int:
        return (self.teeth - 1) // 2

    def side_a(self, offset: int, side: str) -> float:
        """Parameter A of the flank side (``"left"``/``"right"``) of the tooth at
        ``offset`` from the loaded one."""
        m = offset + self.neighbours
        return float(m * self.cell + self.slot + (self.across if side == "right" else 0))

    def tooth_of(self, a) -> tuple[np.ndarray, np.ndarray]:
        """Tooth index m (0 … teeth − 1) and the local A within its cell."""
        a = np.asarray(a, dtype=float)
        m = np.clip(np.floor(a / self.cell), 0, self.teeth - 1).astype(int)
        return m, a - m * self.cell


#: [1] largest growth between neighbouring elements along a half slot, where the fillet
#: and (two cuts) the rounded crease carry the highest stresses
SLOT_GROWTH = 1.5
#: [1] largest growth between neighbouring elements in the other graded directions (up the
#: tooth's sides, across the tooth, down the rim)
GROWTH = 2.5
#: [1] the elements at the root surfaces are at most this many root element sizes h
#: thick (across the tooth, down the rim): the stress concentrates over the fillet's
#: radius normal to the surface as well as along it
LAYER = 2.0


@dataclass(frozen=True)
class _Lengths:
    """Lengths [mm] of one section's graded directions, and the root sizes of its sides."""

    h: tuple[float, float]  # root element size of the left, right side
    slot: tuple[float, float]  # half slot: lower fillet and half the bottom
    rows: tuple[float, float]  # tooth side from the fillet's split point to the tip
    half_width: float  # half the tooth's width at the split points
    rim: float  # from the split points down to the rim's inner surface

    @classmethod
    def of_section(cls, sec: ToothSection, rim_v: float, opt: FEOptions, pitch: float,
                   edge_radius: dict) -> _Lengths:
        curves = (("left", sec.left), ("right", sec.right))
        h = tuple(root_size(c, opt, edge_radius[c.flank]) for _, c in curves)
        slot = tuple(_half_slot_length(sec, side, pitch) for side, _ in curves)
        rows = tuple(c.length - c.split for _, c in curves)
        (vl, pl), (vr, pr) = sec.left.at(sec.left.split), sec.right.at(sec.right.split)
        width = float(sec.metric_length(vl, pl, vr, pr))
        return cls(h, slot, rows, 0.5 * width, sec.length_v * (0.5 * (vl + vr) - rim_v))


def _fewest(n: int, total: float, first: float, growth: float, fine: str, most: int) -> int:
    """The fewest elements, at least ``n`` (at most ``most``), that cover ``total`` [mm]
    from a smallest element ``first`` growing by at most ``growth`` (:func:`graded`'s
    exponents for ``fine``)."""
    while n < most and first * float(np.sum(growth ** size_exponents(n, fine))) < total:
        n += 1
    return n


def mesh_layout(sections: ToothSections, rim_v: np.ndarray, opt: FEOptions) -> SolidLayout:
    """The element counts of the solid: the options' divisions, raised where they cannot
    keep the root fine in every section — a half slot of elements starting at the root
    size h (:func:`root_size`) at its ends (:func:`_slot_fine`) growing by at most
    :data:`SLOT_GROWTH`; the tooth's sides from h growing by at most :data:`GROWTH`; across
    the tooth and down the rim from a layer at most :data:`LAYER` h thick growing by at most
    :data:`GROWTH` — each at most the option's upper bound.

    So a refinement (smaller h) refines the root in every direction, and a coarse model is
    not made of elements several h thick under its fillets (docs/fe.md, mesh convergence).

    Parameters
    ----------
    sections : ToothSections — the member's sections at every node plane
    rim_v : ndarray (2 face + 1,) — [1] profile fraction of the rim's inner surface there
    opt : FEOptions — the divisions (minimums) and the root element size

    Returns
    -------
    SolidLayout — the element counts (teeth and face divisions as given)
    """
    lay = SolidLayout.from_options(opt)
    fine = _slot_fine(sections.one_cut)
    slot, flank, half, rim = lay.slot, lay.flank, lay.across // 2, lay.rim
    for j, sec in enumerate(sections.sections):
        ln = _Lengths.of_section(sec, rim_v[j], opt, sections.pitch, sections.edge_radius)
        for h, s_len, r_len in zip(ln.h, ln.slot, ln.rows, strict=True):
            slot = _fewest(slot, s_len, h, SLOT_GROWTH, fine, 20)
            flank = _fewest(flank, r_len, h, GROWTH, "start", 60)
        h = float(np.mean(ln.h))
        half = _fewest(half, ln.half_width, LAYER * h, GROWTH, "start", 10)
        rim = _fewest(rim, ln.rim, LAYER * h, GROWTH, "start", 20)
    return dataclasses.replace(lay, slot=slot, flank=flank, across=2 * half, rim=rim)


@dataclass(frozen=True)
class _Grading:
    """Division tables (:func:`graded`) of one section: every graded direction starts
    from the root element size h of its side (``FEOptions.fillet_divisions`` or
    ``root_element_size``) and grows geometrically to cover its length."""

    slot: tuple[np.ndarray, np.ndarray]  # left, right half slot (from the split point)
    rows: tuple[np.ndarray, np.ndarray]  # left, right tooth side (split point → tip)
    across: np.ndarray
    rim: np.ndarray

    @classmethod
    def of_section(cls, sec: ToothSection, rim_v: float, opt: FEOptions, pitch: float,
                   lay: SolidLayout, edge_radius: dict, one_cut: bool = True) -> _Grading:
        ln = _Lengths.of_section(sec, rim_v, opt, pitch, edge_radius)
        fine = _slot_fine(one_cut)
        slots, rows = [], []
        for h, s_len, r_len in zip(ln.h, ln.slot, ln.rows, strict=True):
            q = geometric_ratio(lay.slot, s_len, h, fine=fine)
            slots.append(graded(lay.slot, q ** _top_exponent(lay.slot, fine), fine))
            q = geometric_ratio(lay.flank, r_len, h)
            rows.append(graded(lay.flank, q ** (lay.flank - 1), "start"))
        h = float(np.mean(ln.h))
        n = lay.across // 2
        q = geometric_ratio(n, ln.half_width, h)
        across = graded(lay.across, q ** (n - 1), "both")
        q = geometric_ratio(lay.rim, ln.rim, h)
        rim = graded(lay.rim, q ** (lay.rim - 1), "end")
        return cls(tuple(slots), tuple(rows), across, rim)


def _slot_fine(one_cut: bool) -> str:
    """Where a half slot's elements are smallest: at the fillet (``"start"``) when one
    cut makes the slot, whose bottom is straight between the fillets; also at the slot's
    middle (``"both"``) when two cuts meet there in a rounded crease, where the stress
    concentrates (:mod:`contact.compliance.fe.section`)."""
    return "start" if one_cut else "both"


def _top_exponent(n: int, fine: str) -> int:
    """The exponent of the largest element of a graded division (:func:`graded`)."""
    return (n - 1) // 2 if fine == "both" else n - 1


def root_size(curve, opt: FEOptions, edge_radius: float) -> float:
    """Element size h [mm] at a root fillet: ``opt.root_element_size``, or the shorter of
    the fillet's arc (slot bottom → flank) and a quarter circle of the blade's edge
    radius (the curvature of the fillets and of the roundings where two cuts meet) over
    ``opt.fillet_divisions``."""
    if opt.root_element_size is not None:
        return opt.root_element_size
    return min(curve.junction, 0.5 * math.pi * edge_radius) / opt.fillet_divisions


#: [1] the slot's middle (where two half slots meet) lies at least this fraction of the
#: slot's path from either split point. Where two cuts meet, the middle is their crease,
#: which lies near one fillet's split point where the cuts' root lines cross along the
#: face (tip planes on the root cone): at 2 % of the path (ISO 23509 sample 2 pinion)
#: that half slot's elements are slivers that invert between node planes. Measured over
#: the bundled pinions' sections, the crease lies at 1–39 % of the path (the Kolivand
#: pinions at >= 12 %, whose meshes this margin leaves as they were)
SLOT_MIDDLE_MARGIN = 0.1


def _slot_path(sec: ToothSection, pitch: float) -> tuple[float, float, float, float, float]:
    """The reference tooth's right slot as one path from its right split point down the
    right fillet, along the slot bottom and up the next tooth's left fillet to its split
    point: (right fillet part, bottom's right half, its left half, left fillet part,
    distance of the slot's middle from the right split point), all [mm]. The middle is
    the bottom's midpoint (the crease where two cuts meet), kept
    :data:`SLOT_MIDDLE_MARGIN` of the path from either end."""
    end = np.array([sec.right.v[0], sec.right.phi[0]])
    mid = 0.5 * (end + sec.bottom[1])
    half_r = float(sec.metric_length(end[0], end[1], mid[0], mid[1]))
    half_l = float(sec.metric_length(mid[0], mid[1], sec.bottom[1][0], sec.bottom[1][1]))
    a, c = float(sec.right.split), float(sec.left.split)
    total = a + half_r + half_l + c
    middle = min(max(a + half_r, SLOT_MIDDLE_MARGIN * total),
                 (1.0 - SLOT_MIDDLE_MARGIN) * total)
    return a, half_r, half_l, c, middle


def _half_slot_length(sec: ToothSection, side: str, pitch: float) -> float:
    """Length [mm] of a half slot: from the side's split point down its lower fillet and
    along the slot bottom to the slot's middle (:func:`_slot_path`)."""
    a, half_r, half_l, c, middle = _slot_path(sec, pitch)
    return middle if side == "right" else a + half_r + half_l + c - middle


@dataclass(frozen=True, eq=False)
class ToothSolid:
    """A member's meshed tooth solid.

    Attributes
    ----------
    case_name : str
    member : str
    options : FEOptions
    layout : SolidLayout
    sections : ToothSections — at the lengthwise fraction of every node plane
        (2 face + 1 planes, W = 0, ½, 1, …)
    rim_v : ndarray (2 face + 1,) — [1] profile fraction of the rim's inner surface
        in each node plane
    rim_depth : float — [mm] the rim depth used (under the deepest slot bottom; where the
        default follows a solid shaft, :func:`default_rim_depth`, its smaller end's)
    fillet_rows : int — [1] element rows of the tooth sides that reach past the
        fillets' junction with the flanks in every section, plus one
    junction_rows : ndarray (2 face + 1, 2) — [1] in each node plane, on the left and
        the right side, the rows from the fillet's split point up to the one that holds
        its junction with the flank: the root (:meth:`in_root`)
    mesh : MappedMesh — parameter and physical meshes
    build_time : float — [s] sections and mesh
    """

    case_name: str
    member: str
    options: FEOptions
    layout: SolidLayout
    sections: ToothSections
    rim_v: np.ndarray
    rim_depth: float
    fillet_rows: int
    junction_rows: np.ndarray
    mesh: MappedMesh
    build_time: float

    @property
    def pitch(self) -> float:
        """Angular pitch [rad]."""
        return self.sections.pitch

    def constrained_nodes(self) -> np.ndarray:
        """Mesh nodes held fixed by ``options.constraint`` (every displacement component)."""
        lay = self.layout
        if self.options.constraint == "bore":
            return self.mesh.nodes_where(lambda p: p[1] < 1e-9)
        return self.mesh.nodes_where(lambda p: (p[2] > lay.face - 1e-9)
                                     & (p[1] < lay.rim + 1e-9))

    def flank_facets(self, offset: int, side: str) -> np.ndarray:
        """Boundary facets of the flank side (``"left"``/``"right"``) of the tooth at
        ``offset``: its half slot (lower fillet, half the slot bottom), upper fillet and
        flank, up to the face cone."""
        a = self.layout.side_a(offset, side)
        rim = self.layout.rim
        side_facets = self.mesh.facets_where(lambda p: (np.abs(p[0] - a) < 1e-9)
                                             & (p[1] > rim))
        return np.r_[self.fillet_facets(offset, side)[0], side_facets]

    def in_root(self, side: str, param: np.ndarray) -> np.ndarray:
        """Whether points on the rows of the tooth side ``side`` above its half slot
        (parameter coordinates (3, P)) lie in the root: in a row below or holding the
        fillet's junction with the flank in one of the node planes of the point's element.
        Above it the side is flank, where a load's own local stress would be taken for the
        root's (the half slot is root throughout)."""
        lay = self.layout
        row = np.floor(param[1] - lay.rim + 1e-9).astype(int)
        w = np.clip(np.floor(param[2] + 1e-9).astype(int), 0, lay.face - 1)
        k = 0 if side == "left" else 1
        planes = np.stack([self.junction_rows[2 * w + d, k] for d in range(3)])
        return row < planes.max(axis=0)

    def fillet_facets(self, offset: int, side: str) -> tuple[np.ndarray, np.ndarray]:
        """Boundary facets of the root on one side of the tooth at ``offset``: (facets of
        the half slot — lower fillet and half the slot bottom —, facets of the tooth
        side whose rows reach the fillet's junction with the flank, and one more)."""
        lay = self.layout
        a = lay.side_a(offset, side)
        lo, hi = (a - lay.slot, a) if side == "left" else (a, a + lay.slot)
        slot = self.mesh.facets_where(lambda p: (np.abs(p[1] - lay.rim) < 1e-9)
                                      & (p[0] > lo) & (p[0] < hi))
        top = lay.rim + self.fillet_rows
        up = self.mesh.facets_where(lambda p: (np.abs(p[0] - a) < 1e-9) & (p[1] > lay.rim)
                                    & (p[1] < top))
        return slot, up


def _half_slot(sec: ToothSection, side: str, f: np.ndarray, pitch: float):
    """(v, φ) along a half slot of the reference tooth at fractions f: 0 at the side's
    split point, down its lower fillet, then along the slot bottom to the slot's middle
    (1; :func:`_slot_path`: the bottom's midpoint, or beyond it on the other fillet)."""
    a, half_r, half_l, c, middle = _slot_path(sec, pitch)
    total = a + half_r + half_l + c
    f = np.asarray(f, dtype=float)
    # distance from the reference tooth's right split point along its right slot's path
    d = f * middle if side == "right" else total - f * (total - middle)
    v, phi = sec.right.at(a - np.clip(d, 0.0, a))
    end = np.array([sec.right.v[0], sec.right.phi[0]])
    mid = 0.5 * (end + sec.bottom[1])
    for lo, length, p0, p1 in ((a, half_r, end, mid), (a + half_r, half_l, mid, sec.bottom[1])):
        if length > 0.0:
            t = np.clip((d - lo) / length, 0.0, 1.0)[..., None]
            lin = p0 + t * (p1 - p0)
            on = (d > lo) & (d <= lo + length)
            v, phi = np.where(on, lin[..., 0], v), np.where(on, lin[..., 1], phi)
    vl, pl = sec.left.at(np.clip(d - a - half_r - half_l, 0.0, c))
    up = d > a + half_r + half_l
    v, phi = np.where(up, vl, v), np.where(up, pl + pitch, phi)
    if side == "left":  # the reference tooth's left slot: the right one a pitch back
        phi = phi - pitch
    return v, phi


def _tooth_point(sec: ToothSection, frac_a, b, grad: _Grading):
    """(v, φ) of tooth-block nodes: across fraction ``frac_a``, row parameter b ∈
    [0, flank divisions] (0 at the split points)."""
    out = []
    for curve, table in zip((sec.left, sec.right), grad.rows, strict=True):
        arc = curve.split + (curve.length - curve.split) * at_index(table, b)
        out.append(curve.at(arc))
    (vl, pl), (vr, pr) = out
    return (1 - frac_a) * vl + frac_a * vr, (1 - frac_a) * pl + frac_a * pr


def _plane_points(sec: ToothSection, rim_v: float, a, b, lay: SolidLayout, grad: _Grading,
                  pitch: float):
    """(v, φ) of the nodes with parameters (A, B) in one section."""
    m, la = lay.tooth_of(a)
    offset = m - lay.neighbours
    v = np.empty(a.shape)
    phi = np.empty(a.shape)
    base = b <= lay.rim + 1e-12
    # rim block: the top point of the node's column, then down to the rim's inner surface
    left = la <= lay.slot
    right = la >= lay.slot + lay.across
    mid = ~(left | right)
    vt, pt = np.empty(a.shape), np.empty(a.shape)
    if left.any():
        vt[left], pt[left] = _half_slot(sec, "left", at_index(grad.slot[0],
                                                              lay.slot - la[left]), pitch)
    if right.any():
        vt[right], pt[right] = _half_slot(sec, "right", at_index(
            grad.slot[1], la[right] - lay.slot - lay.across), pitch)
    if mid.any():
        fa = at_index(grad.across, la[mid] - lay.slot)
        vt[mid], pt[mid] = _tooth_point(sec, fa, np.zeros(fa.shape), grad)
    g = at_index(grad.rim, np.minimum(b, lay.rim))
    v[base] = (rim_v + g * (vt - rim_v))[base]
    phi[base] = pt[base]
    top = ~base
    if top.any():
        fa = at_index(grad.across, la[top] - lay.slot)
        v[top], phi[top] = _tooth_point(sec, fa, b[top] - lay.rim, grad)
    return v, phi + offset * pitch


def _rim_line(sections: ToothSections, depth, u: np.ndarray) -> np.ndarray:
    """Profile fraction v of the rim's inner cone in the sections at ``u``: the line
    parallel to the root cone ``depth`` [mm] below its deepest slot bottom; ``depth`` a
    pair (toe, heel) [mm]: the line through the end sections' points that far below it
    (a cone that narrows towards the toe faster than the root cone: a solid shaft's,
    :func:`default_rim_depth`)."""
    c = sections.corners
    a = (1 - u)[:, None] * c[0, 0] + u[:, None] * c[1, 0]
    d = (1 - u)[:, None] * c[0, 1] + u[:, None] * c[1, 1] - a
    if np.ndim(depth) == 0:
        root = c[1, 0] - c[0, 0]
        n = np.array([root[1], -root[0]]) / np.hypot(*root)
        n *= math.copysign(1.0, float(n @ (c[0, 1] - c[0, 0])))  # towards the teeth
        level = -(sections.slot_depth + depth)
        return (level - (a - c[0, 0]) @ n) / (d @ n)
    v0 = _rim_line(sections, float(depth[0]), np.array([0.0]))[0]
    v1 = _rim_line(sections, float(depth[1]), np.array([1.0]))[0]
    p0 = (1 - v0) * c[0, 0] + v0 * c[0, 1]
    e = (1 - v1) * c[1, 0] + v1 * c[1, 1] - p0

    def cross(x, y):
        return x[..., 0] * y[..., 1] - x[..., 1] * y[..., 0]

    return cross(p0 - a, e) / cross(d, e)


#: [1] the default rim of a member too small for a 1.2 h_e rim (a small pinion, a solid
#: shaft) stops at this fraction of the radius its inner cone has at the slot bottoms:
#: the core inside it is held rigid instead of modelled to the axis (where the mapped
#: mesh's elements would collapse). The polar and axial second moments of a solid
#: section grow as r⁴, so the core inside a quarter of the radius carries 0.25⁴ = 0.4 %
#: of the shaft section's torsional and bending stiffness.
SOLID_CORE_FRACTION = 0.25


def _rim_end_radii(sections: ToothSections, depth) -> np.ndarray:
    """Radii [mm] (toe, heel) of the rim's inner cone ``depth`` [mm] (one, or a pair toe,
    heel) below the deepest slot bottom (:func:`_rim_line`) at the model's end sections."""
    c = sections.corners
    v = _rim_line(sections, depth, np.array([0.0, 1.0]))
    return np.array([((1 - v[0]) * c[0, 0] + v[0] * c[0, 1])[1],
                     ((1 - v[1]) * c[1, 0] + v[1] * c[1, 1])[1]])


def default_rim_depth(sections: ToothSections, blank) -> float | tuple[float, float]:
    """The FE model's default rim depth [mm] of a member (``FEOptions.rim_depth`` None).

    Parameters
    ----------
    sections : ToothSections — the member's tooth sections (its end sections, u = 0, 1,
        among them)
    blank : geometry.case.Blank — the member's blank (outer addendum and dedendum [mm])

    Returns
    -------
    float or (float, float) — [mm] 1.2 × the outer whole depth h_e, the rim thickness
    above which ISO 6336-3 treats a gear as solid (rim factor Y_B = 1 for s_R/h_t ≥ 1.2),
    a rim parallel to the root cone. Where that rim's inner cone would come within
    :data:`SOLID_CORE_FRACTION` of the axis at the toe or the heel — a small hypoid
    pinion (5–7 teeth), which is a solid shaft, not a rim — the pair (toe, heel) of the
    depths at which the inner cone reaches that fraction of its radius at the slot
    bottoms, each at most 1.2 h_e: the body is modelled down to a quarter of its root
    radius at both ends and the core inside held rigid (source of the fraction: the r⁴
    law of a solid section's second moments, :data:`SOLID_CORE_FRACTION`; docs/fe.md,
    "Rim and support"). A member with a rim of 1.2 h_e everywhere gets the float, so its
    model is unchanged.

    The inner cone's radius at each end is affine in that end's depth, so the limiting
    depths are exact: r(d) = r(0) + (r(d₁) − r(0)) d/d₁.
    """
    full = 1.2 * (blank.outer_addendum + blank.outer_dedendum)
    at_root = _rim_end_radii(sections, 0.0)
    at_full = _rim_end_radii(sections, full)
    if np.all(at_full >= SOLID_CORE_FRACTION * at_root):
        return float(full)
    drop = np.maximum((at_root - at_full) / full, 1e-12)  # [mm/mm] radius lost per mm
    toe, heel = np.minimum(full, (1.0 - SOLID_CORE_FRACTION) * at_root / drop)
    log.info("%s: default rim depth %.3g mm at the toe, %.3g mm at the heel (1.2 h_e = "
             "%.3g mm would reach radius %.3g / %.3g mm): a solid shaft held inside %.0f %% "
             "of its root radius", sections.member, toe, heel, full, *at_full,
             100 * SOLID_CORE_FRACTION)
    return float(toe), float(heel)


def _check_root_size(sections: ToothSections, opt: FEOptions) -> None:
    """Refuse a root element size that leaves no element across a fillet."""
    if opt.root_element_size is None:
        return
    arc = min(min(sec.left.junction, sec.right.junction) for sec in sections.sections)
    if opt.root_element_size >= arc:
        raise InputError(f"root_element_size: must be < {arc:.4g} mm, the shortest root "
                         f"fillet arc of the {sections.member} (a larger size leaves no "
                         f"element across the fillet), got {opt.root_element_size:g}")


def build_tooth_solid(case, member: str, options: FEOptions | None = None) -> ToothSolid:
    """Mesh the teeth of one member from its generated surfaces.

    Parameters
    ----------
    case : geometry.case.Case — a loaded case (face milling or face hobbing)
    member : str — ``"pinion"`` or ``"gear"``
    options : FEOptions, optional — solid, mesh and material (default ``FEOptions()``)

    Returns
    -------
    ToothSolid

    Raises
    ------
    InputError
        A bad member, a blade without an edge radius, or a rim so deep that its inner
        cone reaches the member axis (``rim_depth``).
    LTCAError
        The generated flanks do not make a tooth the mesh can follow
        (:func:`contact.compliance.fe.section.tooth_sections`), or the mapping inverts
        an element (:func:`contact.compliance.fe.mapped_mesh.mapped_mesh`).

    Notes
    -----
    The solid's surfaces are the generated ones (seed §2.2, Eq. 2.7a–2.8) and the blank's
    cones (ISO 23509 blank data of the case); the rim and its support are this model's
    (``options.rim_depth``, ``options.constraint``: docs/fe.md).
    """
    t0 = time.perf_counter()
    opt = options if options is not None else FEOptions()
    u = np.linspace(0.0, 1.0, 2 * opt.face_divisions + 1)
    sections = tooth_sections(case, member, u, opt.slot_bottom)
    blank = case.member(member).blank
    depth = opt.rim_depth if opt.rim_depth is not None else default_rim_depth(sections, blank)
    rim_v = _rim_line(sections, depth, u)
    c = sections.corners
    for ui, vi in ((0.0, rim_v[0]), (1.0, rim_v[-1])):
        rho = ((1 - ui) * (1 - vi) * c[0, 0] + ui * (1 - vi) * c[1, 0]
               + (1 - ui) * vi * c[0, 1] + ui * vi * c[1, 1])[1]
        if rho <= 0.05 * blank.outer_cone_distance * math.sin(blank.root_angle):
            raise InputError(f"rim_depth: {np.min(depth):.4g} mm puts the rim's inner cone at "
                             "radius "
                             f"{rho:.3g} mm at the {'toe' if ui == 0 else 'heel'}, at or "
                             "through the member axis; give a smaller rim depth")

    _check_root_size(sections, opt)
    lay = mesh_layout(sections, rim_v, opt)
    grading = [_Grading.of_section(sec, rim_v[j], opt, sections.pitch, lay,
                                   sections.edge_radius, sections.one_cut)
               for j, sec in enumerate(sections.sections)]

    def mapping(p: np.ndarray) -> np.ndarray:
        out = np.empty_like(p)
        planes = np.rint(2.0 * p[2]).astype(int)
        for j in np.unique(planes):
            sel = planes == j
            sec = sections.sections[j]
            v, phi = _plane_points(sec, rim_v[j], p[0, sel], p[1, sel], lay, grading[j],
                                   sections.pitch)
            z = ((1 - sec.u) * (1 - v) * c[0, 0, 0] + sec.u * (1 - v) * c[1, 0, 0]
                 + (1 - sec.u) * v * c[0, 1, 0] + sec.u * v * c[1, 1, 0])
            rho = ((1 - sec.u) * (1 - v) * c[0, 0, 1] + sec.u * (1 - v) * c[1, 0, 1]
                   + (1 - sec.u) * v * c[0, 1, 1] + sec.u * v * c[1, 1, 1])
            out[0, sel], out[1, sel], out[2, sel] = rho * np.cos(phi), rho * np.sin(phi), z
        return out

    def keep(centre: np.ndarray) -> np.ndarray:
        _, la = lay.tooth_of(centre[0])
        return (centre[1] < lay.rim) | ((la > lay.slot) & (la < lay.slot + lay.across))

    mesh = mapped_mesh(lay.shape, mapping, keep)
    junction_rows = np.array([
        [int(np.searchsorted(curve.split + (curve.length - curve.split) * table[0::2],
                             curve.junction)) for curve, table in
         zip((sec.left, sec.right), g.rows, strict=True)]
        for sec, g in zip(sections.sections, grading, strict=True)])
    fillet_rows = 1 + int(junction_rows.max())
    elapsed = time.perf_counter() - t0
    log.info("%s %s solid: %d elements, %d nodes, worst Jacobian ratio %.3f, %.1f s",
             case.name, member, mesh.mesh.nelements, mesh.mesh.doflocs.shape[1],
             mesh.min_jacobian, elapsed)
    return ToothSolid(case.name, member, opt, lay, sections, rim_v, float(np.min(depth)),
                      min(fillet_rows, lay.flank), junction_rows, mesh, elapsed)


@memoised(maxsize=4)
def _kept_solid(member: str, key: str, name: str, case: Carried, options: Carried
                ) -> ToothSolid:
    """:func:`build_tooth_solid` of ``case.value``'s ``member`` with ``options.value``,
    memoised by the member's FE key ``key`` and the case's ``name``."""
    return build_tooth_solid(case.value, member, options.value)


def kept_tooth_solid(case, member: str, options: FEOptions | None = None) -> ToothSolid:
    """:func:`build_tooth_solid`, the last four solids of the process kept (read-only: the
    same object to every caller).

    Parameters
    ----------
    case : geometry.case.Case — a loaded case (face milling or face hobbing)
    member : str — ``"pinion"`` or ``"gear"``
    options : FEOptions, optional — solid, mesh and material (default ``FEOptions()``)

    Returns
    -------
    ToothSolid — as :func:`build_tooth_solid` returns it (its ``build_time`` the first
        build's [s])

    Raises
    ------
    InputError, LTCAError
        As :func:`build_tooth_solid`.

    Notes
    -----
    Keyed by the member's data and the options as the FE cache keys its coefficients
    (:func:`contact.compliance.fe.cache.cache_key`: blank, blades, machine settings, hand,
    process; the solid depends on nothing else of the case, :func:`contact.compliance.fe.
    section.tooth_sections`) and by the case's name (the solid's ``case_name``). Why: a
    re-synthesis's reuse check (:func:`contact.compliance.fe.reuse.point_deviation`) compares
    the new member's solid with the one the FE build of the design before has just made
    (0.5-1.0 s of CPU each on the 10x43 hypoid's pinion, issue 75), and where it refuses,
    the new member's build meshes the same solid again. The solid of a member is the same
    for both working flanks (both are modelled).
    """
    from contact.compliance.fe.cache import cache_key

    opt = options if options is not None else FEOptions()
    key = cache_key(case.member(member), "solid", opt)
    return _kept_solid(member, key, str(case.name), Carried(case), Carried(opt))
