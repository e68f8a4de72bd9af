"""Tests of contact.deviations (seed §4.3, Eq. 4.3–4.10).

Independent checks: exact identities (zero deviation; rigid rotations of either member about
its own axis only shift ε and Q by constants, which the re-shift removes), the closed form
of the interpolant (a thin-plate spline with a degree-1 polynomial reproduces a plane), and
a full regeneration: the deviation produced by a small change of a gear machine setting,
measured on the two real flanks, must give the ease-off and UTE of the modified case.
"""

from __future__ import annotations

import dataclasses as dc
from pathlib import Path

import numpy as np
import pytest

from contact.deviations import SurfaceDeviation, apply_deviations, read_deviation_csv
from contact.easeoff import ease_off
from contact.utca import pair_transmission_error, unloaded_tca
from geometry.case import load_case
from geometry.errors import InputError
from geometry.flank import blank_outline, flank_at

CASE = Path(__file__).resolve().parents[1] / "cases" / "kolivand2009_fm_11x41.toml"


@pytest.fixture(scope="module")
def case():
    return load_case(CASE)


@pytest.fixture(scope="module")
def eo(case):
    return ease_off(case)


def _rotz(p, angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([c * p[..., 0] - s * p[..., 1], s * p[..., 0] + c * p[..., 1], p[..., 2]],
                    -1)


def _rigid_deviation(pos, nrm, angle):
    """Normal component of the displacement of a flank turned about its own axis (+z)."""
    return np.einsum("...i,...i", _rotz(pos, angle) - pos, nrm)


def _node_grid(eo, values):
    return SurfaceDeviation(eo.u, eo.v, values)


# --------------------------------------------------------------------- identities
def test_zero_deviation_reproduces_easeoff(case, eo):
    out = apply_deviations(eo, pinion=SurfaceDeviation.zero(), gear=SurfaceDeviation.zero(),
                           case=case)
    v = eo.valid
    # angles and Q: δ = 0 adds exact zeros and the minimum over the valid nodes is already
    # exactly 0, so the arrays must be identical
    np.testing.assert_array_equal(out.ease_off_angle, eo.ease_off_angle)
    np.testing.assert_array_equal(out.roll_angle, eo.roll_angle)
    # the normal ease-off is rebuilt with the same formula but a different summation order
    # of n·e_θ: round-off only (1e-15 mm ≪ 1 nm)
    np.testing.assert_allclose(out.ease_off[v], eo.ease_off[v], rtol=0, atol=1e-15)
    assert out.roll_zero == eo.roll_zero and out.gear_phase == eo.gear_phase
    np.testing.assert_array_equal(out.reason, eo.reason)
    same = apply_deviations(eo)
    np.testing.assert_array_equal(same.ease_off_angle, eo.ease_off_angle)


def test_rigid_gear_rotation_only_shifts(case, eo):
    dphi = 1e-5  # [rad] small: the chord's second-order part ρΔ²/2 ≈ 5e-9 mm → 1e-10 rad
    # the gear turned by s_g·Δ about its axis (makes it lag): its flank moves out of the
    # material by δ, measured from the turned flank points (independent of normal_arm)
    delta = _rigid_deviation(eo.gear_position, eo.gear_normal, eo.lag_sense * dphi)
    delta = np.where(np.isfinite(delta), delta, 0.0)
    assert np.all(delta[eo.valid] > 0)  # the rotation adds material everywhere
    out = apply_deviations(eo, gear=_node_grid(eo, delta), case=case)
    v = eo.valid
    # ease-off shape unchanged after the re-shift (1e-9 rad = the brief's tolerance; the
    # linearisation error is ~1e-10 rad, see dphi)
    np.testing.assert_allclose(out.ease_off_angle[v], eo.ease_off_angle[v], rtol=0, atol=1e-9)
    np.testing.assert_array_equal(out.roll_angle, eo.roll_angle)  # gear deviation: Q fixed
    # the re-shift is the rotation itself: the gear needs Δ less lag everywhere, so the
    # kinematic gear phase moves by −s_g Δ (1e-9 rad as above)
    assert out.gear_phase - eo.gear_phase == pytest.approx(-eo.lag_sense * dphi, abs=1e-9)
    # the UTE envelope of the UTCA is unchanged (1e-3 urad = 1e-9 rad as above)
    _, d0 = unloaded_tca(case, easeoff=eo)
    _, d1 = unloaded_tca(case, easeoff=out)
    np.testing.assert_allclose(d1["roll"].values, d0["roll"].values, rtol=0, atol=1e-7)
    np.testing.assert_allclose(d1.unloaded_transmission_error.values,
                               d0.unloaded_transmission_error.values, rtol=0, atol=1e-3)


def _pinion_rotation_deviation(case, eo, dphi):
    """δ_p(u, v) of the pinion turned by s_p·Δ, on a 41 × 21 grid of pinion fractions."""
    corners = blank_outline(case.pinion.blank).corners

    def f(u, v):
        p = ((1 - u) * (1 - v))[..., None] * corners[0, 0] + (u * (1 - v))[..., None] * \
            corners[1, 0] + ((1 - u) * v)[..., None] * corners[0, 1] + (u * v)[..., None] * \
            corners[1, 1]
        fs = flank_at(case, "pinion", eo.pinion_flank, p[..., 0], p[..., 1])
        return _rigid_deviation(fs.position, fs.normal, eo.drive_sense * dphi)

    return SurfaceDeviation.from_function(f, nu=41, nv=21, u_limits=(0.0, 1.0),
                                          v_limits=(0.2, 1.0))


def test_rigid_pinion_rotation_only_shifts(case, eo):
    dphi = 1e-5  # [rad]
    dev = _pinion_rotation_deviation(case, eo, dphi)
    out = apply_deviations(eo, pinion=dev, case=case)
    v = eo.valid
    # the pinion turned by Δ in the driving sense reaches every node Δ earlier: Q shifts by
    # a constant, removed by the re-shift. Tolerance 5e-9 rad = 5e-4 Δ: the chord error is
    # ~1e-10 rad and the thin-plate interpolation of δ_p has a relative error ~1e-4 (measured
    # 2.3e-8 of 2.4e-4 mm), largest where the mates (v ≈ 0.17) lie below the grid's first
    # row v = 0.2, which must stay above the kink of δ_p at the pinion's fillet junction
    np.testing.assert_allclose(out.roll_angle[v], eo.roll_angle[v], rtol=0, atol=5e-9)
    # the gear turned with it by Δ/R: ε shifts by a constant as well (same tolerance, ≥ R×)
    np.testing.assert_allclose(out.ease_off_angle[v], eo.ease_off_angle[v], rtol=0,
                               atol=5e-9)
    assert out.roll_zero - eo.roll_zero == pytest.approx(-eo.drive_sense * dphi, abs=5e-9)
    with pytest.raises(InputError, match="case"):
        apply_deviations(eo, pinion=dev)  # the pinion arms need the real pinion


# --------------------------------------------------------------------- regeneration check
def _modified(case, kind, name, step):
    tool = case.gear.convex
    part = getattr(tool, kind)
    tool = dc.replace(tool, **{kind: dc.replace(part, **{name: getattr(part, name) + step})})
    return dc.replace(case, gear=dc.replace(case.gear, convex=tool))


@pytest.mark.parametrize("kind, name", [("machine", "radial_setting"),
                                        ("blade", "point_radius")])
def test_machine_setting_change_matches_regenerated_easeoff(case, eo, kind, name):
    assert eo.gear_flank == "convex"
    mod = _modified(case, kind, name, 0.01)  # +0.01 mm
    eo_mod = ease_off(mod)
    # the deviation the change produces, on the same projection-plane places of the nodes
    f0 = flank_at(case, "gear", eo.gear_flank, eo.axial, eo.radius)
    f1 = flank_at(mod, "gear", eo.gear_flank, eo.axial, eo.radius)
    delta = np.einsum("...i,...i", f1.position - f0.position, f0.normal)
    assert np.all(np.isfinite(delta))
    out = apply_deviations(eo, gear=_node_grid(eo, delta), case=case)
    both = eo.valid & eo_mod.valid
    assert both.sum() > 0.9 * eo.valid.sum()
    change = np.abs(eo_mod.ease_off - eo.ease_off)[both].max()
    assert change > 1e-3  # the change itself is > 1 µm: the check is not vacuous
    # brief: 0.5 µm of normal ease-off (first-order update; measured ~0.02 µm)
    np.testing.assert_allclose(out.ease_off[both], eo_mod.ease_off[both], rtol=0, atol=5e-4)
    # UTE of the reference pair on a fixed roll grid and the envelope's peak-to-peak:
    # 0.5 µrad (brief; measured ~0.01 µrad)
    roll = np.linspace(0.2, 1.2, 41)
    u_mod = pair_transmission_error(eo_mod, roll)
    u_out = pair_transmission_error(out, roll)
    np.testing.assert_array_equal(np.isfinite(u_out), np.isfinite(u_mod))
    np.testing.assert_allclose(u_out, u_mod, rtol=0, atol=5e-7)
    _, d_mod = unloaded_tca(mod, easeoff=eo_mod)
    _, d_out = unloaded_tca(case, easeoff=out)
    assert float(d_out.peak_to_peak_transmission_error) == pytest.approx(
        float(d_mod.peak_to_peak_transmission_error), abs=0.5)  # [µrad]


# --------------------------------------------------------------------- interpolation, I/O
def test_plane_is_reproduced_everywhere(tmp_path):
    # a thin-plate spline with a degree-1 polynomial reproduces a plane exactly, inside the
    # grid and extrapolated (closed form; round-off of the 45 × 45 solve: 1e-12 mm)
    def plane(u, v):
        return 0.002 + 0.003 * u - 0.001 * v

    dev = SurfaceDeviation.from_function(plane)
    assert dev.deviation.shape == (9, 5)
    u = np.array([0.0, 0.33, 1.0, -0.1, 1.1])
    v = np.array([0.0, 0.5, 1.0, 0.02, 1.05])
    np.testing.assert_allclose(dev(u, v), plane(u, v), rtol=0, atol=1e-12)
    # CSV (wide format) round trip reproduces the grid exactly (repr of floats)
    path = tmp_path / "dev.csv"
    lines = ["# test grid, mm", "v\\u," + ",".join(repr(float(x)) for x in dev.u)]
    for j, vj in enumerate(dev.v):
        lines.append(repr(float(vj)) + "," + ",".join(repr(float(x)) for x in dev.deviation[:, j]))
    path.write_text("\n".join(lines) + "\n")
    back = read_deviation_csv(path)
    np.testing.assert_array_equal(back.u, dev.u)
    np.testing.assert_array_equal(back.v, dev.v)
    np.testing.assert_array_equal(back.deviation, dev.deviation)


def test_bad_input_names_the_field(tmp_path, eo):
    u, v = np.linspace(0, 1, 9), np.linspace(0.05, 1, 5)
    with pytest.raises(InputError, match="deviation"):
        SurfaceDeviation(u, v, np.zeros((5, 9)))  # transposed grid
    bad = np.zeros((9, 5))
    bad[3, 2] = np.nan
    with pytest.raises(InputError, match="deviation"):
        SurfaceDeviation(u, v, bad)
    with pytest.raises(InputError, match="deviation"):
        SurfaceDeviation(u, v, np.full((9, 5), 1.0))  # 1 mm: not a small deviation
    with pytest.raises(InputError, match="u"):
        SurfaceDeviation(u[::-1], v, np.zeros((9, 5)))
    with pytest.raises(InputError, match="v"):
        SurfaceDeviation(u, v[:2], np.zeros((9, 2)))
    with pytest.raises(InputError, match="nu"):
        SurfaceDeviation.from_function(lambda a, b: a * 0, nu=2)
    with pytest.raises(InputError, match="gear"):
        apply_deviations(eo, gear=np.zeros((9, 5)))
    with pytest.raises(InputError, match="eo"):
        apply_deviations(None)
    path = tmp_path / "bad.csv"
    path.write_text("v\\u,0,0.5,1\n0,0,0\n")
    with pytest.raises(InputError, match="row 2"):
        read_deviation_csv(path)
    path.write_text("v\\u,0,0.5,1\n0,0,x,0\n")
    with pytest.raises(InputError, match="non-numeric"):
        read_deviation_csv(path)
    with pytest.raises(InputError, match="path"):
        read_deviation_csv(tmp_path / "missing.csv")


def test_pipeline_with_deviations_side_by_side(tmp_path):
    # zero deviations reproduce the theoretical results exactly; a wear-like deviation
    # (the bundled example) changes the ease-off by up to the deviations' sum and is
    # written next to the theoretical results; `ltca run --deviations` and `ltca plot`
    from contact.cli import main
    from contact.io import read_netcdf
    from contact.ltca import LTCAOptions
    from contact.pipeline import run_analysis

    root = Path(__file__).resolve().parents[1] / "cases"
    case = load_case(root / "kolivand2009_fm_11x41.toml")
    opts = LTCAOptions(cycles=1, rolls_per_cycle=4, segments=10)
    zero = run_analysis(case, [200.0], options=opts, geometry=False,
                        deviations=(SurfaceDeviation.zero(), SurfaceDeviation.zero()))
    np.testing.assert_array_equal(zero["ltca"]["transmission_error"].values,
                                  zero["theoretical/ltca"]["transmission_error"].values)
    assert float(np.nanmax(np.abs(zero["easeoff"]["ease_off_change"].values))) < 1e-9
    dev = root / "deviations"
    out = tmp_path / "dev.nc"
    assert main(["run", str(root / "kolivand2009_fm_11x41.toml"), "--torque", "200",
                 "--rolls-per-cycle", "4", "--segments", "10", "--speed", "0", "--no-progress",
                 "--deviations", str(dev / "wear_11x41_pinion.csv"),
                 str(dev / "wear_11x41_gear.csv"), "-o", str(out)]) == 0
    tree = read_netcdf(out)
    change = tree["easeoff"]["ease_off_change"].values
    assert 5.0 < float(np.nanmax(change) - np.nanmin(change)) < 15.0 + 1e-6  # um
    assert main(["plot", str(out), "--plots", str(tmp_path / "png")]) == 0
    assert (tmp_path / "png" / "deviations_easeoff_change.png").exists()
