"""Damage of the flanks and the tooth roots over a load spectrum (Miner's rule, local approach).

Stresses from the LTCA, strength from the material: each bin of a duty cycle gives, per
flank point, the peak contact pressure of a tooth mesh (``/ltca/pressure_envelope``, the
envelope over the mesh cycle on the gear's contact grid) and, per fillet point, the peak
tensile fillet stress of a tooth mesh (``/ltca/root_stress`` where the analysis has it).
Every point of a tooth sees one such stress cycle each time its tooth meshes: once per
revolution of its member. Miner's rule sums the bins' n / N(σ)
(:mod:`contact.load_capacity.durability.
sn_curve`); damage grows linearly with the duration of the spectrum, so the life [h] is
the spectrum's duration divided by the largest damage, at the point that has it.

Public functions
----------------
member_cycles        load cycles per tooth point of each member in each bin
cumulative_damage    Σ over bins of n / N(σ) at every point
peak_fillet_stress   the peak tensile fillet stress of a tooth mesh from ``root_stress``
life_at_first_failure  life [h] and the index of the point first reaching damage 1
pressure_envelopes   peak pressure of a tooth mesh on the gear grid, flank and edge apart

References
----------
ISO 6336-6:2019, Calculation of load capacity of spur and helical gears — Part 6:
Calculation of service life under variable load (the damage of a load spectrum by the
Palmgren–Miner rule on the S–N curves of ISO 6336-2 and -3).
A. Palmgren (1924). Die Lebensdauer von Kugellagern. Z. VDI 68, 339–341.
M. A. Miner (1945). Cumulative damage in fatigue. J. Appl. Mech. 12, A159–A164.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from contact.load_capacity.durability.sn_curve import SNCurve
from geometry.core.errors import InputError

__all__ = ["cumulative_damage", "life_at_first_failure", "member_cycles",
           "peak_fillet_stress", "pressure_envelopes"]


def pressure_envelopes(pressure: np.ndarray, seg_u: np.ndarray, seg_v: np.ndarray,
                       edge: np.ndarray, u: np.ndarray, v: np.ndarray
                       ) -> tuple[np.ndarray, np.ndarray]:
    """Peak pressure of a tooth mesh at every gear-grid node, flank and edge contact apart.

    Parameters
    ----------
    pressure : array_like (roll, pair, segment) — [MPa]
        ``/ltca/pressure_max`` of one torque (NaN where unloaded).
    seg_u, seg_v : array_like (roll, pair, segment) — [1]
        ``/ltca/segment_u``, ``segment_v``: the gear-grid fractions of the segments.
    edge : array_like (segment,) of bool
        True for the edge-contact segments (``segment_kind`` not ``"curve"``).
    u, v : array_like (nu,), (nv,) — [1]
        The gear grid (uniform, as the ease-off's).

    Returns
    -------
    flank, edge : ndarray (nu, nv) — [MPa]
        The largest pressure of the contact-curve segments, and of the edge segments,
        landing on each node (nearest node, the rule of ``/ltca/pressure_envelope``, whose
        values are the larger of the two); 0 where none.

    Raises
    ------
    InputError
        Mismatched shapes.
    """
    p = np.asarray(pressure, float)
    su, sv = np.asarray(seg_u, float), np.asarray(seg_v, float)
    e = np.asarray(edge, bool)
    if su.shape != p.shape or sv.shape != p.shape or e.shape != p.shape[-1:]:
        raise InputError(f"pressure: segment fractions {su.shape}, {sv.shape} and edge flags "
                         f"{e.shape} do not match the pressures {p.shape}")
    u, v = np.asarray(u, float), np.asarray(v, float)
    nu, nv = u.size, v.size
    ui = np.rint((su - u[0]) / (u[-1] - u[0]) * (nu - 1))
    vi = np.rint((sv - v[0]) / (v[-1] - v[0]) * (nv - 1))
    good = np.isfinite(ui) & np.isfinite(vi)
    uu = np.clip(np.where(good, ui, 0), 0, nu - 1).astype(int)
    vv = np.clip(np.where(good, vi, 0), 0, nv - 1).astype(int)
    pz = np.nan_to_num(p)
    out = []
    for mask in (good & ~np.broadcast_to(e, p.shape), good & np.broadcast_to(e, p.shape)):
        env = np.zeros((nu, nv))
        np.maximum.at(env, (uu[mask], vv[mask]), pz[mask])
        out.append(env)
    return out[0], out[1]


def member_cycles(pinion_revolutions: np.ndarray, pinion_teeth: int, gear_teeth: int
                  ) -> dict[str, np.ndarray]:
    """Load cycles of one tooth point of each member in each bin.

    Parameters
    ----------
    pinion_revolutions : array_like (NB,) — [1]
        Pinion revolutions of each bin.
    pinion_teeth, gear_teeth : int
        z1, z2.

    Returns
    -------
    dict
        ``{"pinion": (NB,), "gear": (NB,)}`` — [1]: a tooth meshes once per revolution of
        its member, so the pinion's points see the pinion revolutions and the gear's
        z1/z2 of them.

    Raises
    ------
    InputError
        Negative revolutions or tooth numbers below 1.

    Notes
    -----
    The load-cycle count of ISO 6336-2/-3 (N_L) and of a load spectrum's bins in
    ISO 6336-6:2019: a tooth of a member meshing with one mate sees one load cycle per
    revolution of its member, so n_gear = n_pinion z1/z2.
    """
    n = np.asarray(pinion_revolutions, float)
    if not np.all(np.isfinite(n)) or np.any(n < 0):
        raise InputError("pinion_revolutions: must be finite and >= 0")
    if pinion_teeth < 1 or gear_teeth < 1:
        raise InputError("teeth: tooth numbers must be >= 1")
    return {"pinion": n, "gear": n * pinion_teeth / gear_teeth}


def cumulative_damage(stress: np.ndarray, cycles: np.ndarray,
                      curve: SNCurve | Sequence[SNCurve], rule: str = "modified"
                      ) -> np.ndarray:
    """Miner's cumulative damage at every point over the bins.

    Parameters
    ----------
    stress : array_like (NB, ...) — [MPa]
        Peak stress of one load cycle at each point in each bin (0 where unloaded).
    cycles : array_like (NB,) — [1]
        Load cycles of a point in each bin.
    curve : SNCurve or sequence of NB SNCurve
        One curve for every bin, or one per bin (the rating's allowables depend on the
        bin's speed: :meth:`SNCurve.rated`).
    rule : str
        Miner's variant (:data:`contact.load_capacity.durability.sn_curve.MINER_RULES`).

    Returns
    -------
    ndarray (NB, ...) — [1]
        The damage of each bin at each point (their sum over axis 0 is the cycle's).

    Raises
    ------
    InputError
        Mismatched shapes, negative or non-finite stresses or cycles, unknown rule.

    Notes
    -----
    D = Σ_b n_b / N(σ_b), the linear damage accumulation of Palmgren (1924) and Miner
    (1945) as ISO 6336-6:2019 applies it to a load spectrum; N(σ) from the S–N curve of
    ISO 6336-2 (contact) or -3 (bending) below the knee as the chosen variant has it
    (:data:`contact.load_capacity.durability.sn_curve.MINER_RULES`: elementary, modified
    after Haibach 1970, original).
    """
    s = np.asarray(stress, float)
    n = np.asarray(cycles, float)
    if n.ndim != 1 or s.shape[:1] != n.shape:
        raise InputError(f"cycles: one number per bin, got shape {n.shape} for stresses "
                         f"of shape {s.shape}")
    if isinstance(curve, SNCurve):
        return curve.damage(s, n.reshape((-1,) + (1,) * (s.ndim - 1)), rule)
    curves = list(curve)
    if len(curves) != n.size:
        raise InputError(f"curve: one S-N curve per bin, got {len(curves)} for {n.size} bins")
    return np.stack([c.damage(s[b], n[b], rule) for b, c in enumerate(curves)])


def peak_fillet_stress(root_stress: np.ndarray) -> np.ndarray:
    """Peak tensile fillet stress of one tooth mesh at each fillet point.

    Parameters
    ----------
    root_stress : array_like (roll, member, tooth, fillet_point) — [MPa]
        Fillet stress of every tooth in mesh over the mesh cycle (``/ltca/root_stress`` of
        one torque); NaN where not computed.

    Returns
    -------
    ndarray (member, fillet_point) — [MPa]
        The largest tensile (positive) stress over the roll positions and the teeth: one
        cycle per tooth mesh passes from unloaded (0) to it; compressive stresses give 0.

    Raises
    ------
    InputError
        Wrong number of dimensions, or no finite stress at all.

    Notes
    -----
    One load cycle per tooth mesh from 0 to the peak: the one-directional (pulsating)
    tooth-root loading for which ISO 6336-3's bending strength σ_FE and its S–N curve hold
    (the local approach: the stress of the FE model, docs/fe.md, in place of ISO's nominal
    σ_F).
    """
    a = np.asarray(root_stress, float)
    if a.ndim != 4:
        raise InputError(f"root_stress: needs dims (roll, member, tooth, fillet_point), got "
                         f"{a.ndim} dims")
    if not np.any(np.isfinite(a)):
        raise InputError("root_stress: no finite fillet stress")
    return np.clip(np.nanmax(a, axis=(0, 2)), 0.0, None)


def life_at_first_failure(damage: np.ndarray, hours: float) -> tuple[float, tuple[int, ...]]:
    """Life [h] at the point that first reaches damage 1, and that point's index.

    Parameters
    ----------
    damage : array_like (...) — [1]
        Cumulative damage of the whole spectrum at every point.
    hours : float — [h]
        The spectrum's duration, > 0.

    Returns
    -------
    life : float — [h]
        hours / max(damage) (damage is linear in the duration); inf where nothing is
        damaged.
    index : tuple of int
        The index of the point of largest damage.

    Raises
    ------
    InputError
        Non-finite or negative damage, non-positive hours.

    Notes
    -----
    Failure where the accumulated damage reaches D = 1 (Miner 1945); as D grows linearly
    with the number of repetitions of the spectrum, the life is the spectrum's duration
    over the largest damage (ISO 6336-6:2019's service life of a load spectrum).
    """
    d = np.asarray(damage, float)
    if d.size == 0 or not np.all(np.isfinite(d)) or np.any(d < 0):
        raise InputError("damage: must be finite and >= 0 at every point")
    if not hours > 0:
        raise InputError(f"hours: the spectrum's duration must be > 0, got {hours!r}")
    idx = np.unravel_index(int(np.argmax(d)), d.shape)
    top = float(d[idx])
    return (hours / top if top > 0 else float("inf")), tuple(int(i) for i in idx)
