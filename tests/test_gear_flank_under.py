"""The gear flank point under pair-frame points (:func:`contact.ltca.edges.gear_flank_under`,
issue 75 item 4, helper study90: its Gauss–Newton steps' 2 × 2 normal equations solved in
closed form instead of a batched LAPACK solve), and the edge candidates' contact points.

Independent checks, on the default case's ease-off (its real gear flank splines):
- points built off the flank along its normal at known places: the foot found is a
  stationary point of |x(u, v) − p|² (the residual orthogonal to x_u and x_v to 1e-9 of
  |x − p| |x_u|: the Gauss–Newton stop at a step of 1e-13 of the grid leaves ~1e-12), and
  is the place the point was built at (off along the position spline's own normal
  x_u × x_v) to 1e-9 of the grid;
- the same feet as the Gauss–Newton iteration with NumPy's batched LAPACK solve (written
  out here, the function's arithmetic before study90) to 1e-12 of the grid in (u, v) and
  1e-10 mm in position: the closed form differs from LU with pivoting by round-off per step,
  and both stop within one step of 1e-13;
- a degenerate flank place (x_u ∥ x_v) raises numpy's LinAlgError, as the LAPACK solve did;
- ``_edge_contact_points`` (each pinion edge's mate once per boundary segment) gives every
  candidate's points as the formula applied to that candidate alone, bit for bit.
"""

from __future__ import annotations

from functools import cache
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from contact.ltca.discretisation import gear_to_pair
from contact.ltca.edges import _FOOT_STEP, gear_flank_under
from contact.utca import EaseOffFields
from contact.utca.easeoff import ease_off
from geometry.case import load_case
from geometry.pair.assembly import rotate_about_axis

CASES = Path(__file__).resolve().parents[1] / "cases"


@cache
def _setup():
    eo = ease_off(load_case(CASES / "hypoid_iso23509_s2.toml"))
    return eo, EaseOffFields(eo)


def _points(offset: float, n: int = 60, seed: int = 3):
    """Pair-frame points ``offset`` [mm] off the gear flank along its normal, at random
    places inside the grid, each at its own gear rotation ψ; their places (u, v)."""
    eo, f = _setup()
    rng = np.random.default_rng(seed)
    u = rng.uniform(f.u[0] + 0.1 * (f.u[-1] - f.u[0]), f.u[-1] - 0.1 * (f.u[-1] - f.u[0]), n)
    v = rng.uniform(f.v[0] + 0.1 * (f.v[-1] - f.v[0]), f.v[-1] - 0.1 * (f.v[-1] - f.v[0]), n)
    # along the position spline's own normal x_u × x_v: the foot is then (u, v) itself
    nrm = np.cross(f.values(("pos",), u, v, dx=1), f.values(("pos",), u, v, dy=1))
    nrm /= np.linalg.norm(nrm, axis=-1, keepdims=True)
    gear_pts = f.values(("pos",), u, v) + offset * nrm
    psi = eo.gear_phase + rng.uniform(-0.2, 0.2, n)
    return psi, gear_to_pair(eo.kinematics, psi, gear_pts), u, v


def _lapack_feet(f, kin, psi, points, u, v, iterations: int = 8):
    """The Gauss–Newton feet with NumPy's batched LAPACK solve of JᵀJ Δ = Jᵀr (the
    function's arithmetic before study90), for comparison."""
    p = rotate_about_axis(kin.gear_axis, -psi, points - kin.gear_origin) \
        @ kin.gear_place[:3, :3]
    lo, hi = np.array([f.u[0], f.v[0]]), np.array([f.u[-1], f.v[-1]])
    uv = np.stack([u, v], axis=-1)
    act = np.arange(uv.shape[0])
    for _ in range(iterations):
        if act.size == 0:
            break
        ua, va = uv[act, 0], uv[act, 1]
        x = f.values(("pos",), ua, va)
        jac = np.stack([f.values(("pos",), ua, va, dx=1),
                        f.values(("pos",), ua, va, dy=1)], axis=-1)
        jtj = np.einsum("nia,nib->nab", jac, jac)
        jtr = np.einsum("nia,ni->na", jac, p[act] - x)
        new = np.clip(uv[act] + np.linalg.solve(jtj, jtr[..., None])[..., 0], lo, hi)
        step = np.abs(new - uv[act]).max(axis=-1)
        uv[act] = new
        act = act[step > _FOOT_STEP]
    return uv[:, 0], uv[:, 1], f.values(("pos",), uv[:, 0], uv[:, 1])


@pytest.mark.parametrize("offset", [0.0, 0.02, -0.05])
def test_foot_is_stationary_and_at_the_building_place(offset):
    eo, f = _setup()
    psi, pts, u0, v0 = _points(offset)
    rng = np.random.default_rng(5)
    du = 0.02 * (f.u[-1] - f.u[0]) * rng.uniform(-1, 1, u0.size)  # starts a little off
    dv = 0.02 * (f.v[-1] - f.v[0]) * rng.uniform(-1, 1, v0.size)
    u, v, pos, nrm = gear_flank_under(f, eo.kinematics, psi, pts, u0 + du, v0 + dv)
    kin = eo.kinematics
    p = rotate_about_axis(kin.gear_axis, -psi, pts - kin.gear_origin) @ kin.gear_place[:3, :3]
    r = p - pos
    xu = f.values(("pos",), u, v, dx=1)
    xv = f.values(("pos",), u, v, dy=1)
    scale = np.maximum(np.linalg.norm(r, axis=-1), 1e-3)  # (offset 0: |r| ~ 0)
    assert np.all(np.abs(np.sum(r * xu, -1)) <= 1e-9 * scale * np.linalg.norm(xu, axis=-1))
    assert np.all(np.abs(np.sum(r * xv, -1)) <= 1e-9 * scale * np.linalg.norm(xv, axis=-1))
    # the place it was built at (the stop at a step of 1e-13 of the grid, the steps
    # shrinking linearly at a rate below 1/2 here: ≤ 1e-12 left; 1e-9 with a margin)
    assert np.max(np.abs(u - u0)) <= 1e-9 * (f.u[-1] - f.u[0])
    assert np.max(np.abs(v - v0)) <= 1e-9 * (f.v[-1] - f.v[0])
    np.testing.assert_allclose(np.linalg.norm(nrm, axis=-1), 1.0, rtol=0, atol=1e-14)


def test_same_feet_as_the_lapack_iteration():
    eo, f = _setup()
    psi, pts, u0, v0 = _points(0.03, n=200, seed=11)
    start_u, start_v = u0 + 0.01 * (f.u[-1] - f.u[0]), v0 - 0.01 * (f.v[-1] - f.v[0])
    u, v, pos, _ = gear_flank_under(f, eo.kinematics, psi, pts, start_u.copy(),
                                    start_v.copy())
    ur, vr, pos_r = _lapack_feet(f, eo.kinematics, psi, pts, start_u.copy(), start_v.copy())
    assert np.max(np.abs(u - ur)) <= 1e-12 * (f.u[-1] - f.u[0])
    assert np.max(np.abs(v - vr)) <= 1e-12 * (f.v[-1] - f.v[0])
    assert np.max(np.abs(pos - pos_r)) <= 1e-10  # [mm]


def test_degenerate_place_raises_as_lapack_did():
    # a flank whose v-derivative is parallel to its u-derivative: JᵀJ singular
    class Flat:
        u = np.array([0.0, 1.0])
        v = np.array([0.0, 1.0])

        def values(self, names, u, v, dx=0, dy=0):
            u = np.asarray(u, dtype=float)
            out = np.zeros((u.size, 3 * len(names)))
            if dx or dy:
                out[:, 0] = 1.0  # x_u = x_v = e_x
            else:
                out[:, 0] = u + np.asarray(v, dtype=float)
                if "nrm" in names:
                    out[:, 5] = 1.0
            return out

    kin = SimpleNamespace(gear_axis=np.array([0.0, 0.0, 1.0]), gear_origin=np.zeros(3),
                          gear_place=np.eye(4))
    with pytest.raises(np.linalg.LinAlgError):
        gear_flank_under(Flat(), kin, np.zeros(2), np.array([[0.5, 0.1, 0.0]] * 2),
                         np.array([0.3, 0.4]), np.array([0.3, 0.4]))


def test_edge_contact_points_as_each_candidate_alone():
    """``_edge_contact_points`` (each gear edge turned alone, each distinct pinion-edge
    mate once, study90) gives, for every candidate, the points of the formula applied to
    that candidate alone — the boundary point in the pair frame at the candidate's roll (a
    gear edge), or its mate at Q turned on with the pinion by s_p (q − Q) (a pinion
    edge) — bit for bit: the same element-wise arithmetic."""
    from contact.ltca.edges import _edge_contact_points, flank_boundary

    eo, f = _setup()
    bd = flank_boundary(f, 0.25)
    kin = eo.kinematics
    rng = np.random.default_rng(7)
    ee = rng.integers(0, bd.kind.size, 400)
    ee[200:] = ee[:200]  # candidates repeat their boundary segments
    q = rng.uniform(-0.5, 0.5, ee.size) * eo.pitch
    assert np.any(bd.gear_edge[ee]) and not np.all(bd.gear_edge[ee])
    pts, phi, psi, g = _edge_contact_points(eo, bd, q, ee)
    for i in range(ee.size):
        e = ee[i:i + 1]
        phi_i = eo.roll_zero + eo.drive_sense * q[i:i + 1]
        psi_i = eo.gear_phase - phi_i / eo.ratio
        if bd.gear_edge[e[0]]:
            want = gear_to_pair(kin, psi_i[:, None], bd.position[e])
        else:
            q_m = bd.roll_angle[e]
            mate = gear_to_pair(kin, eo.gear_phase - (eo.roll_zero + eo.drive_sense * q_m)
                                / eo.ratio, bd.position[e])
            want = rotate_about_axis(kin.pinion_axis, eo.drive_sense * (q[i] - q_m),
                                     mate - kin.pinion_origin) + kin.pinion_origin
        np.testing.assert_array_equal(pts[i:i + 1], want)
        assert phi[i] == phi_i[0] and psi[i] == psi_i[0]
    np.testing.assert_array_equal(g, bd.gear_edge[ee])
