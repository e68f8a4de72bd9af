"""Edge contact on the coast flank: moment arms, torque equilibrium and the edge share
(issue 60: a coast LTCA gave pinion-edge segments negative moment arms, hence negative
separations R (lag − UTE), loads pressed into them and an ``edge_load_share`` of −115 %
on the reference design at 100 N·m, −214 % on a spiral bevel at 222.5 N·m).

Independent checks, on the reference design at Table 3.1's misalignments at 500 N·m (one
mesh cycle of 6 rolls: ~2 s a flank with the ease-off computed once), whose coast flank
has pinion-edge contact at that torque and whose drive flank has it too:

- rigid-body statics from the stored contact points and normals alone, independent of the
  stored moment arms: every loaded segment's moment (p − o) × n · a about the gear axis
  has one sign on a flank (the sense of the gear torque: opposite on coast and drive), its
  magnitude is the stored arm to 1e-2 mm (the arms are the splines' normal arm, within
  7e-3 mm of the arm of each stored point and normal: tests/test_plastic_edges.py), and
  Σ F (p − o) × n · a = ±T_g at every roll to 1e-5 (the same spline error, averaged over a
  roll's segments);
- the shares: each kind of segment (curve, gear tip/heel/toe, pinion edge) carries a share
  Σ_kind F R / T_g in [0, 1], the shares sum to 1, and ``edge_load_share`` is the edges'
  Σ F |(p − o) × n · a| over all rolls divided by n_rolls T_g (to 1e-5, the statics' error);
- the effective mesh point of the mesh interface reproduces the forces' own moment about
  the gear axis beside the load centre (on coast it was put beyond the gear axis).
"""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

from contact.catalogue import resolve_case
from contact.ltca import LTCAOptions, loaded_tca
from contact.ltca.mesh_interface import effective_mesh
from contact.ltca.summary import edge_load_share
from contact.utca.easeoff import ease_off

OPTS = LTCAOptions(cycles=1, rolls_per_cycle=6)
TORQUE = 500.0  # [N·m] pinion: both flanks have pinion-edge contact at it


@cache
def _run(flank: str):
    case = resolve_case(None)  # the reference design at Table 3.1's misalignments
    eo = ease_off(case, flank=flank)
    return loaded_tca(case, [TORQUE], flank=flank, options=OPTS, easeoff=eo)


def _statics(ds):
    """(F, arm from points and normals (roll, pair, segment), loaded mask)."""
    F = ds["force"].isel(torque=0).fillna(0.0).values
    p, n = ds["contact_point"].values, ds["contact_normal"].values
    a = np.asarray(ds.attrs["gear_axis"])
    o = np.asarray(ds.attrs["gear_origin_mm"])
    return F, np.nan_to_num(np.einsum("...i,i->...", np.cross(p - o, n), a)), F > 0


@pytest.mark.parametrize("flank", ["coast", "drive"])
def test_loaded_segments_balance_the_gear_torque_with_positive_arms(flank):
    ds = _run(flank)
    kind = ds["segment_kind"].values
    F, R_pn, loaded = _statics(ds)
    assert np.any(loaded[..., kind == "pinion_edge"])  # the case of the defect is exercised
    R = ds["moment_arm"].values
    # the stored arms are positive on every loaded segment, edges included
    assert np.all(R[loaded] > 0)
    # one sense of the moment over all loaded segments: the flank's torque sense
    sense = np.sign(R_pn[loaded])
    assert np.all(sense == sense[0])
    sense = sense[0]
    assert sense == (-1.0 if flank == "coast" else 1.0)  # the gear torque reverses on coast
    assert np.max(np.abs(sense * R_pn - R)[loaded]) < 1e-2
    gear_torque = float(ds["gear_torque"][0]) * 1e3  # [N·mm]
    np.testing.assert_allclose((F * sense * R_pn).sum((-2, -1)) / gear_torque, 1.0,
                               rtol=0, atol=1e-5)


@pytest.mark.parametrize("flank", ["coast", "drive"])
def test_edge_load_share_is_the_edges_fraction_of_the_torque(flank):
    ds = _run(flank)
    kind = ds["segment_kind"].values
    F, R_pn, _ = _statics(ds)
    gear_torque = float(ds["gear_torque"][0]) * 1e3
    rolls = F.shape[0]
    M = F * np.nan_to_num(ds["moment_arm"].values)
    shares = {k: M[..., kind == k].sum() / (rolls * gear_torque) for k in np.unique(kind)}
    for k, s in shares.items():
        assert 0.0 <= s <= 1.0, (k, s)
    assert sum(shares.values()) == pytest.approx(1.0, abs=1e-9)
    edge = kind != "curve"
    expected = np.abs(F * R_pn)[..., edge].sum() / (rolls * gear_torque)
    share = float(edge_load_share(ds)[0])
    assert 0.0 < share < 1.0
    assert share == pytest.approx(expected, abs=1e-5)
    assert share == pytest.approx(1.0 - shares["curve"], abs=1e-9)


@pytest.mark.parametrize("flank", ["coast", "drive"])
def test_mesh_point_reproduces_the_torque_beside_the_load_centre(flank):
    """The effective mesh point (contact.ltca.mesh_interface.effective_mesh) on the line of
    action nearest the load centre that reproduces the gear torque: the force W l at it
    has the forces' own moment about the stored gear axis (Σ F (p − o) × n · a, negative
    on coast: independent of the stored arms) to 1e-5 (the arms' spline error, as above),
    W λ_g = T_g to 1e-9 and the point lies within 1 mm of the load centre (the face width
    is ~30 mm; measured ≤ 0.15 mm on both flanks; 165 mm on coast, beyond the gear axis,
    when the point was placed for +T_g about a_g)."""
    ds = _run(flank)
    F, R_pn, _ = _statics(ds)
    J = F.shape[0]
    a = np.asarray(ds.attrs["gear_axis"])
    o = np.asarray(ds.attrs["gear_origin_mm"])
    e = effective_mesh(F.reshape(J, -1), ds["contact_point"].values.reshape(J, -1, 3),
                       ds["contact_normal"].values.reshape(J, -1, 3),
                       ds["moment_arm"].values.reshape(J, -1), a, o)
    gear_torque = float(ds["gear_torque"][0]) * 1e3
    moment = (F * R_pn).sum((-2, -1))
    about_axis = e["mesh_force"] * (np.cross(e["mesh_point"] - o, e["line_of_action"]) @ a)
    np.testing.assert_allclose(about_axis / moment, 1.0, rtol=0, atol=1e-5)
    np.testing.assert_allclose(e["mesh_force"] * e["gear_rotation_radius"] / gear_torque,
                               1.0, rtol=0, atol=1e-9)
    shift = np.linalg.norm(e["mesh_point"] - e["load_centre"], axis=-1)
    assert shift.max() < 1.0, shift
