"""The mesh interface for dynamic models (issue 38, part 4): contact.ltca.mesh_interface.

The three checks the issue names, each against something the reduction does not use:

* equilibrium — the mesh force W along the line of action at the mesh point has the gear
  torque's moment about the gear axis, W λ_g = T_g, to 1e-9 (the issue's bound; the
  contact problem's own equilibrium residual is certified to 1e-7 and is ~1e-15 with the
  exact solver); and, independently, its moment about the *pinion* axis is the pinion
  torque, W |λ_p| = T_p, to 1 % (the contact problem balances the gear only; the pinion
  side holds to the discretised contact lines' conjugacy, 0.2–0.5 % measured);
* stiffness — the condensed tangent stiffness k_Θ / λ_g² agrees with a central finite
  difference of the LTE between T (1 ± 1 %) to 1 % at every roll whose contact set is
  the same at the three torques (a change of the set is a kink of the LTE that a finite
  difference straddles; at the others the median error stays below 1 %); the Weber
  iteration's LTE tolerance, 1e-3 µrad, is 0.03 % of
  the ±2.4 µrad the LTE moves, and the curvature of the LTE–torque curve over ±1 % adds
  O(1e-4): 1 % leaves a wide margin yet catches a secant (Weber's secant compliance is
  ~10 % off the tangent);
* geometry — a pair whose loads sit on one line: the effective point lies on that line.

Cheap enough for CI: one LTCA of the default case at three torques and 8 rolls per mesh
cycle (~10 s), shared by the module's tests; the command test reuses nothing and runs 6
rolls per cycle at one torque.
"""

from __future__ import annotations

import csv

import numpy as np
import pytest

from contact.catalogue import resolve_case
from contact.cli import main
from contact.ltca import LTCAOptions, loaded_tca
from contact.ltca.mesh_interface import (
    MESH_INTERFACE_COLUMNS,
    effective_mesh,
    mesh_interface,
)
from geometry.core.errors import InputError

T0, H = 250.0, 0.01


@pytest.fixture(scope="module")
def three_torques():
    case = resolve_case(None)
    problems: list = []
    ds = loaded_tca(case, [T0 * (1 - H), T0, T0 * (1 + H)],
                    options=LTCAOptions(rolls_per_cycle=8), roll_problems=problems)
    return ds, mesh_interface(ds, problems)


def test_mesh_force_reproduces_the_gear_torque(three_torques):
    ltca, mesh = three_torques
    assert bool(ltca["found"].all())
    gear_torque = ltca["gear_torque"].values[:, None] * 1e3  # [N·mm]
    moment = mesh["mesh_force"].values * mesh["gear_rotation_radius"].values
    assert np.max(np.abs(moment / gear_torque - 1)) < 1e-9
    # the resultant's moment about the pinion axis: the pinion torque, to the conjugacy
    pinion = mesh["mesh_force"].values * np.abs(mesh["pinion_rotation_radius"].values)
    ratio = pinion / (ltca["torque"].values[:, None] * 1e3)
    assert np.max(np.abs(ratio - 1)) < 0.01, ratio
    # the line of action is a unit vector; the mesh point stays near the load centre
    assert np.allclose(np.linalg.norm(mesh["line_of_action"].values, axis=-1), 1.0)
    shift = np.linalg.norm(mesh["mesh_point"].values - mesh["load_centre"].values, axis=-1)
    assert shift.max() < 1.0, shift.max()  # [mm], the tooth's face width is ~30 mm


def test_stiffness_is_the_finite_difference_of_the_lte(three_torques):
    ltca, mesh = three_torques
    te = ltca["transmission_error"].values * 1e-6  # [rad]
    tg = ltca["gear_torque"].values * 1e3  # [N·mm]
    lam = mesh["gear_rotation_radius"].values[1]
    fd = (tg[2] - tg[0]) / (te[2] - te[0]) / lam**2 * 1e-3  # [N/µm]
    k = mesh["mesh_stiffness"].values[1]
    contact = ltca["contact"].values
    same = np.all(contact[0] == contact[1], axis=(1, 2)) & np.all(
        contact[2] == contact[1], axis=(1, 2))
    assert same.sum() >= 4, "too few rolls keep their contact set"
    err = np.abs(k / fd - 1)
    assert err[same].max() < 0.01, err
    # where a segment enters or leaves contact between the torques (mostly edge segments
    # of round-off load) the difference straddles a kink: still close on the whole
    assert np.median(err) < 0.01 and err.max() < 0.05, err
    assert 100 < np.mean(k) < 2000  # [N/µm]: the range of hypoid and bevel meshes


def test_harmonics_reconstruct_the_excitation(three_torques):
    """The stored harmonics with the mean give back the excitation at the 8 samples per
    cycle (an identity of the Fourier series: 3 harmonics resolve the 8 samples up to
    the 4th, so the residual is the 4th harmonic's share; bound from its amplitude)."""
    _, mesh = three_torques
    e = mesh["te_excitation"].values[1]
    phi = mesh["mesh_cycle"].values
    amp = mesh["te_excitation_amplitude"].values[1]
    ph = mesh["te_excitation_phase"].values[1]
    h = mesh["harmonic"].values
    fit = float(mesh["te_excitation_mean"].values[1]) + np.sum(
        amp[:, None] * np.cos(2 * np.pi * h[:, None] * phi[None, :] + ph[:, None]), axis=0)
    resid = e - fit
    # the 4th (Nyquist) harmonic is all that is left: alternating signs of one size
    assert np.allclose(resid, resid[0] * (-1.0) ** np.arange(e.size), atol=1e-9)


def test_loads_on_one_line_give_a_point_on_it():
    """Forces along one line of action (collinear) and forces on one straight contact line
    with a common normal: the effective point lies on the line (and is the load centre)."""
    rng = np.random.default_rng(3)
    axis, origin = np.array([0.0, 0.0, 1.0]), np.zeros(3)
    n = np.array([-0.72, 0.67, 0.16])
    n /= np.linalg.norm(n)
    base = np.array([95.0, 21.0, 32.0])
    force = rng.uniform(10, 500, 12)
    for direction in (n, np.array([0.1, 0.2, 0.97]) / np.linalg.norm([0.1, 0.2, 0.97])):
        pts = base + np.outer(rng.uniform(-8, 8, 12), direction)
        normals = np.tile(n, (12, 1))
        arms = np.cross(pts - origin, normals) @ axis
        e = effective_mesh(force, pts, normals, arms, axis, origin)
        d = e["mesh_point"] - base
        off_line = np.linalg.norm(d - (d @ direction) * direction)
        assert off_line < 1e-9 * np.linalg.norm(base)
        assert np.allclose(e["mesh_point"], e["load_centre"], atol=1e-9)
        assert np.allclose(e["line_of_action"], n)
        assert e["mesh_force"] == pytest.approx(force.sum(), rel=1e-12)


def test_effective_mesh_refuses_bad_shapes():
    with pytest.raises(InputError, match="shapes"):
        effective_mesh(np.ones(3), np.ones((2, 3)), np.ones((3, 3)), np.ones(3),
                       [0, 0, 1], [0, 0, 0])


def test_mesh_interface_command_writes_a_documented_csv(tmp_path):
    out = tmp_path / "mesh.csv"
    assert main(["mesh-interface", "--torque", "200", "--rolls-per-cycle", "6",
                 "--no-progress", "-o", str(out), "--plots", str(tmp_path / "figs")]) == 0
    lines = out.read_text().splitlines()
    comments = [ln for ln in lines if ln.startswith("#")]
    for name, unit, _ in MESH_INTERFACE_COLUMNS:  # every column documented with its unit
        assert any(f"  {name} [{unit}]:" in c for c in comments), name
    rows = list(csv.reader(ln for ln in lines if not ln.startswith("#")))
    assert rows[0] == [f"{n} [{u}]" for n, u, _ in MESH_INTERFACE_COLUMNS]
    values = np.array(rows[1:], float)
    assert values.shape == (12, len(MESH_INTERFACE_COLUMNS))  # 2 cycles × 6 rolls
    assert np.all(np.isfinite(values))
    figure = "kolivand2009_fm_11x41_reference_mesh_interface_T200.png"  # command, torques
    assert (tmp_path / "figs" / figure).stat().st_size > 10_000
