"""Real surfaces: measured (CMM) and local (wear) deviations update ease-off and Q (seed §4.3).

The seed (§4.3, Eq. 4.3–4.10) does not regenerate the deviated flanks and repeat the tooth
contact search: it updates the theoretical ease-off ε and surface of roll angle Q of
:func:`contact.utca.easeoff.ease_off` directly from the normal deviations of the two flanks,
assuming the deviated and theoretical surfaces share their normals (Eq. 4.3).

Sign convention
---------------
A deviation δ [mm] is measured along the member's **outward** unit normal (out of the
material): **positive = material added**. The seed takes inward normals (Eq. 4.3: r* = r +
δ n with n inward, i.e. positive = material removed); our δ is the negative of the seed's.

Equations (our reading of the garbled Eq. 4.5–4.10)
---------------------------------------------------
With L u·n = a·((r − O) × n) (Eq. 4.4–4.5b,c: L is the distance to the axis, u the unit
circumferential direction a × r / |a × r|), the rotation of a member that moves its flank
by δ along its normal is δ / |a·((r − O) × n)| (Eq. 4.5a). For a gear node with real gear
point r_g (normal arm ρ|n_g·e_θ|, :attr:`EaseOff.normal_arm`) and pinion mate r_p:

* gear deviation δ_g (Eq. 4.8): added material closes the gap, the gear needs less lag:
  Δε_g = −δ_g / (ρ |n_g·e_θ|); Q is unchanged to first order;
* pinion deviation δ_p (Eq. 4.5–4.7): the deviated pinion equals, locally, the theoretical
  one turned by δ_p / arm_p in the driving sense (arm_p = |a_p·((r_p − O_p) × n_p)|), so it
  reaches the node earlier: ΔQ = −δ_p / arm_p (Eq. 4.5a, 4.6), and the gear turned with it
  by ΔQ / R closes the gap: Δε_p = ΔQ / R (Eq. 4.7, here as an angle about the gear axis).
  By the equation of meshing (Eq. 2.19) R·arm_p equals the gear's moment arm of the common
  normal at the contact, so Δε_p ≈ −δ_p / (ρ|n·e_θ|) (the brief's form; not used: the real
  gear normal differs from the contact normal by the ease-off slope);
* ε* = ε + Δε_g + Δε_p (Eq. 4.9–4.10) and Q* = Q + ΔQ (Eq. 4.6), both shifted again to touch
  zero over the valid nodes (§4.3 text); the normal ease-off is rebuilt from ε* exactly as in
  :func:`contact.utca.easeoff.ease_off`.

The seed writes the ease-off as a length (Δε = L_g Δq); the toolkit's angular ease-off
is the same quantity divided by the gear's moment arm.

Public functions
----------------
SurfaceDeviation            normal deviations of one flank on a (u, v) grid, interpolated (TPS)
weighted_average_deviation  the seed's baseline interpolation (inverse-distance, Shepard)
apply_deviations            update an EaseOff for pinion and gear deviations (Eq. 4.3–4.10)

Deviation files (CSV, netCDF) are read and written by :mod:`contact.utca.deviation_files`.

References
----------
M. Kolivand, PhD dissertation, Ohio State University, 2009 (the seed), §4.3, Eq. 4.3–4.10.
V. Kin, "Tooth contact analysis based on inspection", Proc. 3rd World Congress on Gearing
and Power Transmissions, Paris, 1992 (seed ref. [4.3]).
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
from scipy.interpolate import RBFInterpolator

from contact.utca.easeoff import EaseOff, normal_ease_off
from geometry.core.errors import InputError
from geometry.core.validation import integer, positive, real_array
from geometry.machine.flank import flank_at

if TYPE_CHECKING:
    from geometry.case import Case

__all__ = [
    "DEFAULT_MEASUREMENT_GRID",
    "MAX_DEVIATION",
    "SurfaceDeviation",
    "apply_deviations",
    "weighted_average_deviation",
]

log = logging.getLogger(__name__)

#: default measurement grid: 9 lengthwise (toe → heel) × 5 profile (root → tip) points over
#: the flank's projection-plane fractions (the limits of
#: :data:`geometry.machine.flank.DEFAULT_GRID`)
DEFAULT_MEASUREMENT_GRID = {"nu": 9, "nv": 5, "u_limits": (0.0, 1.0), "v_limits": (0.05, 1.0)}

#: [mm] largest accepted |δ|: the update is first order in δ (seed Eq. 4.3 assumes the real
#: and theoretical normals equal)
MAX_DEVIATION = 0.5

_FRACTION_RANGE = (-0.5, 1.5)  # accepted grid fractions (a little beyond the blank)


def _as_grid(name: str, values) -> np.ndarray:
    """A measurement grid's fractions (≥ 3, strictly increasing, within the fraction range)."""
    lo, hi = _FRACTION_RANGE
    a = real_array(name, values, unit="1", low=lo, high=hi, ndim=1)
    if a.size < 3:
        raise InputError(f"{name}: must have at least 3 fractions, got {a.size}")
    if np.any(np.diff(a) <= 0):
        raise InputError(f"{name}: must be strictly increasing, got {a!r}")
    return a


@dataclass(frozen=True)
class SurfaceDeviation:
    """Normal deviations of one member's flank on a projection-plane measurement grid.

    Parameters
    ----------
    u : array_like (nu,) — [1]
        Lengthwise fractions of the member's projection plane, toe 0 → heel 1, strictly
        increasing, ≥ 3 values in [−0.5, 1.5] (the fractions of
        :func:`geometry.machine.flank.projection_grid`).
    v : array_like (nv,) — [1]
        Profile fractions, root 0 → tip 1, as ``u``.
    deviation : array_like (nu, nv) — [mm]
        Deviation δ along the outward normal: **positive = material added**; finite,
        |δ| ≤ :data:`MAX_DEVIATION`.

    Raises
    ------
    InputError
        Naming the field: wrong grid shape, non-monotonic or non-finite grid, NaN or too
        large deviation.

    Notes
    -----
    Call the object with fractions (u, v) to interpolate: a thin-plate-spline radial basis
    function with a degree-1 polynomial (:class:`scipy.interpolate.RBFInterpolator`, no
    smoothing), which passes through the measured values. Outside the measured grid (e.g.
    the flank edges beyond the inset CMM grid) it extrapolates smoothly, tending to the
    least-squares plane of the data far away; extrapolated values are only as good as that
    trend. Source: seed §4.3 (deviations δ_ij on the grid, Eq. 4.3).
    """

    u: np.ndarray
    v: np.ndarray
    deviation: np.ndarray
    _rbf: RBFInterpolator = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        u = _as_grid("u", self.u)
        v = _as_grid("v", self.v)
        # |δ| ≤ MAX_DEVIATION: the update is first order in δ
        d = real_array("deviation", self.deviation, unit="mm", low=-MAX_DEVIATION,
                       high=MAX_DEVIATION)
        if d.shape != (u.size, v.size):
            raise InputError(f"deviation: must have shape (len(u), len(v)) = ({u.size}, "
                             f"{v.size}), got {d.shape}")
        uu, vv = np.meshgrid(u, v, indexing="ij")
        pts = np.stack([uu.ravel(), vv.ravel()], -1)
        rbf = RBFInterpolator(pts, d.ravel(), kernel="thin_plate_spline", degree=1)
        for name, val in (("u", u), ("v", v), ("deviation", d), ("_rbf", rbf)):
            object.__setattr__(self, name, val)

    def __call__(self, u, v) -> np.ndarray:
        """Deviation at fractions (u, v).

        Parameters
        ----------
        u, v : array_like, broadcastable — [1]
            Projection-plane fractions (NaN allowed: NaN out).

        Returns
        -------
        ndarray — [mm]
            δ (positive = material added), shape of the broadcast inputs.
        """
        uu, vv = np.broadcast_arrays(np.asarray(u, dtype=float), np.asarray(v, dtype=float))
        out = np.full(uu.shape, np.nan)
        ok = np.isfinite(uu) & np.isfinite(vv)
        if ok.any():
            out[ok] = self._rbf(np.stack([uu[ok], vv[ok]], -1))
        return out

    @classmethod
    def from_function(cls, func: Callable[[np.ndarray, np.ndarray], np.ndarray], *,
                      nu: int = DEFAULT_MEASUREMENT_GRID["nu"],
                      nv: int = DEFAULT_MEASUREMENT_GRID["nv"],
                      u_limits: tuple[float, float] = DEFAULT_MEASUREMENT_GRID["u_limits"],
                      v_limits: tuple[float, float] = DEFAULT_MEASUREMENT_GRID["v_limits"],
                      ) -> SurfaceDeviation:
        """Sample a deviation function f(u, v) [mm] on a measurement grid.

        Parameters
        ----------
        func : callable
            f(u, v) → δ [mm] on arrays (nu, nv) of fractions (positive = material added).
        nu, nv : int
            Lengthwise and profile grid points (≥ 3; default 9 × 5).
        u_limits, v_limits : (float, float) — [1]
            Grid fractions (default those of :data:`DEFAULT_MEASUREMENT_GRID`).

        Returns
        -------
        SurfaceDeviation

        Raises
        ------
        InputError
            For a bad grid, or a function returning the wrong shape, NaN or too large values.
        """
        nu = integer("nu", nu, low=3)
        nv = integer("nv", nv, low=3)
        u = np.linspace(*u_limits, int(nu))
        v = np.linspace(*v_limits, int(nv))
        uu, vv = np.meshgrid(u, v, indexing="ij")
        d = np.broadcast_to(np.asarray(func(uu, vv), dtype=float), uu.shape)
        return cls(u, v, np.array(d))

    @classmethod
    def zero(cls) -> SurfaceDeviation:
        """The theoretical surface (δ = 0 on the default measurement grid)."""
        return cls.from_function(lambda u, v: np.zeros_like(u))

    def weighted_average(self, u, v, *, power: float = 2.0) -> np.ndarray:
        """The seed's weighted-average interpolation; see :func:`weighted_average_deviation`."""
        return weighted_average_deviation(self, u, v, power=power)


def weighted_average_deviation(deviation: SurfaceDeviation, u, v, *,
                               power: float = 2.0) -> np.ndarray:
    """Inverse-distance weighted average of the measured deviations (Shepard's method).

    The seed's baseline (§4.5.2: "a simple weighted average is used to interpolate (or
    extrapolate) the deviations"); the seed gives no weights, so this is a reconstruction:
    δ(u, v) = Σ wᵢ δᵢ / Σ wᵢ with wᵢ = 1 / dᵢ^power over all grid points, dᵢ the distance
    in the (u, v) fraction plane (D. Shepard, "A two-dimensional interpolation function for
    irregularly-spaced data", Proc. 23rd ACM National Conference, 1968, Eq. 1 with
    μ = power). It passes through the data and is bounded by their range (a convex
    combination), but has flat spots at the nodes (zero gradient for power > 1) and tends
    to the data mean away from the grid, so it cannot extrapolate a trend to the flank
    edges. :class:`SurfaceDeviation` itself interpolates with a thin-plate spline; this
    function is kept for comparison (tests/test_deviations.py).

    Parameters
    ----------
    deviation : SurfaceDeviation
        The measured grid.
    u, v : array_like, broadcastable — [1]
        Projection-plane fractions (NaN allowed: NaN out).
    power : float
        Distance exponent μ > 0 (default 2).

    Returns
    -------
    ndarray — [mm]
        δ at (u, v), positive = material added, shape of the broadcast inputs.

    Raises
    ------
    InputError
        ``deviation`` not a SurfaceDeviation, or ``power`` not a finite number > 0.
    """
    if not isinstance(deviation, SurfaceDeviation):
        raise InputError(f"deviation: must be a SurfaceDeviation, got "
                         f"{type(deviation).__name__}")
    power = positive("power", power)
    uu, vv = np.broadcast_arrays(np.asarray(u, dtype=float), np.asarray(v, dtype=float))
    gu, gv = np.meshgrid(deviation.u, deviation.v, indexing="ij")
    gu, gv, gd = gu.ravel(), gv.ravel(), deviation.deviation.ravel()
    out = np.full(uu.shape, np.nan)
    ok = np.isfinite(uu) & np.isfinite(vv)
    pu, pv = uu[ok], vv[ok]
    dist = np.hypot(pu[:, None] - gu[None, :], pv[:, None] - gv[None, :])
    hit = dist == 0.0
    with np.errstate(divide="ignore"):
        w = np.where(hit, 0.0, dist ** -float(power))
    val = (w @ gd) / w.sum(axis=1)
    on_node = hit.any(axis=1)
    val[on_node] = gd[np.argmax(hit[on_node], axis=1)]
    out[ok] = val
    return out


def _pinion_arm(eo: EaseOff, case: Case | None) -> np.ndarray:
    """Moment arm |a_p·((r_p − O_p) × n_p)| [mm] of the pinion mate of every gear node."""
    if case is None:
        raise InputError("case: must be the case of the ease-off when pinion deviations are "
                         "given (pinion moment arms at the mates), got None")
    have = np.isfinite(eo.pinion_axial) & np.isfinite(eo.pinion_radius)
    arm = np.full(eo.pinion_axial.shape, np.nan)
    if have.any():
        fs = flank_at(case, "pinion", eo.pinion_flank, eo.pinion_axial[have],
                      eo.pinion_radius[have])
        p, n = fs.position, fs.normal
        # pinion frame: axis +z through the crossing point at the origin (geometry.pair.assembly)
        arm[have] = np.abs(p[..., 0] * n[..., 1] - p[..., 1] * n[..., 0])
    return arm


def apply_deviations(eo: EaseOff, pinion: SurfaceDeviation | None = None,
                     gear: SurfaceDeviation | None = None, *,
                     case: Case | None = None) -> EaseOff:
    """Ease-off and surface of roll angle of deviated flanks (seed Eq. 4.3–4.10).

    Parameters
    ----------
    eo : contact.utca.easeoff.EaseOff
        The theoretical ease-off (from :func:`contact.utca.easeoff.ease_off`).
    pinion : SurfaceDeviation, optional
        Deviations of the pinion flank ``eo.pinion_flank`` in pinion projection-plane
        fractions [mm], positive = material added; evaluated at the mates
        (``eo.pinion_u``, ``eo.pinion_v``) of the gear nodes.
    gear : SurfaceDeviation, optional
        Deviations of the gear flank ``eo.gear_flank`` in gear fractions [mm], evaluated at
        the nodes (``eo.u``, ``eo.v``).
    case : geometry.case.Case, optional
        The case of ``eo``; required with ``pinion``: the pinion moment arm
        |a_p·((r_p − O_p) × n_p)| [mm] is evaluated on the real pinion
        (:func:`geometry.machine.flank.flank_at` at the mates). (The shortcut normal_arm / R of the
        equation of meshing was tried and rejected: it is off by 0.6–3 % of ΔQ because the
        real-gear normal differs from the contact normal by the ease-off slope.)

    Returns
    -------
    EaseOff
        ``ease_off_angle`` ε* [rad], ``ease_off`` [mm] (rebuilt from ε*), ``roll_angle``
        Q* [rad] and their ``raw_*`` fields updated and shifted to touch zero over the valid
        nodes; ``roll_zero`` and ``gear_phase`` [rad] moved by the same shifts (in the
        senses of :func:`contact.utca.easeoff.ease_off`); all other fields unchanged (the mask,
        normal arm, gap curvature and the mates are those of the theoretical surfaces).

    Raises
    ------
    InputError
        If ``eo`` is not an EaseOff, ``pinion``/``gear`` not a SurfaceDeviation, ``case``
        missing with ``pinion``, or the deviations leave no finite value on the valid nodes.

    Notes
    -----
    Seed §4.3 (module docstring): Δε = −δ_g/(ρ|n_g·e_θ|) + ΔQ/R with ΔQ = −δ_p/arm_p
    (Eq. 4.5a, 4.6–4.9; ε* = ε + Δε, Eq. 4.10). Reconstructed from the garbled extraction:
    the sign convention (the seed's normals point inward, ours outward), the angular form
    of Eq. 4.7–4.8 (the seed multiplies by L_g to get a length), the product L u·n written
    as the moment a·((r − O) × n) of Eq. 4.5b,c, and the re-shift of both surfaces.
    First order in δ: the normals of the real and theoretical surfaces are taken equal
    (Eq. 4.3 text) and the mates are not moved.
    """
    if not isinstance(eo, EaseOff):
        raise InputError(f"eo: must be a contact.utca.easeoff.EaseOff, got {type(eo).__name__}")
    for name, dev in (("pinion", pinion), ("gear", gear)):
        if dev is not None and not isinstance(dev, SurfaceDeviation):
            raise InputError(f"{name}: must be a SurfaceDeviation or None, got "
                             f"{type(dev).__name__}")
    eps = np.array(eo.raw_ease_off_angle, dtype=float)
    q = np.array(eo.raw_roll_angle, dtype=float)
    d_eps = np.zeros(eps.shape)
    d_q = np.zeros(q.shape)
    if gear is not None:
        uu, vv = np.meshgrid(eo.u, eo.v, indexing="ij")
        d_eps -= gear(uu, vv) / eo.normal_arm  # Eq. 4.8
    if pinion is not None:
        have = np.isfinite(eo.pinion_u) & np.isfinite(eo.pinion_v)
        dp = np.zeros(q.shape)
        dp[have] = pinion(eo.pinion_u[have], eo.pinion_v[have])
        d_q = np.where(have, -dp / _pinion_arm(eo, case), np.nan)  # Eq. 4.5a, 4.6
        d_eps += d_q / eo.ratio  # Eq. 4.7
    eps = eps + d_eps  # Eq. 4.9-4.10
    q = q + d_q
    valid = eo.valid & np.isfinite(eps) & np.isfinite(q)
    if not valid.any():
        raise InputError("pinion, gear: must leave a finite ease-off on a valid node, got "
                         "none")
    s_e = float(np.min(eps[valid]))
    s_q = float(np.min(q[valid]))
    eps = eps - s_e
    q = q - s_q
    # normal ease-off as in contact.utca.easeoff.ease_off (chord of the rotation)
    pg, ng = eo.gear_position, eo.gear_normal
    rho = np.hypot(pg[..., 0], pg[..., 1])
    nt = (ng[..., 1] * pg[..., 0] - ng[..., 0] * pg[..., 1]) / rho
    nr = (ng[..., 0] * pg[..., 0] + ng[..., 1] * pg[..., 1]) / rho
    normal = normal_ease_off(eps, eo.lag_sense, rho, nt, nr)
    v0 = eo.valid
    log.info("apply_deviations: ease-off re-shifted by %.4g urad, Q by %.4g urad",
             s_e * 1e6, s_q * 1e6)
    return eo._replace(
        ease_off=np.where(v0, normal, np.nan),
        ease_off_angle=np.where(v0, eps, np.nan),
        roll_angle=np.where(v0, q, np.nan),
        raw_ease_off_angle=eps, raw_roll_angle=q,
        roll_zero=float(eo.roll_zero + eo.drive_sense * s_q),
        gear_phase=float(eo.gear_phase + eo.lag_sense * s_e),
    )

