"""Tests of contact.utca.deviations (seed §4.3, Eq. 4.3–4.10).

Independent checks: exact identities (zero deviation; rigid rotations of either member about
its own axis only shift ε and Q by constants, which the re-shift removes), the closed form
of the interpolant (a thin-plate spline with a degree-1 polynomial reproduces a plane), and
a full regeneration: the deviation produced by a small change of a gear machine setting,
measured on the two real flanks, must give the ease-off and UTE of the modified case.
The interpolant is compared with the seed's weighted average (Shepard) on a smooth
measured-like field whose exact values are known everywhere; the netCDF files round-trip
bit for bit (mm) or to round-off (µm).
"""

from __future__ import annotations

import dataclasses as dc
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from contact.utca import pair_transmission_error, unloaded_tca
from contact.utca.deviation_files import (
    SurfaceDeviation,
    apply_deviations,
    read_deviation_csv,
    read_deviation_netcdf,
    read_deviations,
    weighted_average_deviation,
    write_deviation_netcdf,
)
from contact.utca.easeoff import ease_off
from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.machine.flank import blank_outline, flank_at

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
    from contact.ltca import LTCAOptions
    from contact.pipeline import run_analysis
    from geometry.core.io import read_netcdf

    root = Path(__file__).resolve().parents[1] / "cases"
    case = load_case(root / "kolivand2009_fm_11x41.toml")
    opts = LTCAOptions(cycles=1, rolls_per_cycle=4, segments=10)
    zero = run_analysis(case, [200.0], options=opts, geometry=False, root_stress=False,
                        deviations=(SurfaceDeviation.zero(), SurfaceDeviation.zero()))
    # zero deviations: the theoretical run's LTE, to round-off of the two runs (1e-12)
    np.testing.assert_allclose(zero["ltca"]["transmission_error"].values,
                               zero["theoretical/ltca"]["transmission_error"].values,
                               rtol=1e-12, atol=0)
    assert float(np.nanmax(np.abs(zero["easeoff"]["ease_off_change"].values))) < 1e-9
    dev = root / "deviations"
    out = tmp_path / "dev.nc"
    assert main(["run", str(root / "kolivand2009_fm_11x41.toml"), "--torque", "200",
                 "--rolls-per-cycle", "4", "--segments", "10", "--speed", "0", "--no-progress",
                 "--no-root-stress",  # (the deviations are tested: no FE build of these teeth)
                 "--deviations", str(dev / "wear_11x41_pinion.csv"),
                 str(dev / "wear_11x41_gear.csv"), "-o", str(out)]) == 0
    tree = read_netcdf(out)
    change = tree["easeoff"]["ease_off_change"].values
    # the change spans at most the sum of the deepest wear (8.1 + 3.4 µm, the bundled
    # simulated wear of make_wear_case.py) plus the thin-plate splines' overshoot beside
    # it (≤ 10 % of the peaks, see test_active_flank_deviation_leaves_the_root_mates_alone)
    # and the re-shift: asserted < 16.5 µm (measured 11.0)
    assert 5.0 < float(np.nanmax(change) - np.nanmin(change)) < 16.5  # um
    assert main(["plot", str(out), "--plots", str(tmp_path / "png")]) == 0
    # named for the case and the torques (<case>_T<torques>_<figure>.png, issue 56)
    assert list((tmp_path / "png").glob("kolivand2009_fm_11x41_T*_deviations_easeoff_change.png"))


# --------------------------------------------------------------------- netCDF and dispatch
def test_netcdf_round_trip_units_and_dispatch(tmp_path):
    pin = SurfaceDeviation.from_function(lambda u, v: 0.01 * u - 0.02 * v * u)
    gear = SurfaceDeviation.from_function(lambda u, v: -0.005 * v + 0.001, nu=7, nv=4)
    # mm, grids differ → member dims; read back exactly (float64 stored)
    path = write_deviation_netcdf(tmp_path / "dev.nc", pinion=pin, gear=gear)
    for name, dev in (("pinion", pin), ("gear", gear)):
        back = read_deviation_netcdf(path, member=name)
        np.testing.assert_array_equal(back.u, dev.u)
        np.testing.assert_array_equal(back.v, dev.v)
        np.testing.assert_array_equal(back.deviation, dev.deviation)
        # the dispatcher picks the netCDF reader by suffix
        np.testing.assert_array_equal(read_deviations(path, name).deviation, dev.deviation)
    # µm on a shared grid: stored ×1000, read back in mm (one rounding each way: 1e-18 mm)
    path = write_deviation_netcdf(tmp_path / "um.nc", pinion=pin, gear=pin, units="um")
    with xr.open_dataset(path) as ds:
        assert ds["gear_deviation"].dims == ("u", "v")
        assert ds["gear_deviation"].attrs["units"] == "um"
        np.testing.assert_allclose(ds["gear_deviation"].values, 1e3 * pin.deviation,
                                   rtol=1e-15)
    np.testing.assert_allclose(read_deviation_netcdf(path, "gear").deviation, pin.deviation,
                               rtol=0, atol=1e-18)
    # a (v, u) file is transposed on reading
    xr.Dataset({"pinion_deviation": (("v", "u"), pin.deviation.T, {"units": "mm",
                                                                    "long_name": "d"})},
               coords={"u": pin.u, "v": pin.v}).to_netcdf(tmp_path / "vu.nc")
    np.testing.assert_array_equal(read_deviation_netcdf(tmp_path / "vu.nc").deviation,
                                  pin.deviation)
    # the dispatcher reads the bundled CSV like read_deviation_csv
    csv_path = Path(__file__).resolve().parents[1] / "cases/deviations/wear_11x41_gear.csv"
    np.testing.assert_array_equal(read_deviations(csv_path, "gear").deviation,
                                  read_deviation_csv(csv_path).deviation)


def test_netcdf_bad_input_names_the_field(tmp_path):

    dev = SurfaceDeviation.zero()
    path = write_deviation_netcdf(tmp_path / "p.nc", pinion=dev)
    with pytest.raises(InputError, match=r"gear_deviation: no such variable.*pinion_deviation"):
        read_deviation_netcdf(path, member="gear")
    with pytest.raises(InputError, match="member"):
        read_deviations(path, member="wheel")
    with pytest.raises(InputError, match=r"unknown deviation file type '\.txt'.*\.csv"):
        read_deviations(tmp_path / "p.txt")
    with pytest.raises(InputError, match="path"):
        read_deviation_netcdf(tmp_path / "missing.nc")
    with pytest.raises(InputError, match="pinion, gear"):
        write_deviation_netcdf(tmp_path / "none.nc")
    with pytest.raises(InputError, match="units"):
        write_deviation_netcdf(tmp_path / "in.nc", pinion=dev, units="inch")
    xr.Dataset({"pinion_deviation": (("x", "y"), np.zeros((9, 5)), {"units": "mm"})}).to_netcdf(
        tmp_path / "dims.nc")
    with pytest.raises(InputError, match=r"pinion_deviation: must have the dimensions \(u, v\)"):
        read_deviation_netcdf(tmp_path / "dims.nc")
    xr.Dataset({"pinion_deviation": (("u", "v"), np.zeros((9, 5)), {"units": "inch"})},
               coords={"u": dev.u, "v": dev.v}).to_netcdf(tmp_path / "units.nc")
    with pytest.raises(InputError, match="pinion_deviation: units"):
        read_deviation_netcdf(tmp_path / "units.nc")
    xr.Dataset({"pinion_deviation": (("u", "v"), np.zeros((9, 5)), {"units": "mm"})}).to_netcdf(
        tmp_path / "nocoord.nc")
    with pytest.raises(InputError, match="coordinate"):
        read_deviation_netcdf(tmp_path / "nocoord.nc")


# --------------------------------------------------------------------- RBF against Shepard
def _measured_like(u, v):
    """Pressure-angle error (linear in v), spiral-angle error (linear in u), twist (u·v) and
    a quadratic bias [mm] (seed Fig. 4.10 in kind, 50 µm scale)."""
    su, sv = 2 * u - 1, 2 * v - 1
    return 0.025 * sv + 0.015 * su + 0.010 * su * sv + 0.008 * su**2 - 0.004 * sv**2


def test_rbf_beats_the_seed_weighted_average():
    dev = SurfaceDeviation.from_function(_measured_like)  # 9 × 5, v from 0.05
    # dense flank grid, including the extrapolation to the edges (v < 0.05 down to 0)
    uu, vv = np.meshgrid(np.linspace(0, 1, 101), np.linspace(0, 1, 101), indexing="ij")
    truth = _measured_like(uu, vv)
    err_rbf = np.abs(dev(uu, vv) - truth).max()
    err_idw = np.abs(weighted_average_deviation(dev, uu, vv) - truth).max()
    np.testing.assert_array_equal(dev.weighted_average(uu, vv),
                                  weighted_average_deviation(dev, uu, vv))
    # measured: thin-plate spline 0.75 µm, Shepard (power 2) 14.8 µm, ratio 19.7; asserted
    # with margin: RBF below 1.5 µm and at least 10× better
    assert err_rbf < 1.5e-3
    assert err_idw > 10 * err_rbf
    # both interpolate: the measured values at the 45 nodes (RBF: round-off of the solve,
    # 1e-12 mm; Shepard returns the node value exactly)
    gu, gv = np.meshgrid(dev.u, dev.v, indexing="ij")
    np.testing.assert_allclose(dev(gu, gv), dev.deviation, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(weighted_average_deviation(dev, gu, gv), dev.deviation)
    # Shepard's is a convex combination: bounded by the data range everywhere, even far
    # outside the grid (1e-15 mm: round-off of the normalised weights)
    far = np.linspace(-0.5, 1.5, 81)
    s = weighted_average_deviation(dev, far[:, None], far[None, :])
    assert s.min() >= dev.deviation.min() - 1e-15
    assert s.max() <= dev.deviation.max() + 1e-15
    assert np.isnan(weighted_average_deviation(dev, np.nan, 0.5))
    with pytest.raises(InputError, match="power"):
        weighted_average_deviation(dev, 0.5, 0.5, power=0)
    with pytest.raises(InputError, match="deviation"):
        weighted_average_deviation(np.zeros((9, 5)), 0.5, 0.5)


def test_active_flank_deviation_leaves_the_root_mates_alone(case, eo):
    # a pinion hollow (10 µm) tapered to exactly zero at and below the profile row
    # v = 0.2875 of the 9 × 5 grid (zero rows v = 0.05 and 0.2875)
    def hollow(u, v):
        t = np.clip((v - 0.2875) / 0.2, 0.0, 1.0)
        return -0.010 * np.exp(-(((u - 0.5) / 0.22) ** 2 + ((v - 0.6) / 0.25) ** 2)) * (
            t * t * (3 - 2 * t))

    dev = SurfaceDeviation.from_function(hollow)
    assert np.all(dev.deviation[:, :2] == 0.0)
    out = apply_deviations(eo, pinion=dev, case=case)
    # undo the re-shifts (recorded in gear_phase and roll_zero), leaving the raw changes
    s_e = (out.gear_phase - eo.gear_phase) * eo.lag_sense
    s_q = (out.roll_zero - eo.roll_zero) * eo.drive_sense
    d_eps = out.ease_off_angle + s_e - eo.ease_off_angle  # [rad]
    d_q = out.roll_angle + s_q - eo.roll_angle
    arm = eo.normal_arm  # [mm/rad]: normal gap per radian of gear rotation
    root = eo.valid & (eo.pinion_v <= 0.25)  # mates on the zero rows' side of the taper
    active = eo.valid & (eo.pinion_v > 0.45)
    assert root.sum() >= 10 and active.sum() >= 100
    # on the active flank the change is of the order of the deviation (not vacuous)
    assert np.nanmax(np.abs(d_eps[active] * arm[active])) > 5e-3  # > 5 µm
    # where the deviation is zero only the thin-plate spline's tail reaches: its largest
    # |value| below v = 0.25 for this field is 0.90 µm (measured; 9 % of the 10 µm peak, the
    # spline's overshoot between the zero rows and the hollow); asserted < 1 µm
    tail = np.abs(dev(np.linspace(0, 1, 41)[:, None], np.linspace(0, 0.25, 26)[None, :])).max()
    assert tail < 1.0e-3
    # the root mates' ease-off change stays within that tail: Δε·ρ|n·e_θ| = −δ_p times
    # (normal arm)/(R·pinion arm), which the equation of meshing makes 1 to within the 3 %
    # stated in apply_deviations (measured 0.897 µm against the tail's 0.898 µm); 5 % margin
    change_root = np.abs(d_eps[root] * arm[root]).max()
    assert change_root <= 1.05 * tail
    assert change_root < 0.15 * np.nanmax(np.abs(d_eps[active] * arm[active]))  # 0.9 vs 9.4
    # and Q changes by at most tail / (least pinion arm ≈ 17.8 mm): 5.6e-5 rad (measured
    # 4.3e-5 rad)
    assert np.abs(d_q[root]).max() < 5.6e-5


def test_bundled_wear_sits_on_the_active_flanks(eo):
    # cases/deviations/wear_11x41_*.csv are simulated (make_wear_case.py, contact.wear):
    # material only removed, and only where the flanks mesh — the deepest node at a place
    # that meshes (the pinion at the mates of the valid gear nodes, the gear at those
    # nodes), nothing below the lowest meshing profile fraction (the fillet and root)
    root = Path(__file__).resolve().parents[1] / "cases" / "deviations"
    gu, gv = np.meshgrid(eo.u, eo.v, indexing="ij")
    ok = eo.valid & np.isfinite(eo.pinion_u) & np.isfinite(eo.pinion_v)
    places = {"pinion": (eo.pinion_u[ok], eo.pinion_v[ok]), "gear": (gu[ok], gv[ok])}
    for member, (u, v) in places.items():
        dev = read_deviations(root / f"wear_11x41_{member}.csv", member)
        d = dev.deviation
        assert d.max() == 0.0 and d.min() < -1e-3  # worn, > 1 µm deep
        i, j = np.unravel_index(np.argmin(d), d.shape)
        assert u.min() <= dev.u[i] <= u.max() and v.min() <= dev.v[j] <= v.max()
        below = dev.v < v.min() - 0.5 * (dev.v[1] - dev.v[0])
        assert below.any() and np.all(d[:, below] == 0.0)
