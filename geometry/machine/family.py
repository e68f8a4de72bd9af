"""The family of cutter surfaces in the blank frame and the meshing function (seed Eq. 2.7–2.8).

The cutter surface r_t(s, θ) carried through the machine's kinematic chain
(:func:`geometry.machine.cradle.machine_transform`) gives the family r_g(s, θ, q) in the
blank frame; this module evaluates it with all first and second derivatives in s, θ and q
(batched, component-major buffers for speed) and the normalised meshing function of seed
Eq. 2.8, (∂r/∂s × ∂r/∂θ)·∂r/∂q = 0, with its gradient. Face hobbing adds the cutter's spin
tied to the work's indexing (seed Eq. 2.1): the swept surface's normal.

Public functions
----------------
GeneratedFamily     r_g and its derivatives, shape (..., 3)
Chain, chain        the constant factors of the machine chain, folded for 3-vectors
generated_family    r_g(s, θ, q) and all first and second derivatives in the blank frame
meshing_function    seed Eq. 2.8, normalised, and its gradient
dot                 the dot product of the last axis (cross: geometry.core.vectors)
cutter_buffer, family_buffer, family_views, meshing_buffer   the batched kernels
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from geometry.core.errors import InputError
from geometry.machine.cradle import (
    MachineSettings,
    rot,
    taylor_coefficients,
    trans,
)
from geometry.machine.cutter import (
    Blade,
    ProfileSections,
    blade_edge,
    blade_profile,
    profile_sections,
    revolution_normal,
)

__all__ = [
    "GeneratedFamily",
    "generated_family",
    "meshing_function",
]

class GeneratedFamily(NamedTuple):
    """The family of cutter surfaces in the blank frame, r_g(s, θ, q), with derivatives.

    All vectors on the last axis [mm, or mm per unit of the differentiating parameters].
    ``normal`` is the unit normal out of the work material of the surface r_g(·, ·, q) at
    fixed q (face milling: the cutter surface's; face hobbing: ±r_s × r_θ normalised).
    """

    r: np.ndarray
    r_s: np.ndarray
    r_theta: np.ndarray
    r_q: np.ndarray
    r_ss: np.ndarray
    r_stheta: np.ndarray
    r_thetatheta: np.ndarray
    r_sq: np.ndarray
    r_thetaq: np.ndarray
    r_qq: np.ndarray
    normal: np.ndarray


class Chain(NamedTuple):
    """Constant factors of the chain of :func:`machine_transform`, folded for 3-vectors.

    With A = R_z(q_c + q) = cos a·I_c + sin a·S + I_z (I_c = diag(1, 1, 0), S = dR_z/dα at
    α = 0, I_z = diag(0, 0, 1)), the part T(0,0,−X_p) R_y(γ_m − π/2) T(0,−E_m,X_b) A
    T(S_r,0,0) R_z(j) R_x(i) of the chain is cos a·K₁ + sin a·K₂ + K₃ (+ the q-dependent
    part of T(0,−E_m,X_b) with helical or vertical motion) with constant 3 × 4 blocks K_k,
    the last column acting on points only.
    """

    k_lin: np.ndarray  # (9, 3): K₁, K₂, K₃ linear parts stacked (rows)
    k_point: np.ndarray  # (9, 1): their translation columns
    r2_y: np.ndarray  # (3,) R_y(γ_m − π/2) e_y: direction of −E_m
    r2_z: np.ndarray  # (3,) R_y(γ_m − π/2) e_z: direction of X_b
    motion: bool  # helical or vertical motion: T(0,−E_m,X_b) depends on q
    #: the polynomial coefficients (:func:`geometry.machine.cradle.taylor_motion`'s, read
    #: only) of the vertical motion E_m(q), the helical motion X_b(q) and the modified roll
    #: φ(q)/R_a, each None where the settings give it no derivatives
    taylor: tuple = (None, None, None)


def chain(settings: MachineSettings) -> Chain:
    """Fold the constant factors of the machine chain (see :class:`Chain`)."""
    c5 = (trans([settings.radial_setting, 0.0, 0.0]) @ rot("z", settings.swivel)
          @ rot("x", settings.tilt))[:3]
    r2 = rot("y", settings.machine_root_angle - 0.5 * math.pi)[:3, :3]
    k1 = r2[:, :2] @ c5[:2]  # R_2 I_c c5
    k2 = np.outer(r2[:, 1], c5[0]) - np.outer(r2[:, 0], c5[1])  # R_2 S c5
    k3 = np.outer(r2[:, 2], c5[2])  # R_2 I_z c5
    motion = bool(any(settings.helical_motion) or any(settings.vertical_motion))
    k3[2, 3] -= settings.machine_center_to_back
    if not motion:
        k3[:, 3] += -settings.blank_offset * r2[:, 1] + settings.sliding_base * r2[:, 2]
    k = np.concatenate([k1, k2, k3])  # (9, 4)

    def taylor(value0, derivatives):
        if not any(derivatives):
            return None
        return taylor_coefficients(float(value0), tuple(float(d) for d in derivatives))

    roll = (1.0, *(-c for c in settings.modified_roll))
    return Chain(np.ascontiguousarray(k[:, :3]), k[:, 3:].copy(), r2[:, 1].copy(),
                  r2[:, 2].copy(), motion,
                  (taylor(settings.blank_offset, settings.vertical_motion),
                   taylor(settings.sliding_base, settings.helical_motion),
                   taylor(0.0, roll) if any(settings.modified_roll) else None))


#: order of the vectors in a family buffer (:func:`family_buffer`)
_FIELDS = ("r", "r_s", "r_theta", "r_ss", "r_stheta", "r_thetatheta", "normal", "r_q", "r_sq",
           "r_thetaq", "r_qq")


_XZ = np.array([0, 1, 3, 6])  # cutter vectors in the blade's axial plane: r, r_s, r_ss, normal


def cutter_buffer(blade: Blade, sections: ProfileSections, s: np.ndarray, theta: np.ndarray,
                   section) -> np.ndarray:
    """The vectors of :func:`geometry.machine.cutter.cutter_surface`, component-major (3, 7, n).

    Order of the first seven :data:`_FIELDS`; the same expressions (seed Eq. 2.6a–c: blade
    vectors in the blade's axial plane turned by θ about the cutter axis), written straight
    into one array.
    """
    if blade.placed:
        return _placed_cutter_buffer(blade, sections, s, theta, section)
    p = blade_profile(sections, s, section)
    c, sn = np.cos(theta), np.sin(theta)
    sg = blade.sigma
    v = np.empty((3, 7, s.size))
    # (np.array of the rows: np.stack's array without its wrapper)
    bx = np.array([p.rho, p.drho, p.d2rho, -sg * p.dh])
    v[0, _XZ] = bx * c
    v[1, _XZ] = bx * sn
    v[2, _XZ] = np.array([-p.h, -p.dh, -p.d2h, -sg * p.drho])
    v[0, 2] = -p.rho * sn
    v[1, 2] = p.rho * c
    v[0, 4] = -p.drho * sn
    v[1, 4] = p.drho * c
    v[0, 5] = -v[0, 0]
    v[1, 5] = -v[1, 0]
    v[2, 2] = v[2, 4] = v[2, 5] = 0.0
    return v


def _placed_cutter_buffer(blade: Blade, sections: ProfileSections, s: np.ndarray,
                          theta: np.ndarray, section) -> np.ndarray:
    """:func:`cutter_buffer` of a placed (face-hobbing) blade: the edge of
    :func:`geometry.machine.cutter.blade_edge` turned by θ, r_θ = S r, r_θθ = S² r, r_sθ = S r_s."""
    e, e_s, e_ss = (a.T for a in blade_edge(blade, s, section, sections))
    n_rev = revolution_normal(blade, e.T, e_s.T).T
    c, sn = np.cos(theta), np.sin(theta)
    v = np.empty((3, 7, s.size))
    for k, w in ((0, e), (1, e_s), (3, e_ss), (6, n_rev)):
        v[0, k] = c * w[0] - sn * w[1]
        v[1, k] = sn * w[0] + c * w[1]
        v[2, k] = w[2]
    for k, src in ((2, 0), (4, 1)):  # S v = (−v_y, v_x, 0)
        v[0, k] = -v[1, src]
        v[1, k] = v[0, src]
        v[2, k] = 0.0
    v[0, 5] = -v[0, 0]
    v[1, 5] = -v[1, 0]
    v[2, 5] = 0.0
    return v


def family_buffer(chain: Chain, settings: MachineSettings, v: np.ndarray,
                   q: np.ndarray, theta: np.ndarray | None = None) -> np.ndarray:
    """The eleven vectors of :func:`generated_family`, component-major: (3, 11, q.size).

    ``v`` holds the cutter vectors at the points (:func:`cutter_buffer`, (3, 7, n)); the
    result the vectors in the order of :data:`_FIELDS`. The chain is applied to all seven
    cutter vectors at once: one product with the folded constant factors (:class:`Chain`),
    the cradle rotation as cos a·K₁v + sin a·K₂v + K₃v and its q-derivatives (K₂ and −K₁
    are the derivatives of K₁ and K₂), then the work rotation R_z(−φ) differentiated by
    the product rule, with dR_z(−φ)/dq = −φ' S R_z(−φ).

    Face hobbing (κ = ``settings.indexing_ratio`` ≠ 0; ``theta`` (n,) the cutter spin
    [rad], required then): the work rotation gains κθ, φ = φ_roll(q) + κθ, applied in
    Formate too, and the θ-derivatives the indexing terms (``docs/machine.md``):
    r_θ = R(c_θ − κ S c), r_sθ = R(c_sθ − κ S c_s), r_θθ = R(c_θθ − 2κ S c_θ + κ² S² c),
    r_θq = R(y_θq − κ S y_q) with y_q = c_q − φ_roll′ S c the pre-rotation r_q. The normal
    is then that of the swept surface, the oriented unit r_s × r_θ (:func:`_swept_normal`),
    not the head's surface of revolution's.
    """
    n = q.size
    generate = settings.process == "Generate"
    q = q.reshape(n) if generate else np.zeros(n)
    # component-major layout (3, vector, n): long contiguous inner loops over the points
    pk = (chain.k_lin @ v.reshape(3, 7 * n)).reshape(9, 7, n)
    pk[:, 0] += chain.k_point
    p1, p2, p3 = pk.reshape(3, 3, 7, n)
    a = settings.cradle_angle + q
    ca, sa = np.cos(a), np.sin(a)
    # y: the seven vectors before the work rotation, then the q-derivatives (before the
    # work rotation's own) of r, r_s, r_θ and the second one of r
    y = np.empty((3, 11, n))
    c = y[:, :7]
    np.multiply(p1, ca, out=c)
    c += p2 * sa
    c += p3
    dc = p2[:, :3] * ca - p1[:, :3] * sa
    d2c = -(p1[:, 0] * ca + p2[:, 0] * sa)
    if chain.motion:
        em, dem, d2em = _motion(settings.blank_offset, chain.taylor[0], q)
        xb, dxb, d2xb = _motion(settings.sliding_base, chain.taylor[1], q)
        # (the outer products of np.outer, as broadcast products: the same elements)
        ry, rz = chain.r2_y[:, None], chain.r2_z[:, None]
        c[:, 0] += ry * -em + rz * xb
        dc[:, 0] += ry * -dem + rz * dxb
        d2c += ry * -d2em + rz * d2xb
    kappa = settings.indexing_ratio
    if not generate and kappa == 0.0:
        y[:, 7:10] = dc
        y[:, 10] = d2c
        out = y
    else:
        if not generate:
            phi, d1, d2 = np.zeros(n), 0.0, None
        elif chain.taylor[2] is not None:
            # roll_angle's φ = R_a (q − C q² − …), from the chain's coefficients
            phi, d1, d2 = _taylor_values(chain.taylor[2], q)
            ra = settings.ratio_of_roll
            phi, d1, d2 = ra * phi, ra * d1, ra * d2
        else:
            phi, d1, d2 = settings.ratio_of_roll * q, settings.ratio_of_roll, None
        # S v = (−v_y, v_x, 0): r_q = R_z(−φ)(c' − φ' S c), and r_qq likewise
        y[0, 7:10] = dc[0] + d1 * c[1, :3]
        y[1, 7:10] = dc[1] - d1 * c[0, :3]
        y[2, 7:10] = dc[2]
        y[0, 10] = d2c[0] + 2.0 * d1 * dc[1, 0] - d1 * d1 * c[0, 0]
        y[1, 10] = d2c[1] - 2.0 * d1 * dc[0, 0] - d1 * d1 * c[1, 0]
        y[2, 10] = d2c[2]
        if d2 is not None:
            y[0, 10] += d2 * c[1, 0]
            y[1, 10] -= d2 * c[0, 0]
        if kappa != 0.0:
            if theta is None:
                raise InputError("theta: the cutter spin is needed for a face-hobbing "
                                 "family (indexing_ratio != 0)")
            _index_terms(y, kappa)
            phi = phi + kappa * np.reshape(theta, n)
        cf, sf = np.cos(phi), -np.sin(phi)
        out = np.empty_like(y)
        out[0] = cf * y[0] - sf * y[1]
        out[1] = sf * y[0] + cf * y[1]
        out[2] = y[2]
        if kappa != 0.0:
            _swept_normal(out)
    return out


def _motion(value0: float, coefficients, q: np.ndarray):
    """:func:`geometry.machine.cradle.taylor_motion` from its coefficients (:class:`Chain`),
    but a motion without derivatives (None) as its three constants (floats): the chain's
    outer products then broadcast one column per component, each element the same product
    and sum as with the constant arrays."""
    if coefficients is None:
        return float(value0), 0.0, 0.0
    return _taylor_values(coefficients, q)


def _taylor_values(coef: np.ndarray, q: np.ndarray):
    """f, f′, f″ (n,) at q (n,) of :func:`geometry.machine.cradle.taylor_motion`'s
    coefficients ``coef``: its arithmetic (the increasing Vandermonde matrix of q by
    cumulative products, times the coefficients) without its checks."""
    v = np.empty((q.size, coef.shape[0]))
    v[:, 0] = 1.0
    if coef.shape[0] > 1:
        v[:, 1:] = q[:, None]
        np.multiply.accumulate(v[:, 1:], out=v[:, 1:], axis=1)
    out = v @ coef
    return out[:, 0], out[:, 1], out[:, 2]


def _swept_normal(out: np.ndarray) -> None:
    """Face hobbing: replace the normal of a family buffer by that of the swept surface.

    With indexing the surface r(·, ·, q) swept at a fixed cradle angle is not the head's
    surface of revolution, whose normal (n_rev, :func:`geometry.machine.cutter.revolution_normal`)
    the cutter vectors carry: the two share the edge but differ by a turn about it of the
    order of the lead angle ν. Its unit normal is ±(r_s × r_θ)/|r_s × r_θ| (the envelope's
    normal where the equation of meshing holds), turned out of the material by n_rev
    (design note "Face hobbing" §2.9: n_rev only fixes the sign). In place, on (3, 11, n).
    """
    nvec = _cross0(out[:, 1], out[:, 2])
    with np.errstate(divide="ignore", invalid="ignore"):
        scale = np.sign((nvec * out[:, 6]).sum(0)) / np.sqrt((nvec * nvec).sum(0))
    out[:, 6] = nvec * scale


def _index_terms(y: np.ndarray, kappa: float) -> None:
    """Add the indexing terms of the θ-derivatives to a pre-rotation buffer, in place."""
    def spin(k):  # S y_k = (−y_y, y_x, 0) of vector k, shape (2, n): its x, y components
        return np.stack([-y[1, k], y[0, k]])

    s_c, s_cs, s_ct, s_yq = spin(0), spin(1), spin(2), spin(7)
    # S² c = (−c_x, −c_y, 0)
    y[:2, 5] += -2.0 * kappa * s_ct - kappa * kappa * y[:2, 0]
    y[:2, 2] -= kappa * s_c
    y[:2, 4] -= kappa * s_cs
    y[:2, 9] -= kappa * s_yq


def family_views(buf: np.ndarray, shape: tuple) -> GeneratedFamily:
    """A :class:`GeneratedFamily` of views into a family buffer, arrays shape + (3,)."""
    out = buf.reshape(3, 11, *shape)
    out = out.transpose(*range(1, out.ndim), 0)
    return GeneratedFamily(**{name: out[k] for k, name in enumerate(_FIELDS)})


def generated_family(blade: Blade, settings: MachineSettings, s, theta, q, section=None,
                     sections: ProfileSections | None = None,
                     links: Chain | None = None) -> GeneratedFamily:
    """Cutter surface carried into the blank frame at roll q, with analytic derivatives.

    Parameters
    ----------
    blade : Blade
    settings : MachineSettings
    s : array_like — [mm]
        Arc length along the blade edge.
    theta : array_like — [rad]
        Blade angle about the cutter axis.
    q : array_like — [rad]
        Cradle rotation (broadcast with s and θ; ignored for Formate).
    section, sections
        See :func:`geometry.machine.cutter.cutter_surface`.
    links : Chain, optional
        :func:`chain` of ``settings``, made once by a caller that evaluates the family of
        one cut many times (a march, a Newton loop): the same folded factors as made here
        by default, so the same numbers.

    Returns
    -------
    GeneratedFamily
        r_g [mm] and its derivatives with respect to s [mm], θ [rad] and q [rad] up to second
        order, and the unit normal out of the work material; arrays shape broadcast + (3,)
        (views into one array holding all eleven vectors).

    Notes
    -----
    Seed Eq. 2.7a (family of surfaces) differentiated analytically: r_g = M(q) r_t(s, θ),
    so ∂r_g/∂s = M ∂r_t/∂s, ∂r_g/∂q = M'(q) r_t, ∂²r_g/∂q² = M''(q) r_t, etc. The chain of
    :func:`machine_transform` is applied to 3-vectors with its constant factors folded
    (same result to round-off, tested; several times faster than forming the batched 4×4
    products).
    """
    s, theta, q = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (s, theta, q)))
    return family_views(generated_buffer(blade, settings, s, theta, q, section, sections,
                                         links), q.shape)


def generated_buffer(blade: Blade, settings: MachineSettings, s: np.ndarray,
                     theta: np.ndarray, q: np.ndarray, section=None,
                     sections: ProfileSections | None = None,
                     links: Chain | None = None) -> np.ndarray:
    """:func:`generated_family`'s buffer (3, 11, n) (:func:`family_buffer`) of ``s``,
    ``theta``, ``q``, float arrays of one shape (n points): for a caller that also wants
    :func:`meshing_buffer` of it without :func:`meshing_function` stacking the family's
    views back into such a buffer (the same numbers). Parameters as
    :func:`generated_family`'s."""
    sections = profile_sections(blade) if sections is None else sections
    if section is not None:
        section = np.broadcast_to(np.asarray(section, dtype=int), q.shape).ravel()
    v = cutter_buffer(blade, sections, s.ravel(), theta.ravel(), section)
    return family_buffer(chain(settings) if links is None else links, settings, v, q,
                         theta.ravel())


def dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Dot product over the last axis of two broadcastable arrays (..., 3)."""
    return (a * b).sum(axis=-1)


def meshing_function(family: GeneratedFamily, length_scale: float):
    """Equation of meshing (seed Eq. 2.8), normalised, and its gradient in (s, θ, q).

    Parameters
    ----------
    family : GeneratedFamily
    length_scale : float — [mm]
        L, the normalising length (the toolkit uses the member's outer cone distance).

    Returns
    -------
    f : ndarray — [1]
        f = n · (∂r_g/∂q) / L, the normal component of the relative velocity per unit cradle
        rotation divided by L (n the unit normal): zero on the envelope. It is the seed's
        (∂r/∂s × ∂r/∂θ)·∂r/∂q divided by −σ|∂r/∂s × ∂r/∂θ| L.
    grad : ndarray, shape f.shape + (3,)
        ∂f/∂(s, θ, q) [1/mm, 1/rad, 1/rad], analytic (second derivatives of r_g).
    """
    buf = np.stack([np.reshape(getattr(family, name), (-1, 3)).T for name in _FIELDS], 1)
    f, grad = meshing_buffer(buf, length_scale)
    shape = np.shape(family.r)[:-1]
    return f.reshape(shape), grad.T.reshape(*shape, 3)


_MESH_A = np.array([1, 3, 4, 8])  # r_s, r_ss, r_sθ, r_sq (× r_θ)


_MESH_B = np.array([4, 5, 9])  # r_sθ, r_θθ, r_θq (r_s ×)


_MESH_C = np.array([8, 9, 10])  # r_sq, r_θq, r_qq


def meshing_buffer(buf: np.ndarray, length_scale: float):
    """:func:`meshing_function` of a family buffer: f (n,) and its gradient (3, n)."""
    # N = r_s × r_θ and its derivatives dN/d(s, θ, q) = (r_ss, r_sθ, r_sq) × r_θ
    # + r_s × (r_sθ, r_θθ, r_θq), all cross products in two stacked ones
    x1 = _cross0(buf[:, _MESH_A], buf[:, 2:3])
    x2 = _cross0(buf[:, 1:2], buf[:, _MESH_B])
    nvec = x1[:, 0]
    dn = x1[:, 1:] + x2
    r_q = buf[:, 7]
    # (sums over the components by np.add.reduce: ndarray.sum's reduction without its
    # wrapper)
    add = np.add.reduce
    nn = np.sqrt(add(nvec * nvec, 0))
    # orientation: unit normal = sign * nvec / |nvec|
    sign = np.sign(add(nvec * buf[:, 6], 0))
    scale = sign / (nn * length_scale)
    g = add(nvec * r_q, 0)
    dg = add(dn * r_q[:, None], 0) + add(buf[:, _MESH_C] * nvec[:, None], 0)
    dnn = add(nvec[:, None] * dn, 0) / nn  # d|N|
    grad = (dg - g * dnn / nn) * scale
    return g * scale, grad


def _cross0(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Cross product over the first axis (component-major arrays, broadcasting)."""
    # (the broadcast shape of two arrays of equal rank, as np.broadcast_shapes gives it)
    out = np.empty((3, *(x if y == 1 else y for x, y in zip(a.shape[1:], b.shape[1:],
                                                             strict=True))))
    # each component a_i b_j − a_j b_i, written in place (no stack of temporaries)
    for k, (i, j) in enumerate(((1, 2), (2, 0), (0, 1))):
        np.multiply(a[i], b[j], out=out[k])
        out[k] -= a[j] * b[i]
    return out
