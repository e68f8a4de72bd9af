"""The root line a blade cuts: its generated edge-radius and tip points on transverse sections.

A lengthwise fraction u of the member's projection plane (:mod:`geometry.machine.flank`)
picks the straight line between the front and back cones at that fraction; its surface of
revolution about the member axis is a *transverse section* with coordinates v (profile
fraction: 0 on the root cone, 1 on the face cone, negative below the root cone) and φ.
Near the slot bottom the generated surface turns flat, where v is no parameter, so the
fillet is solved at prescribed blade arc lengths s: the equation of meshing (seed Eq. 2.8)
with the point on the section's line, unknowns θ, q and v, Newton's method continued in s
from the lowest generated point down to s = 0 — the edge radius's tangent point with the
tip plane, whose generated points are the cut's **root line** — and, with the blade's flat
tip added below s = 0 (:func:`tip_sections`), on along the slot bottom the tip cuts.

The FE tooth (:mod:`contact.compliance.fe.section`) builds its fillets and slot bottoms
from these points; the synthesis (:mod:`geometry.synthesis.tip_plane`) places a cut's tip
plane by its root line.

Public names
------------
projection_point   (z, ρ) of projection-plane fractions (the bilinear map) and ∂/∂v
section_envelope   generated points of one cut on (sections × profile fractions) and the
                   start of each section's fillet march
section_march      fillet (and tip) points at blade arc lengths, per section
tip_sections       a blade's profile sections with its flat tip below s = 0
root_line_points   v, φ of a cut's root line in each section
below_root_cone    depth of projection-plane points below the blank's root cone
"""

from __future__ import annotations

import numpy as np

from geometry.case import Blank
from geometry.machine.cradle import MachineSettings
from geometry.machine.cutter import Blade, ProfileSections, profile_sections
from geometry.machine.family import (
    chain,
    family_views,
    generated_buffer,
    generated_family,
    meshing_buffer,
)
from geometry.machine.flank import blank_outline
from geometry.machine.meshing import EnvelopeSolution, solve_envelope

__all__ = [
    "EDGE_STEPS",
    "V_TARGETS",
    "below_root_cone",
    "projection_point",
    "root_line_points",
    "section_envelope",
    "section_march",
    "tip_sections",
]

#: mirror y → −y of a left-hand member
MIRROR = np.array([1.0, -1.0, 1.0])
#: profile fractions of the flank targets: down to a whole depth under the root cone
#: (generated slot bottoms lie up to half a depth under it at the toe of a tilted
#: pinion), denser near the root
V_TARGETS = np.r_[np.linspace(-1.0, -0.3, 15)[:-1], np.linspace(-0.3, 0.2, 41)[:-1],
                  np.linspace(0.2, 1.0, 17)]
EDGE_STEPS = 24  # blade arc-length steps of the fillet continuation down to s = 0
NEWTON_ITER = 40
NEWTON_TOL = 1e-10  # [mm] position, [1] × L meshing residual
STEP_LIMIT = np.array([0.05, 0.05, 0.05])  # [rad, rad, 1] Newton step limits θ, q, v


def projection_point(corners: np.ndarray, u, v):
    """(z, ρ) [mm] of projection-plane fractions and their v-derivative (..., 2).

    ``corners`` (2, 2, 2) [mm]: :attr:`geometry.machine.flank.BlankOutline.corners`
    ([toe, heel] × [root, tip] as (z, ρ)); ``u``, ``v`` [1] broadcast together."""
    u = np.asarray(u, dtype=float)[..., None]
    v = np.asarray(v, dtype=float)[..., None]
    c = corners
    p = (1 - u) * (1 - v) * c[0, 0] + u * (1 - v) * c[1, 0] + (1 - u) * v * c[0, 1] \
        + u * v * c[1, 1]
    pv = (1 - u) * (c[0, 1] - c[0, 0]) + u * (c[1, 1] - c[1, 0])
    return p, np.broadcast_to(pv, p.shape)


def section_envelope(blade: Blade, settings: MachineSettings, blank: Blank, u: np.ndarray
                     ) -> tuple[EnvelopeSolution, np.ndarray, np.ndarray]:
    """Generated points of one cut at the profile fractions :data:`V_TARGETS` of each
    section ``u`` (K,) [1] (:func:`geometry.machine.meshing.solve_envelope`, seed
    Eq. 2.7a, 2.8), the (K, V) fractions v, and (K, 4) the start s, θ, q, v of each
    section's fillet march: its lowest generated point (NaN where none)."""
    corners = blank_outline(blank).corners
    uu, vv = np.meshgrid(u, V_TARGETS, indexing="ij")
    p, pv = projection_point(corners, uu, vv)
    through = p[..., 1] <= 0.0
    if through.any():
        # a whole depth under the root cone passes the member axis at the toe of a small
        # pinion (a 5-tooth hypoid at a large offset): those targets are moved up to a
        # twentieth of the root cone's radius in their section (no slot bottom lies
        # through the axis; the other targets are kept as they were)
        rho0 = projection_point(corners, uu, 0.0)[0][..., 1]
        v_floor = (0.05 * rho0 - rho0) / np.where(pv[..., 1] > 0, pv[..., 1], np.inf)
        vv = np.where(through, np.maximum(vv, v_floor), vv)
        p, _ = projection_point(corners, uu, vv)
    seed = (len(u) // 2, int(np.argmin(np.abs(V_TARGETS - 0.5))))
    sol = solve_envelope(blade, settings, p[..., 0], p[..., 1],
                         length_scale=blank.outer_cone_distance,
                         depth=blank.outer_addendum + blank.outer_dedendum, seed_index=seed)
    ok = sol.reason == 0
    s_low = np.where(ok, sol.s, np.inf)
    j0 = np.argmin(s_low, axis=1)
    rows = np.arange(len(u))
    start = np.column_stack([sol.s[rows, j0], sol.theta[rows, j0], sol.q[rows, j0],
                             vv[rows, j0]])
    start[~ok[rows, j0]] = np.nan
    if settings.process != "Generate":
        start[:, 2] = 0.0
        start[~ok[rows, j0]] = np.nan
    return sol, vv, start


def section_march(blade: Blade, settings: MachineSettings, blank: Blank, corners: np.ndarray,
                  u: np.ndarray, start: np.ndarray, mirror: bool, s_end=0.0,
                  steps: int = EDGE_STEPS, sections=None):
    """Fillet points at blade arc lengths from ``start`` down to ``s_end``, per section.

    ``start`` (K, 4): s, θ, q, v of a generated point in each section (NaN where none).
    Newton's method on [z − Z(u, v), ρ − P(u, v), f] = 0 in (θ, q, v) at fixed s (seed
    Eq. 2.7a, 2.8; in Formate q ≡ 0 and f is not used), continued in s from the previous
    step. ``s_end`` [mm] (scalar or (K,)): below 0 the march goes on along the blade's tip
    (``sections`` from :func:`tip_sections`). Returns (K, steps) arrays s, v, φ, with NaN
    after a step that fails, and (K, 3) θ, q, v of each section's last point.
    """
    gen = settings.process == "Generate"
    length = blank.outer_cone_distance
    # the blade's sections and the machine chain's folded factors made once for the
    # march's 2 x steps x Newton evaluations of the family (each made them again: ~7 % of
    # a face-milled development's synthesis, in the tip planes' root lines; the same
    # arrays, so the same numbers)
    sections = profile_sections(blade) if sections is None else sections
    links = chain(settings)
    k = len(u)
    s_out = np.full((k, steps), np.nan)
    v_out, phi_out = s_out.copy(), s_out.copy()
    alive = np.all(np.isfinite(start), axis=1)
    x = np.where(alive[:, None], start[:, 1:], 0.0)
    s0 = np.where(alive, start[:, 0], 0.0)
    s_end = np.broadcast_to(np.asarray(s_end, dtype=float), s0.shape)
    m = 3 if gen else 2
    for j in range(steps):
        s = s0 + (s_end - s0) * ((j + 1) / steps)
        idx = np.flatnonzero(alive)
        if idx.size == 0:
            break
        xi = x[idx].copy()
        ok = np.zeros(idx.size, bool)
        r_at = None  # the family's points at xi where the last evaluation was there
        for _ in range(NEWTON_ITER):
            r_at = None
            th, q, v = xi.T
            # the family's buffer kept for the meshing function (meshing_function would
            # stack the views of it back into one)
            buf = generated_buffer(blade, settings, s[idx], th,
                                   q if gen else np.zeros_like(q), sections=sections,
                                   links=links)
            fam = family_views(buf, (idx.size,))
            r = fam.r
            rho = np.hypot(r[:, 0], r[:, 1])
            p, pv = projection_point(corners, u[idx], v)
            rows = [np.stack([r[:, 2] - p[..., 0], rho - p[..., 1]], -1)]
            drho = [(r[:, 0] * d[:, 0] + r[:, 1] * d[:, 1]) / rho
                    for d in (fam.r_theta, fam.r_q)]
            jac = np.zeros((idx.size, m, m))
            jac[:, 0, 0], jac[:, 1, 0] = fam.r_theta[:, 2], drho[0]
            jac[:, 0, m - 1], jac[:, 1, m - 1] = -pv[..., 0], -pv[..., 1]
            if gen:
                f, g = meshing_buffer(buf, length)
                g = g.T
                rows.append(f[:, None])
                jac[:, 0, 1], jac[:, 1, 1] = fam.r_q[:, 2], drho[1]
                jac[:, 2, 0], jac[:, 2, 1] = g[:, 1], g[:, 2]
            res = np.concatenate(rows, axis=1)
            err = np.abs(res[:, :2]).max(axis=1)
            if gen:
                err = np.maximum(err, length * np.abs(res[:, 2]))
            ok = err < NEWTON_TOL
            r_at = r
            if ok.all():
                break
            try:
                dx = np.linalg.solve(jac, -res[..., None])[..., 0]
            except np.linalg.LinAlgError:
                break
            r_at = None
            lim = STEP_LIMIT[[0, 1, 2] if gen else [0, 2]]
            fac = np.minimum(1.0, np.min(lim / np.maximum(np.abs(dx), 1e-300), axis=1))
            step = fac[:, None] * dx
            if gen:
                xi += step
            else:
                xi[:, 0] += step[:, 0]
                xi[:, 2] += step[:, 1]
        good = ok & np.isfinite(xi).all(axis=1)
        alive[idx[~good]] = False
        gi = idx[good]
        x[gi] = xi[good]
        if r_at is None:
            r_at = generated_family(blade, settings, s[gi], x[gi, 0],
                                    x[gi, 1] if gen else np.zeros(gi.size),
                                    sections=sections, links=links).r
        else:  # the last Newton evaluation was at these points: the same numbers
            r_at = r_at[good]
        pos = r_at * (MIRROR if mirror else 1.0)
        s_out[gi, j], v_out[gi, j] = s[gi], x[gi, 2]
        phi_out[gi, j] = np.arctan2(pos[:, 1], pos[:, 0])
    return s_out, v_out, phi_out, np.where(alive[:, None], x, np.nan)



def tip_sections(blade: Blade) -> ProfileSections:
    """The blade's :func:`profile_sections` with its flat tip below s = 0: the tip line
    (h = 0, continuing the edge radius's tangent at s = 0 across the slot), so that the
    same generation (seed Eq. 2.7a, 2.8) gives the slot bottom the tip cuts."""
    sec = profile_sections(blade)

    def cat(a, x):
        return np.r_[x, a]

    return sec._replace(
        s_lo=cat(sec.s_lo, -np.inf), s_hi=cat(sec.s_hi, 0.0), s_ref=cat(sec.s_ref, 0.0),
        rho_ref=cat(sec.rho_ref, sec.rho_ref[0]), h_ref=cat(sec.h_ref, 0.0),
        psi_ref=cat(sec.psi_ref, sec.psi_ref[0]), kappa=cat(sec.kappa, 0.0),
        corner_above=cat(sec.corner_above, False), main=sec.main + 1,
        names=("tip", *sec.names))


def root_line_points(blade: Blade, settings: MachineSettings, blank: Blank, hand: str,
                     u, start: np.ndarray | None = None, *, at_tip: np.ndarray | None = None,
                     solution: bool = False):
    """(K, 2) v [1], φ [rad] of a cut's root line in the sections ``u`` (K,) [1].

    The generated points of the blade's s = 0 point, where its edge radius leaves the tip
    plane (module docstring); φ of the member as cut (a left-hand member mirrored), not
    turned to a reference tooth; NaN where the fillet march does not reach s = 0.

    ``start`` (K, 4), optional: the fillet march's start s, θ, q, v in each section
    (:func:`section_envelope`'s third result), e.g. those of a nearby cut of the same blade
    with its tip plane moved (:func:`geometry.synthesis.tip_plane.tip_plane_on_root_cone`
    reuses them over its iterations); the march solves each of its points to the Newton
    tolerance from there, so the points are the same as from this cut's own starts
    (solved by default) wherever the march reaches s = 0.

    ``at_tip`` (K, 3), optional: θ [rad], q [rad], v [1] near each section's root-line
    point, e.g. a nearby cut's root line (``solution``) or its neighbours' interpolated:
    instead of the march, Newton's method at s = 0 alone from there (one step of
    :func:`section_march` instead of :data:`EDGE_STEPS`; issue 75). The same points to
    the Newton tolerance where it converges; NaN where not (the caller marches).
    ``start`` is not used then.

    ``solution``: return also (K, 3) θ, q, v of each root-line point (NaN where none).
    """
    u = np.atleast_1d(np.asarray(u, dtype=float))
    corners = blank_outline(blank).corners
    if at_tip is not None:
        start = np.column_stack([np.zeros(u.size), np.asarray(at_tip, dtype=float)])
        steps = 1
    else:
        if start is None:
            _, _, start = section_envelope(blade, settings, blank, u)
        steps = EDGE_STEPS
    sm, vm, pm, last = section_march(blade, settings, blank, corners, u, start,
                                     hand == "left", steps=steps)
    at0 = np.isfinite(sm[:, -1]) & (np.abs(sm[:, -1]) < 1e-12)
    points = np.column_stack([np.where(at0, vm[:, -1], np.nan),
                              np.where(at0, pm[:, -1], np.nan)])
    if solution:
        return points, np.where(at0[:, None], last, np.nan)
    return points


def below_root_cone(blank_or_corners, u, v) -> np.ndarray:
    """Distance [mm] of projection-plane points (u, v) below the blank's root cone,
    perpendicular to its generatrix (negative: above it).

    ``blank_or_corners``: a :class:`geometry.case.Blank` or its outline's corners
    (2, 2, 2) [mm]; ``u``, ``v`` [1] broadcast together."""
    corners = (blank_outline(blank_or_corners).corners if isinstance(blank_or_corners, Blank)
               else np.asarray(blank_or_corners, dtype=float))
    root = corners[1, 0] - corners[0, 0]
    normal = np.array([root[1], -root[0]]) / np.hypot(*root)
    normal *= np.copysign(1.0, float(normal @ (corners[0, 1] - corners[0, 0])))
    pts, _ = projection_point(corners, u, v)
    return -(pts - corners[0, 0]) @ normal
