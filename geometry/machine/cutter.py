"""Face-milling blades and the cutter surface of revolution they sweep (seed §2.2.2, Eq. 2.5–2.6).

A face-milling cutter head carries inside blades (IB) and outside blades (OB) on a common
axis. Spinning, the cutting edge of each blade sweeps a surface of revolution, the cutter
surface. The outside blade cuts the concave flank of the tooth slot, the inside blade the
convex flank (seed §2.2, Fig. 2.1a).

Blade profile (in the blade's axial plane, seed Fig. 2.3c)
----------------------------------------------------------
The edge is described in the plane (ρ, h): ρ the radius from the cutter axis, h the height
above the blade-tip plane, measured along the cutter axis away from the work. Going up
the blade from its tip the edge consists of

1. the **edge radius** r_e: a circular arc tangent to the tip plane (h = 0) and to the next
   section (absent when r_e = 0);
2. the **toprem** section: a straight line whose blade angle is α + Δα_T, from the edge
   radius up to the toprem height h_T, where it meets the profile at a corner (absent when
   Δα_T = 0);
3. the **profile**: a straight line through the point (r_p, 0) with blade angle α (ρ grows
   with h on an outside blade, shrinks on an inside blade), or a circular arc of radius
   R_pr tangent to that line at the reference height h_ref (R_pr > 0: convex edge, centre on
   the blade's material side);
4. the **flankrem** section: a straight line of blade angle α + Δα_F from the flankrem
   height h_F upwards, meeting the profile at a corner (absent when Δα_F = 0).

r_p is the point radius (seed r_c with h_f = 0: the reference point M is where the
nominal profile line meets the tip plane). Each section has constant curvature, so the
edge is evaluated in closed form; the parameter s is the arc length along the edge from
the point where the edge radius leaves the tip plane, increasing away from the tip.

Cutter frame S_t (seed Eq. 2.6): origin at the centre of the tip plane, z_t along the cutter
axis pointing from the cutter body towards the blade tips (towards the work). A blade
point is r_t(s, θ) = [ρ(s) cos θ, ρ(s) sin θ, −h(s)]; θ is the angle of the blade about the
cutter axis. The unit normal returned points out of the *work* material (into the slot,
i.e. into the tool), which is the orientation the generated flank inherits.

Public functions
----------------
Blade                    frozen dataclass of one blade's geometry
profile_sections         the constant-curvature sections of a blade's edge
working_sections         which of them cut the working flank (all but the edge radius)
blade_profile            edge point and its first and second s-derivatives in (ρ, h)
placement_vectors        where a (face-hobbing) blade sits in the head: M, rake-plane lines
blade_edge               the edge as a space curve in the cutter frame
mirror_blade             the blade that cuts the mirror image (opposite hand) of a flank
cutter_surface           r_t(s, θ), its first and second derivatives, unit normal
cutter_curvatures        principal curvatures of the cutter surface (analytic)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import NamedTuple

import numpy as np

from geometry.core.caches import Same, memoised, read_only
from geometry.core.errors import InputError
from geometry.core.validation import real

__all__ = [
    "BLADE_SIDES",
    "PROFILE_TYPES",
    "Blade",
    "BladeEdge",
    "BladeProfilePoint",
    "CutterSurface",
    "ProfileSections",
    "blade_edge",
    "blade_profile",
    "cutter_curvatures",
    "cutter_surface",
    "mirror_blade",
    "placement_vectors",
    "profile_sections",
    "revolution_normal",
    "working_sections",
]

#: side sign σ: +1 for the outside blade (cuts the concave flank), −1 for the inside blade
BLADE_SIDES: dict[str, int] = {"outside": 1, "inside": -1}
PROFILE_TYPES = ("straight", "circular")

_MAX_BLADE_ANGLE = math.radians(45.0)
_MAX_REM_ANGLE = math.radians(20.0)


@dataclass(frozen=True)
class Blade:
    """Geometry of one face-milling blade (seed Fig. 2.3; angles in rad, lengths in mm).

    Parameters
    ----------
    side : str
        ``"outside"`` (cuts the concave flank) or ``"inside"`` (cuts the convex flank).
    point_radius : float — [mm]
        r_p, radius of the nominal profile line at the tip plane; > 0.
    blade_angle : float — [rad]
        α, angle between the nominal profile line and the cutter axis, in [0, 45°).
    edge_radius : float — [mm]
        r_e ≥ 0, tip (edge) radius.
    profile : str
        ``"straight"`` or ``"circular"``.
    profile_radius : float — [mm]
        R_pr of a circular profile, > 0 convex edge, < 0 concave edge; |R_pr| > r_e.
        Ignored for a straight profile.
    profile_reference_height : float — [mm]
        h_ref ≥ 0, height above the tip where a circular profile is tangent to the nominal line.
    toprem_angle : float — [rad]
        Δα_T, change of blade angle in the toprem section, |Δα_T| < 20°; 0 = no toprem.
    toprem_height : float — [mm]
        h_T, height of the toprem/profile corner above the tip; > r_e when Δα_T ≠ 0.
    flankrem_angle : float — [rad]
        Δα_F, change of blade angle in the flankrem section, |Δα_F| < 20°; 0 = no flankrem.
    flankrem_height : float — [mm]
        h_F, height of the profile/flankrem corner above the tip; > h_T when Δα_F ≠ 0.
    blade_phase : float — [rad]
        θ_b, angular position of the blade's reference point M (radius r_p, tip plane) in
        the head at spin θ = 0, about +z_t; |θ_b| ≤ 360°. Face hobbing: the outside and
        inside blades of a group sit at different phases (seed Fig. 2.1b, 2.3). Default 0.
    blade_offset_angle : float — [rad]
        δ_b, angle at the cutter axis between the radius to M and the blade's rake plane
        (seed Fig. 2.3, Eq. 2.6c): the rake plane is the head's axial half-plane through M
        turned by δ_b about the axial line through M, so that it lies at the distance
        r_p |sin δ_b| from the cutter axis (the blade offset). |δ_b| < 45°; face hobbing
        typically δ_b ≈ ν, the cutter's lead angle, which puts the rake face normal to the
        tooth trace. Default 0 (face milling: the edge lies in an axial plane).
    rake_angle : float — [rad]
        Side rake of the blade's front face, a further turn of the rake plane about the
        axial line through M (adds to δ_b: the rake plane is turned by
        γ_a = δ_b + rake_angle); |rake| < 30°. Default 0.
    hook_angle : float — [rad]
        γ_h, hook of the rake plane: its turn about its own horizontal line through M
        (tilts the edge towards or away from the cutting direction); |γ_h| < 20°.
        Default 0.
    point_width : float — [mm]
        W ≥ 0, the blade's point width: the width of its flat tip in the tip plane, from the
        point (ρ = r_p) across the slot (towards smaller ρ on an outside blade, larger on an
        inside blade). The tip cuts the slot bottom; a spread-blade cutter's W is the
        outside minus the inside point radius, a blade that finishes one flank alone has its
        own. 0 = not given (the FE root model then cannot bound the tip's cut). Default 0.

    Notes
    -----
    The profile (blade angle, edge radius, toprem, circular profile, flankrem) is given in
    the rake plane: ρ − r_p is measured in the rake plane along its horizontal line from M
    and h along its "vertical" line. With the four placement angles zero the edge lies in
    the head's axial plane at θ = 0 and the blade is a face-milling blade (seed Eq. 2.6).

    Raises
    ------
    InputError
        A field is not finite or out of its range; the message names the field.
    """

    side: str
    point_radius: float
    blade_angle: float
    edge_radius: float = 0.0
    profile: str = "straight"
    profile_radius: float = 0.0
    profile_reference_height: float = 0.0
    toprem_angle: float = 0.0
    toprem_height: float = 0.0
    flankrem_angle: float = 0.0
    flankrem_height: float = 0.0
    blade_phase: float = 0.0
    blade_offset_angle: float = 0.0
    rake_angle: float = 0.0
    hook_angle: float = 0.0
    point_width: float = 0.0

    def __post_init__(self) -> None:
        if self.side not in BLADE_SIDES:
            raise InputError(f"side: must be one of {sorted(BLADE_SIDES)}, got {self.side!r}")
        if self.profile not in PROFILE_TYPES:
            raise InputError(f"profile: must be one of {list(PROFILE_TYPES)}, got {self.profile!r}")
        for name in ("point_radius", "blade_angle", "edge_radius", "profile_radius",
                     "profile_reference_height", "toprem_angle", "toprem_height",
                     "flankrem_angle", "flankrem_height", "blade_phase",
                     "blade_offset_angle", "rake_angle", "hook_angle", "point_width"):
            object.__setattr__(self, name, real(name, getattr(self, name)))
        for name, bound, closed in (("blade_phase", 360.0, True),
                                    ("blade_offset_angle", 45.0, False),
                                    ("rake_angle", 30.0, False), ("hook_angle", 20.0, False)):
            deg = math.degrees(getattr(self, name))
            if abs(deg) > bound + 1e-9 if closed else abs(deg) >= bound:
                brackets = "[]" if closed else "()"
                raise InputError(f"{name}: must be in {brackets[0]}-{bound:g}, {bound:g}"
                                 f"{brackets[1]} deg, got {deg:.6g}")
        if self.point_radius <= 0.0:
            raise InputError(f"point_radius: must be > 0 mm, got {self.point_radius}")
        if not 0.0 <= self.blade_angle < _MAX_BLADE_ANGLE:
            raise InputError(
                f"blade_angle: must be in [0, 45) deg, got {math.degrees(self.blade_angle):.6g}")
        if not 0.0 <= self.edge_radius < 0.5 * self.point_radius:
            raise InputError(
                f"edge_radius: must be in [0, point_radius/2) = [0, {0.5 * self.point_radius:g}) "
                f"mm, got {self.edge_radius}")
        if not 0.0 <= self.point_width < self.point_radius:
            raise InputError(
                f"point_width: must be in [0, point_radius) = [0, {self.point_radius:g}) mm "
                f"(0: not given), got {self.point_width}")
        if self.profile == "circular":
            if abs(self.profile_radius) <= max(self.edge_radius, 1e-6):
                raise InputError(
                    f"profile_radius: a circular profile needs |profile_radius| > edge_radius "
                    f"({self.edge_radius} mm), got {self.profile_radius}")
            if self.profile_reference_height < 0.0:
                raise InputError(
                    "profile_reference_height: must be >= 0 mm, got "
                    f"{self.profile_reference_height}")
        for rem in ("toprem", "flankrem"):
            angle = getattr(self, f"{rem}_angle")
            if abs(angle) >= _MAX_REM_ANGLE:
                raise InputError(
                    f"{rem}_angle: must be in (-20, 20) deg, got {math.degrees(angle):.6g}")
            if not 0.0 <= self.blade_angle + angle < 0.5 * math.pi:
                raise InputError(
                    f"{rem}_angle: blade_angle + {rem}_angle must be in [0, 90) deg, got "
                    f"{math.degrees(self.blade_angle + angle):.6g}")
        if self.toprem_angle != 0.0 and self.toprem_height <= self.edge_radius:
            raise InputError(
                f"toprem_height: must be > edge_radius ({self.edge_radius} mm) when a toprem "
                f"angle is given, got {self.toprem_height}")
        if self.flankrem_angle != 0.0:
            lower = self.toprem_height if self.toprem_angle != 0.0 else self.edge_radius
            if self.flankrem_height <= lower:
                raise InputError(
                    f"flankrem_height: must be > {lower} mm (above the toprem corner and the "
                    f"edge radius) when a flankrem angle is given, got {self.flankrem_height}")
        # constructing the sections checks that the edge radius fits the profile
        profile_sections(self)

    @property
    def placed(self) -> bool:
        """True if the blade is placed off the head's axial plane (phase, offset, rake or hook
        ≠ 0): its edge is a space curve (face hobbing), not a meridian."""
        return bool(self.blade_phase or self.blade_offset_angle or self.rake_angle
                    or self.hook_angle)

    @property
    def rake_plane_angle(self) -> float:
        """γ_a = δ_b + rake angle [rad]: the turn of the rake plane about the axial line
        through M."""
        return self.blade_offset_angle + self.rake_angle

    @property
    def sigma(self) -> int:
        """Side sign σ: +1 outside blade (concave flank), −1 inside blade (convex flank)."""
        return BLADE_SIDES[self.side]


def mirror_blade(blade: Blade) -> Blade:
    """The blade that cuts the mirror image (y → −y) of a flank: placement angles negated.

    Parameters
    ----------
    blade : Blade

    Returns
    -------
    Blade
        ``blade`` with the blade phase θ_b, the blade offset angle δ_b, the rake angle and
        the hook angle γ_h negated; side, radii and profile unchanged (a face-milling blade,
        :attr:`Blade.placed` False, is returned equal to itself).

    Notes
    -----
    The mirror rule of the face-hobbing chain (design note "Face hobbing", §2.8 "Hand and
    mirror"; the placement of :func:`placement_vectors`): with D = diag(1, −1, 1),
    D R_z(a) D = R_z(−a) and D R_x(a) D = R_x(−a), while the profile point [ρ − r_p, 0, −h]
    of the rake plane is its own mirror image, so
    D B(θ_b, γ_a, γ_h) e_b = B(−θ_b, −γ_a, −γ_h) e_b (γ_a = δ_b + rake). Used with
    :func:`geometry.machine.cradle.mirror_settings` (θ → −θ, q → −q, κ unchanged) it generates
    the mirror image D r_g of the member.
    """
    return replace(blade, blade_phase=-blade.blade_phase,
                   blade_offset_angle=-blade.blade_offset_angle,
                   rake_angle=-blade.rake_angle, hook_angle=-blade.hook_angle)


class ProfileSections(NamedTuple):
    """Constant-curvature sections of a blade edge, ordered from the tip upwards.

    Section k is valid for ``s_lo[k] <= s <= s_hi[k]``; on it the edge is the curve of
    constant curvature ``kappa[k]`` [1/mm] (left-normal sign in the (ρ, h) plane) through
    ``(rho_ref[k], h_ref[k])`` with tangent angle ``psi_ref[k]`` [rad] (from the ρ axis) at
    ``s = s_ref[k]``. ``corner_above[k]`` is True where the junction with section k+1 is a
    corner (tangent discontinuity). ``main`` is the index of the profile section and
    ``names`` say what each section is.
    """

    s_lo: np.ndarray
    s_hi: np.ndarray
    s_ref: np.ndarray
    rho_ref: np.ndarray
    h_ref: np.ndarray
    psi_ref: np.ndarray
    kappa: np.ndarray
    corner_above: np.ndarray
    main: int
    names: tuple[str, ...]


_EPS = float(np.finfo(float).eps)  # np.sinc's stand-in for 0


def _curve_point(rho0, h0, psi0, kappa, t):
    """Point, tangent and second derivative of a constant-curvature curve at arc length t."""
    half = 0.5 * kappa * t
    # sin(half)/half, exact at kappa = 0: np.sinc(half / π)'s arithmetic without its wrapper
    y = np.pi * (half / np.pi)
    y = np.where(y, y, _EPS)
    sinc = np.sin(y) / y
    mid = psi0 + half
    rho = rho0 + t * np.cos(mid) * sinc
    h = h0 + t * np.sin(mid) * sinc
    psi = psi0 + kappa * t
    c, s = np.cos(psi), np.sin(psi)
    return rho, h, c, s, -kappa * s, kappa * c


def _t_at_height(h0: float, psi0: float, kappa: float, h_target: float) -> float:
    """Arc length from the reference to where a constant-curvature curve reaches h_target."""
    dh = h_target - h0
    if abs(kappa) < 1e-14:
        return dh / math.sin(psi0)
    # h(t) = h0 + (cos psi0 - cos(psi0 + kappa t)) / kappa
    c = math.cos(psi0) - kappa * dh
    if abs(c) > 1.0:
        raise InputError(
            f"blade profile: a circular section of radius {1 / abs(kappa):g} mm does not reach "
            f"height {h_target:g} mm; increase |profile_radius|")
    base = math.acos(c)
    best = None
    for cand in (base, -base):
        for k in (-1, 0, 1):
            t = (cand + 2 * math.pi * k - psi0) / kappa
            if best is None or abs(t) < abs(best):
                best = t
    return float(best)


def _line_psi(sigma: int, angle: float) -> float:
    """Tangent angle (from the ρ axis, going up the blade) of a line of blade angle ``angle``."""
    return math.atan2(math.cos(angle), sigma * math.sin(angle))


def profile_sections(blade: Blade) -> ProfileSections:
    """Split a blade edge into its constant-curvature sections (seed Fig. 2.3c).

    Parameters
    ----------
    blade : Blade

    Returns
    -------
    ProfileSections
        Arrays of length n_sections (1 to 4), see :class:`ProfileSections`.

    Raises
    ------
    InputError
        If the edge radius cannot be fitted tangent to the tip plane and the lowest section.

    Notes
    -----
    Seed §2.2.2 names the sections (edge, toprem, profile, flankrem) but gives no formulas;
    the construction (tangent edge radius, corners at the toprem and flankrem heights,
    circular profile tangent to the nominal line at h_ref) is ours and follows Fig. 2.3c.
    The sections are kept per blade object and shared by their callers
    (:func:`_memo_profile_sections`): their arrays are not to be written.
    """
    return _memo_profile_sections(Same(blade))


@memoised(maxsize=32)
def _memo_profile_sections(blade: Same) -> ProfileSections:
    """:func:`profile_sections` of the blade ``blade.obj``, once per blade object (a frozen
    dataclass): a study point asked for them 3 times (≈ 0.4 ms; the study's cases share
    their blades, so once per study, issue 75). The same arithmetic, bit for bit; its
    arrays read-only (shared by every caller, :func:`geometry.core.caches.read_only`)."""
    return read_only(_profile_sections(blade.obj))


def _profile_sections(blade: Blade) -> ProfileSections:
    """:func:`profile_sections`, computed."""
    sg = blade.sigma
    a = blade.blade_angle
    # main profile as a constant-curvature curve referenced at its tangency point with the
    # nominal line (height h_ref for a circular profile, the tip point for a straight one)
    if blade.profile == "circular":
        h_q = blade.profile_reference_height
        kap_main = sg / blade.profile_radius
    else:
        h_q = 0.0
        kap_main = 0.0
    main_ref = (blade.point_radius + sg * h_q * math.tan(a), h_q, _line_psi(sg, a), kap_main)
    # lowest working section (toprem line, or the profile itself)
    jt = None
    if blade.toprem_angle != 0.0:
        jt = _point_on(main_ref, blade.toprem_height)
        low_ref = (jt[0], jt[1], _line_psi(sg, a + blade.toprem_angle), 0.0)
    else:
        low_ref = main_ref
    sections = []  # tuples (name, s_lo, s_hi, s_ref, rho, h, psi, kappa, corner_above)
    edge, s1, start_low = _edge_arc(blade, low_ref)
    if edge is not None:
        sections.append(("edge", 0.0, s1, edge[0], edge[1], edge[2], edge[3], edge[4], False))
    main_index = _sections_above(blade, main_ref, low_ref, jt, start_low, s1, sections)
    cols = list(zip(*sections, strict=True))
    return ProfileSections(
        s_lo=np.array(cols[1], dtype=float), s_hi=np.array(cols[2], dtype=float),
        s_ref=np.array(cols[3], dtype=float), rho_ref=np.array(cols[4], dtype=float),
        h_ref=np.array(cols[5], dtype=float), psi_ref=np.array(cols[6], dtype=float),
        kappa=np.array(cols[7], dtype=float), corner_above=np.array(cols[8], dtype=bool),
        main=main_index, names=tuple(cols[0]))


def working_sections(blade: Blade | ProfileSections) -> list[int]:
    """Indices of the sections that cut the working flank: the profile and its toprem and
    flankrem lines (relief, :mod:`geometry.machine.relief`), not the edge radius (the fillet).

    Parameters
    ----------
    blade : Blade or ProfileSections

    Returns
    -------
    list of int
        Section indices of :func:`profile_sections`, in order.

    Notes
    -----
    The toprem and flankrem corners turn the edge's tangent by a few degrees at most (relief
    of tens of µm over millimetres of blade), so a field sampled over the working sections
    is smooth enough for a spline; the fillet's turn of some 65° is not.
    """
    sec = blade if isinstance(blade, ProfileSections) else profile_sections(blade)
    return [k for k, name in enumerate(sec.names) if name != "edge"]


def _point_on(ref, h):
    """(ρ, h, ψ) where the constant-curvature curve ``ref`` = (ρ₀, h₀, ψ₀, κ) reaches
    height h [mm]."""
    rho0, h0, psi0, kap = ref
    t = _t_at_height(h0, psi0, kap, h)
    rho, hh, c, s, _, _ = _curve_point(rho0, h0, psi0, kap, t)
    return float(rho), float(hh), math.atan2(s, c)


def _edge_arc(blade: Blade, low_ref):
    """The edge radius: an arc tangent to the tip plane (h = 0) and to the lowest section
    ``low_ref``; returns (s_ref, ρ, h, ψ, κ) of the arc (None without an edge radius), its
    length [mm] and where the lowest section starts (ρ, h) [mm]."""
    sg, a, re = blade.sigma, blade.blade_angle, blade.edge_radius
    has_top = blade.toprem_angle != 0.0
    rho0, h0, psi0, kap = low_ref
    psi_tip = 0.0 if sg > 0 else math.pi
    if not re > 0.0:
        # the lowest section meets the tip plane directly
        rl, hl, _ = _point_on(low_ref, 0.0)
        return None, 0.0, (rl, hl)
    if abs(kap) < 1e-14:
        alpha_low = math.atan2(sg * math.cos(psi0), math.sin(psi0))  # blade angle of line
        rho_tip_line = rho0 - sg * h0 * math.tan(alpha_low)
        rho_c = rho_tip_line - sg * re * (1.0 - math.sin(alpha_low)) / math.cos(alpha_low)
        centre = (rho_c, re)
        n1 = (sg * math.cos(alpha_low), -math.sin(alpha_low))  # tool outward normal
        t1 = (centre[0] + re * n1[0], centre[1] + re * n1[1])
        psi1 = psi0
    else:
        rpr = 1.0 / abs(kap)
        # centre of the profile circle: on the left (kap > 0) or right of the tangent
        cp = (rho0 - math.sin(psi0) / kap, h0 + math.cos(psi0) / kap)
        # edge centre at height re, at distance |R - re| (convex, centre inside the blade)
        # or R + re (concave) from the profile centre
        convex = blade.profile_radius > 0
        dist = rpr - re if convex else rpr + re
        dy = re - cp[1]
        if dist * dist < dy * dy:
            raise InputError(
                "edge_radius: no edge arc tangent to both the tip plane and the circular "
                f"profile (profile_radius {blade.profile_radius:g} mm, reference height "
                f"{blade.profile_reference_height:g} mm)")
        root = math.sqrt(dist * dist - dy * dy)
        # the branch on the profile's side of the circle (towards the tip-line solution)
        guess = blade.point_radius - sg * re * (1.0 - math.sin(a)) / math.cos(a)
        cands = (cp[0] + root, cp[0] - root)
        rho_c = min(cands, key=lambda r: abs(r - guess))
        centre = (rho_c, re)
        d = (centre[0] - cp[0], centre[1] - cp[1])
        nd = math.hypot(*d)
        t1 = (cp[0] + rpr * d[0] / nd, cp[1] + rpr * d[1] / nd)
        psi1 = None
    if t1[1] < 0.0 or t1[1] > (blade.toprem_height if has_top else np.inf):
        raise InputError(
            "edge_radius: the edge radius does not fit below the toprem corner / profile "
            f"(tangent point at height {t1[1]:.4g} mm)")
    if psi1 is None:
        # tangent of the edge arc at t1, going up the blade: the arc turns
        # counter-clockwise (centre on the left) for sigma = +1, clockwise for -1
        nx, ny = (t1[0] - centre[0]) / re, (t1[1] - centre[1]) / re
        psi1 = math.atan2(nx, -ny) if sg > 0 else math.atan2(-nx, ny)
    len_edge = re * abs(psi1 - psi_tip)
    return (0.0, centre[0], 0.0, psi_tip, sg / re), len_edge, (t1[0], t1[1])


def _sections_above(blade: Blade, main_ref, low_ref, jt, start_low, s: float,
                    sections: list) -> int:
    """Append the toprem (if any), profile and flankrem (if any) sections from arc length
    ``s`` [mm] at ``start_low`` upwards to ``sections``; return the profile's index."""
    sg, a = blade.sigma, blade.blade_angle
    has_flank = blade.flankrem_angle != 0.0

    def ref_t(ref, point):
        return _t_at_height(ref[1], ref[2], ref[3], point[1])

    if jt is not None:
        # toprem: from start_low up to the corner jt (a straight line)
        length = math.hypot(jt[0] - start_low[0], jt[1] - start_low[1])
        sections.append(("toprem", s, s + length, s, start_low[0], start_low[1],
                         low_ref[2], 0.0, True))
        s += length
        start_main = (jt[0], jt[1])
    else:
        start_main = start_low
    # main profile from start_main (arc length measured along the main curve)
    t_start = ref_t(main_ref, start_main)
    s_ref_main = s - t_start
    if has_flank:
        jf = _point_on(main_ref, blade.flankrem_height)
        t_end = ref_t(main_ref, jf)
        s_hi_main = s_ref_main + t_end
        if s_hi_main <= s:
            raise InputError("flankrem_height: the flankrem corner lies below the profile start")
    else:
        s_hi_main = np.inf
    sections.append(("profile", s, s_hi_main, s_ref_main, main_ref[0], main_ref[1],
                     main_ref[2], main_ref[3], has_flank))
    main_index = len(sections) - 1
    if has_flank:
        sections.append(("flankrem", s_hi_main, np.inf, s_hi_main, jf[0], jf[1],
                         _line_psi(sg, a + blade.flankrem_angle), 0.0, False))
    return main_index


class BladeProfilePoint(NamedTuple):
    """Edge point in the (ρ, h) plane with s-derivatives (all arrays of one shape)."""

    rho: np.ndarray  # [mm]
    h: np.ndarray  # [mm]
    drho: np.ndarray  # [1]
    dh: np.ndarray  # [1]
    d2rho: np.ndarray  # [1/mm]
    d2h: np.ndarray  # [1/mm]


def _section_index(sections: ProfileSections, s: np.ndarray) -> np.ndarray:
    """Index of the section holding arc length ``s`` (values below 0 map to section 0)."""
    idx = np.searchsorted(sections.s_hi, np.asarray(s, dtype=float), side="left")
    return np.clip(idx, 0, len(sections.s_hi) - 1)


def blade_profile(blade: Blade | ProfileSections, s, section=None) -> BladeProfilePoint:
    """Point of the blade edge at arc length s, with first and second s-derivatives.

    Parameters
    ----------
    blade : Blade or ProfileSections
    s : array_like — [mm]
        Arc length along the edge from the tip (any shape).
    section : array_like of int, optional
        Section to evaluate (same shape as s); by default the section holding s. Passing a
        section evaluates its analytic extension beyond its range (used by the solver).

    Returns
    -------
    BladeProfilePoint
        ρ, h [mm]; dρ/ds, dh/ds [1]; d²ρ/ds², d²h/ds² [1/mm].

    Notes
    -----
    Seed Eq. 2.5 gives the unit tangent of a straight edge, [sin α_b, 0, cos α_b]; the other
    sections are constant-curvature arcs evaluated in closed form.
    """
    sec = blade if isinstance(blade, ProfileSections) else profile_sections(blade)
    s = np.asarray(s, dtype=float)
    k = _section_index(sec, s) if section is None else np.asarray(section, dtype=int)
    t = s - sec.s_ref[k]
    rho, h, c, sn, d2r, d2h = _curve_point(sec.rho_ref[k], sec.h_ref[k], sec.psi_ref[k],
                                           sec.kappa[k], t)
    return BladeProfilePoint(rho, h, c, sn, d2r, d2h)


class BladeEdge(NamedTuple):
    """The blade edge as a curve in the cutter frame at spin θ = 0, with s-derivatives."""

    e: np.ndarray  # (..., 3) [mm]
    e_s: np.ndarray  # (..., 3) [1]
    e_ss: np.ndarray  # (..., 3) [1/mm]


def placement_vectors(blade: Blade) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The blade placement in the head: M and the rake plane's two in-plane directions.

    Parameters
    ----------
    blade : Blade

    Returns
    -------
    m, a1, a2 : ndarray (3,)
        M = r_p (cos θ_b, sin θ_b, 0) [mm]; a1 = R_z(θ_b + γ_a) e_x, the rake plane's
        horizontal line through M (ρ − r_p is measured along it); a2 = R_z(θ_b + γ_a)
        R_x(γ_h) e_z, its "vertical" line (h is measured along −a2) [1].

    Notes
    -----
    B(θ_b, γ_a, γ_h) = R_z(θ_b) T(r_p, 0, 0) R_z(γ_a) R_x(γ_h) applied to the profile point
    [ρ − r_p, 0, −h] of the rake plane (``docs/machine.md``, "Blade placement"; seed
    Eq. 2.6b–c and Fig. 2.3, whose blade offset angle δ_b, rake and hook angles it reads).
    """
    ph, ga, gh = blade.blade_phase, blade.rake_plane_angle, blade.hook_angle
    m = blade.point_radius * np.array([math.cos(ph), math.sin(ph), 0.0])
    a1 = np.array([math.cos(ph + ga), math.sin(ph + ga), 0.0])
    a2 = np.array([-math.sin(ph + ga) * -math.sin(gh), math.cos(ph + ga) * -math.sin(gh),
                   math.cos(gh)])
    return m, a1, a2


def blade_edge(blade: Blade, s, section=None,
               sections: ProfileSections | None = None) -> BladeEdge:
    """The blade edge e(s) in the cutter frame at spin θ = 0 (seed Eq. 2.6b–c).

    Parameters
    ----------
    blade : Blade
    s : array_like — [mm]
        Arc length along the edge (any shape).
    section : array_like of int, optional
        Section to evaluate (see :func:`blade_profile`).
    sections : ProfileSections, optional
        Precomputed :func:`profile_sections` of ``blade``.

    Returns
    -------
    BladeEdge
        e = M + (ρ − r_p) a1 − h a2 and its first two s-derivatives, arrays s.shape + (3,)
        (:func:`placement_vectors`). A face-milling blade (no placement) gives
        e = [ρ, 0, −h].
    """
    sec = profile_sections(blade) if sections is None else sections
    p = blade_profile(sec, np.asarray(s, dtype=float), section)
    m, a1, a2 = placement_vectors(blade)
    rr = (p.rho - blade.point_radius)[..., None]
    return BladeEdge(m + rr * a1 - p.h[..., None] * a2,
                     p.drho[..., None] * a1 - p.dh[..., None] * a2,
                     p.d2rho[..., None] * a1 - p.d2h[..., None] * a2)


class CutterSurface(NamedTuple):
    """Cutter surface r_t(s, θ) in the cutter frame with derivatives; vectors on the last axis."""

    r: np.ndarray  # (..., 3) [mm]
    r_s: np.ndarray  # ∂r/∂s [1]
    r_theta: np.ndarray  # ∂r/∂θ [mm/rad]
    r_ss: np.ndarray  # [1/mm]
    r_stheta: np.ndarray  # [1/rad]
    r_thetatheta: np.ndarray  # [mm/rad²]
    normal: np.ndarray  # unit normal out of the work material [1]


def cutter_surface(blade: Blade, s, theta, section=None,
                   sections: ProfileSections | None = None) -> CutterSurface:
    """Cutter surface of revolution r_t(s, θ) with analytic derivatives (seed Eq. 2.6).

    Parameters
    ----------
    blade : Blade
    s : array_like — [mm]
        Arc length along the edge (broadcast with theta).
    theta : array_like — [rad]
        Angle of the blade about the cutter axis.
    section : array_like of int, optional
        Section index to evaluate (see :func:`blade_profile`).
    sections : ProfileSections, optional
        Precomputed :func:`profile_sections` of ``blade``.

    Returns
    -------
    CutterSurface
        Arrays of shape broadcast(s, θ) + (3,): position [mm] in the cutter frame S_t, first
        and second derivatives, and the unit normal pointing out of the work material.

    Notes
    -----
    Seed Eq. 2.6a–c: r_t = M_z(θ) r_b with the blade point r_b = [ρ, 0, −h] in the
    blade's axial plane. The normal is σ [−(dh/ds) cos θ, −(dh/ds) sin θ, −dρ/ds]
    (σ = +1 outside blade), the reverse of the tool's outward normal, because the work
    material lies on the other side of the cut surface from the tool. A placed blade
    (:attr:`Blade.placed`, face hobbing) has the edge :func:`blade_edge`, a space curve;
    it still sweeps a surface of revolution r_t = R_z(θ) e(s) (a hyperboloid of
    revolution for a straight edge off the axial plane, seed §2.2.1), whose normal is
    −σ e′ × (e_z × e) / |…| turned by θ (equal to the expression above without placement).
    """
    sec = profile_sections(blade) if sections is None else sections
    s, theta = np.broadcast_arrays(np.asarray(s, dtype=float), np.asarray(theta, dtype=float))
    if blade.placed:
        return _placed_cutter_surface(blade, sec, s, theta, section)
    p = blade_profile(sec, s, section)
    c, sn = np.cos(theta), np.sin(theta)
    sg = blade.sigma

    def vec(x, y, z):
        out = np.empty((*s.shape, 3))
        out[..., 0], out[..., 1], out[..., 2] = x, y, z
        return out

    return CutterSurface(
        r=vec(p.rho * c, p.rho * sn, -p.h), r_s=vec(p.drho * c, p.drho * sn, -p.dh),
        r_theta=vec(-p.rho * sn, p.rho * c, 0.0),
        r_ss=vec(p.d2rho * c, p.d2rho * sn, -p.d2h),
        r_stheta=vec(-p.drho * sn, p.drho * c, 0.0),
        r_thetatheta=vec(-p.rho * c, -p.rho * sn, 0.0),
        normal=vec(-sg * p.dh * c, -sg * p.dh * sn, -sg * p.drho))


def revolution_normal(blade: Blade, e: np.ndarray, e_s: np.ndarray) -> np.ndarray:
    """Unit normal −σ e′ × (e_z × e)/|…| of the surface of revolution swept by an edge.

    Parameters
    ----------
    blade : Blade
        Gives the side sign σ.
    e, e_s : ndarray (..., 3) — [mm], [1]
        Edge points and tangents (:func:`blade_edge`).

    Returns
    -------
    ndarray (..., 3) — [1]
        The normal out of the work material at spin θ = 0 (for an unplaced blade
        σ[−h′, 0, −ρ′], as :func:`cutter_surface`).

    Notes
    -----
    The surface R_z(θ) e(s) has the tangents e′ and e_z × e at θ = 0; their cross product is
    its normal (seed Eq. 2.6 generalised to a space-curve edge, design note "Face hobbing"
    §2.9).
    """
    ez_e = np.stack([-e[..., 1], e[..., 0], np.zeros(e.shape[:-1])], -1)
    n = -blade.sigma * np.cross(e_s, ez_e)
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def _placed_cutter_surface(blade: Blade, sec: ProfileSections, s: np.ndarray,
                           theta: np.ndarray, section) -> CutterSurface:
    """:func:`cutter_surface` of a placed blade: R_z(θ) applied to :func:`blade_edge`."""
    edge = blade_edge(blade, s, section, sec)
    c, sn = np.cos(theta)[..., None], np.sin(theta)[..., None]

    def rot(v):
        return np.stack([c[..., 0] * v[..., 0] - sn[..., 0] * v[..., 1],
                         sn[..., 0] * v[..., 0] + c[..., 0] * v[..., 1], v[..., 2]], -1)

    def spin(v):  # S v = e_z × v
        return np.stack([-v[..., 1], v[..., 0], np.zeros(v.shape[:-1])], -1)

    r, r_s, r_ss = rot(edge.e), rot(edge.e_s), rot(edge.e_ss)
    return CutterSurface(r=r, r_s=r_s, r_theta=spin(r), r_ss=r_ss, r_stheta=spin(r_s),
                         r_thetatheta=spin(spin(r)),
                         normal=rot(revolution_normal(blade, edge.e, edge.e_s)))


def cutter_curvatures(blade: Blade, s, section=None) -> tuple[np.ndarray, np.ndarray]:
    """Principal curvatures of the cutter surface (the imprint it leaves on the work).

    Parameters
    ----------
    blade : Blade
    s : array_like — [mm]
        Arc length along the edge.
    section : array_like of int, optional

    Returns
    -------
    kappa_meridian : ndarray — [1/mm]
        Normal curvature along the blade edge (the profile direction).
    kappa_parallel : ndarray — [1/mm]
        Normal curvature along the circle swept by the blade (lengthwise direction).

    Notes
    -----
    Sign: positive where the work surface is convex (κ = dn·dr/dr·dr with n out of the work
    material). For a surface of revolution the meridians and parallels are lines of
    curvature; with the unit-speed edge (ρ(s), ζ(s) = −h(s)) and the work normal of
    :func:`cutter_surface`: κ_meridian = σ (ρ' ζ'' − ζ' ρ''), κ_parallel = σ ζ'/ρ
    (first and second fundamental forms of a surface of revolution, e.g. do Carmo 1976,
    §3-3 Example 4). A straight outside blade gives κ_parallel = −cos α/ρ (concave flank).
    A placed blade's edge is a space curve: its meridian (ρ_m = |e_xy|, ζ = e_z) is not
    parametrised by arc length, and the same formulas carry the speed
    v = (ρ_m′² + ζ′²)^½: κ_meridian = σ (ρ_m′ ζ″ − ζ′ ρ_m″)/v³, κ_parallel = σ ζ′/(ρ_m v).
    """
    sg = blade.sigma
    if not blade.placed:
        p = blade_profile(blade, s, section)
        zeta_d, zeta_dd = -p.dh, -p.d2h
        k_mer = sg * (p.drho * zeta_dd - zeta_d * p.d2rho)
        k_par = sg * zeta_d / p.rho
        return k_mer, k_par
    e, e1, e2 = blade_edge(blade, s, section)
    rho = np.hypot(e[..., 0], e[..., 1])
    rho1 = (e[..., 0] * e1[..., 0] + e[..., 1] * e1[..., 1]) / rho
    rho2 = ((e1[..., 0] ** 2 + e1[..., 1] ** 2 + e[..., 0] * e2[..., 0]
             + e[..., 1] * e2[..., 1]) - rho1**2) / rho
    z1, z2 = e1[..., 2], e2[..., 2]
    v = np.hypot(rho1, z1)
    return sg * (rho1 * z2 - z1 * rho2) / v**3, sg * z1 / (rho * v)
