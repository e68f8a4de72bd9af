"""Corrective machine settings (geometry.synthesis.correction, ``ltca correct``).

Independent references: the settings a flank was cut with (known perturbations of a
bundled case, recovered from its CMM deviations), closed forms of a cone of revolution
(the Formate gear's flank: a point-radius or axial change is a uniform normal offset, a
spin about its own axis no change), the statistics of least squares under Gaussian noise,
and linear-algebra identities of the subset selection.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from contact.cli import main
from contact.utca.deviations import DEFAULT_MEASUREMENT_GRID
from geometry.case import load_case
from geometry.core.errors import InputError
from geometry.machine.cutter import profile_sections
from geometry.machine.flank import flank_at
from geometry.synthesis.correction import (
    COND_MAX,
    corrected_case,
    corrective_settings,
    identifiable_subset,
    measurement_places,
    setting_value,
    settings_deviation,
)

CASE_FILE = Path(__file__).resolve().parents[1] / "cases" / "kolivand2009_fm_11x41.toml"
# the 5 x 9 CMM grid (seed §4.5.2): 9 lengthwise x 5 profile fractions
U = np.linspace(*DEFAULT_MEASUREMENT_GRID["u_limits"], DEFAULT_MEASUREMENT_GRID["nu"])
V = np.linspace(*DEFAULT_MEASUREMENT_GRID["v_limits"], DEFAULT_MEASUREMENT_GRID["nv"])
DEG = math.pi / 180.0

#: known settings errors (internal units: mm, rad, 1, 1/rad^2) of the pinion's generated
#: concave flank and of the gear's Formate convex flank: deviations of 3.8-23 um
PERTURBATIONS = {
    ("pinion", "concave"): {"radial_setting": 0.02, "cradle_angle": 0.01 * DEG,
                            "ratio_of_roll": 2e-4, "6D": 5e-3},
    ("gear", "convex"): {"machine_root_angle": 0.01 * DEG, "blade_angle": 0.02 * DEG,
                         "machine_center_to_back": 0.01},
}


@pytest.fixture(scope="module")
def case():
    return load_case(CASE_FILE)


def _measured(case, member, flank, pert, sign=1.0):
    tool = case.member(member).flank(flank)
    vals = {k: setting_value(tool, k) + sign * d for k, d in pert.items()}
    return settings_deviation(case, member, flank, vals, U, V)


@pytest.fixture(scope="module")
def pinion_measured(case):
    return _measured(case, "pinion", "concave", PERTURBATIONS["pinion", "concave"])


def _write_csv(path, dev):
    lines = ["# synthetic CMM grid", "v\\u," + ",".join(f"{x:.4f}" for x in U)]
    lines += [f"{v:.4f}," + ",".join(f"{x:.10f}" for x in dev[:, j]) for j, v in enumerate(V)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def test_cmm_deviation_of_a_cone_is_a_uniform_offset(case):
    """The Formate gear flank is the imprint of a cone of revolution (straight blade): a
    point-radius change Δr offsets it by Δr cos α along its normal, an axial shift of the
    work along the cutter axis (sliding base; tilt 0) by ΔX_b sin α, everywhere on the
    straight part; a CMM along the nominal normals measures exactly these offsets. Signs:
    a larger outside-blade radius widens the slot on the concave side (material removed),
    a larger inside-blade radius moves away from the convex flank (material added)."""
    for flank, sign in (("concave", -1.0), ("convex", 1.0)):
        tool = case.gear.flank(flank)
        alpha = tool.blade.blade_angle
        z = flank_at(case, "gear", flank, *_places(case))
        straight = z.section == profile_sections(tool.blade).names.index("profile")
        assert straight.sum() >= 30
        dr = settings_deviation(case, "gear", flank,
                                {"point_radius": tool.blade.point_radius + 0.01}, U, V)
        # accuracy of the CMM measurement: 1e-9 mm (generator points to 1e-10 mm)
        np.testing.assert_allclose(dr[straight], sign * 0.01 * math.cos(alpha), atol=1e-9)
        db = settings_deviation(case, "gear", flank,
                                {"sliding_base": tool.machine.sliding_base + 0.01}, U, V)
        np.testing.assert_allclose(np.abs(db[straight]), 0.01 * math.sin(alpha), atol=1e-9)


def _places(case):
    from geometry.synthesis.correction import measurement_places

    return measurement_places(case.gear.blank, U, V)


@pytest.mark.parametrize("key", list(PERTURBATIONS))
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_recovers_known_settings(case, key, sign):
    """Perturb 3-4 settings, take the CMM deviations of the perturbed flank from the nominal
    as the measurement: the identified error is the perturbation (1 %), the correction
    its negative, the fit residual <= 0.1 um; and the corrected machine (still carrying the
    error) cuts the nominal flank to 0.1 um."""
    member, flank = key
    pert = {k: sign * d for k, d in PERTURBATIONS[key].items()}
    measured = _measured(case, member, flank, pert)
    assert 3e-3 < np.abs(measured).max() < 3e-2  # a few to some 20 um
    c = corrective_settings(case, member, flank, U, V, measured, settings=list(pert))
    true = np.array(list(pert.values()))
    assert c.determined.all() and c.effect.all()
    np.testing.assert_allclose(c.identified, true, rtol=0.01)
    np.testing.assert_array_equal(c.correction, -c.identified)
    np.testing.assert_allclose(c.corrected, c.nominal + c.correction)
    assert c.residual_max <= 1e-4 and c.n_points == U.size * V.size
    # the machine that cut the measured flank has the error; dial in the correction
    tool = case.member(member).flank(flank)
    after = settings_deviation(case, member, flank,
                               {k: setting_value(tool, k) + d + cj
                                for (k, d), cj in zip(pert.items(), c.correction, strict=True)},
                               U, V)
    assert np.abs(after).max() <= 1e-4


def test_corrected_case_cuts_the_opposite_deviation(case, pinion_measured, tmp_path):
    """On a machine without error the corrected settings cut minus the measured deviation
    (first order: the second-order remainder is below 0.2 % of the 23 um deviation on the
    flank proper); the corrected case round-trips through TOML with its provenance.

    The grid's root row (v = 0.05) lies on the fillet the blade's edge radius cuts at the
    heel half of the face (u >= 0.625; at u = 0.5 on the profile by 0.05 mm of blade arc):
    since the tip plane sits on the root cone (c716685; it lay 0.43 mm deeper), the fillet
    reaches higher, and those points lie up to 0.23 mm of arc into the edge radius
    (0.00-0.09 mm before). There the remainder is of order κ_e |δ| with the edge radius's
    curvature κ_e = 1/0.813 mm: at most 2.8 % of δ (measured 0.65 % at the heel, 0.16 %
    with the old tip plane); the flank proper keeps its 0.2 % (measured 0.025 %)."""
    pert = PERTURBATIONS["pinion", "concave"]
    c = corrective_settings(case, "pinion", "concave", U, V, pinion_measured,
                            settings=list(pert))
    back = settings_deviation(case, "pinion", "concave", c.values, U, V)
    tool = case.pinion.concave
    z, rho = measurement_places(case.pinion.blank, U, V)
    fillet = flank_at(case, "pinion", "concave", z, rho).section == (
        profile_sections(tool.blade).names.index("edge"))
    assert not fillet[:, 1:].any()  # only the root row reaches the fillet
    residual, scale = np.abs(back + pinion_measured), np.abs(pinion_measured).max()
    assert residual[~fillet].max() <= 2e-3 * scale
    assert residual[fillet].max() <= scale / tool.blade.edge_radius * scale
    out = corrected_case(case, [c], provenance={"deviation_files": ["p.csv"]})
    path = tmp_path / "corrected.toml"
    path.write_text(out.to_toml(), encoding="utf-8")
    loaded = load_case(path)
    for name, value in c.values.items():
        assert setting_value(loaded.pinion.concave, name) == pytest.approx(value, rel=1e-12)
    assert loaded.gear == case.gear and loaded.pinion.convex == case.pinion.convex
    table = loaded.extra["correction"]
    assert table["source_case"] == case.name
    entry = table["pinion"]["concave"]
    assert entry["corrections"]["radial_setting"] == pytest.approx(-0.02, rel=0.01)
    assert entry["residual_max_um"] <= 0.1
    with pytest.raises(InputError, match="two corrections"):
        corrected_case(case, [c, c])


def test_gauss_newton_recovers_a_large_perturbation(case):
    """Ten times the perturbation (deviations of ~0.23 mm, well beyond the linear range):
    the Gauss-Newton iterations with the generator recover it exactly."""
    pert = {k: 10 * d for k, d in PERTURBATIONS["pinion", "concave"].items()}
    measured = _measured(case, "pinion", "concave", pert)
    assert np.abs(measured).max() > 0.15
    c = corrective_settings(case, "pinion", "concave", U, V, measured, settings=list(pert))
    assert c.iterations > 1
    np.testing.assert_allclose(c.identified, list(pert.values()), rtol=1e-6)
    assert c.residual_max <= 1e-6


def test_noise_degrades_gracefully(case, pinion_measured):
    """1 um Gaussian noise on the grid: each identified error within 4 reported standard
    errors of the truth (the standard errors being those of least squares, σ √diag
    (JᵀJ)⁻¹), the residual RMS that of the noise, √((n − p)/n) σ, within the 99.9 % range
    of a χ² with n − p = 41 degrees of freedom; and with the default candidates the report
    holds fixed the settings the others reproduce, keeps the fit at the noise level."""
    pert = PERTURBATIONS["pinion", "concave"]
    noise = 1e-3 * np.random.default_rng(2).standard_normal(pinion_measured.shape)
    c = corrective_settings(case, "pinion", "concave", U, V, pinion_measured + noise,
                            settings=list(pert))
    err = c.identified - np.array(list(pert.values()))
    assert np.all(np.abs(err) <= 4.0 * c.standard_error_per_um)
    dof = c.n_points - len(pert)
    ratio = c.residual_rms / (1e-3 * math.sqrt(dof / c.n_points))
    assert 0.62 <= ratio <= 1.38
    # σ̂ from the residual scales the per-um standard errors
    np.testing.assert_allclose(c.standard_error / c.standard_error_per_um,
                               math.sqrt(c.n_points / dof) * c.residual_rms / 1e-3)

    d = corrective_settings(case, "pinion", "concave", U, V, pinion_measured + noise)
    held = ~d.determined
    assert held.any() and d.determined.sum() >= 4
    assert d.condition_number > COND_MAX >= d.condition_number_determined
    assert np.all(np.isnan(d.standard_error_per_um[held]))
    assert np.all(d.correction[held] == 0.0)
    # every held setting is one the determined ones nearly reproduce: adding it back
    # raises the condition number beyond the limit
    jn = d.jacobian / np.linalg.norm(d.jacobian, axis=0)
    for j in np.flatnonzero(held):
        cols = np.append(np.flatnonzero(d.determined), j)
        assert np.linalg.cond(jn[:, cols]) > COND_MAX
    assert d.residual_rms <= 1.4e-3  # the noise level, the flank corrected all the same


def test_conditioning_flags_exact_dependences(case):
    """Formate gear, tilt 0: a spin of the cutter about its own axis (swivel) does not move
    the cone (no effect), and on the straight blade a sliding-base change equals a
    point-radius change times tan α (proportional columns) — measured there only (the edge
    radius at the root row is a torus, for which the two differ), the report holds one of
    the two fixed, with a variance inflation beyond 1e6 (against the determined settings,
    its twin among them); the one kept is not inflated (VIF within the fit < 100)."""
    tool = case.gear.concave
    assert tool.machine.tilt == 0.0
    z = flank_at(case, "gear", "concave", *_places(case))
    straight = z.section == profile_sections(tool.blade).names.index("profile")
    measured = np.where(straight, 0.0, np.nan)  # NaN: not measured
    names = ["radial_setting", "blade_angle", "sliding_base", "point_radius", "swivel"]
    c = corrective_settings(case, "gear", "concave", U, V, measured, settings=names)
    assert c.n_points == straight.sum()
    assert not c.effect[4] and not c.determined[4] and math.isinf(c.vif[4])
    ratio = c.jacobian[:, 2] / c.jacobian[:, 3]
    # the finite differences agree with the closed form to 1e-6 (second-order error)
    np.testing.assert_allclose(np.abs(ratio), math.tan(tool.blade.blade_angle), rtol=1e-6)
    assert c.determined[2] != c.determined[3]
    # the held one: its determined twin reproduces it; the kept one: independent of the rest
    held, kept = (3, 2) if c.determined[2] else (2, 3)
    assert c.vif[held] > 1e6 and c.vif[kept] < 100
    assert c.determined[:2].all() and np.abs(c.identified).max() < 1e-9


def test_identifiable_subset_identities():
    """Columns a, b, 2a + 1e-9 c, 0: the rank is 2 (plus the near-dependent), the zero
    column has no effect, a and 2a + ε cannot both be kept, VIF = 1 for a column
    orthogonal to the rest."""
    rng = np.random.default_rng(0)
    q, _ = np.linalg.qr(rng.standard_normal((20, 3)))
    a, b, cvec = q.T
    jac = np.stack([a, b, 2 * a + 1e-9 * cvec, np.zeros(20)], 1)
    sel, sv, vif = identifiable_subset(jac, 100.0)
    assert sel.sum() == 2 and sel[1] and sel[0] != sel[2] and not sel[3]
    assert sv.size == 3 and sv[-1] / sv[0] < 1e-8
    # VIF against the selection: b and the kept twin are orthogonal (1); the twin left out
    # is reproduced by the kept one (> 1e16); the zero column has none
    left_out = 2 if sel[0] else 0
    assert vif[1] == pytest.approx(1.0) and vif[2 - left_out] == pytest.approx(1.0)
    assert vif[left_out] > 1e16 and math.isinf(vif[3])
    sel, _, _ = identifiable_subset(jac, 1e12)  # a looser limit keeps the near-dependent
    assert sel[:3].all()
    with pytest.raises(InputError, match="cond_max"):
        identifiable_subset(jac, 1.0)


def test_bounds_limit_the_correction(case, pinion_measured):
    """A bound on a corrected value is honoured (the value sits on it), the others
    compensate as they can, and the residual grows."""
    pert = PERTURBATIONS["pinion", "concave"]
    s0 = case.pinion.concave.machine.radial_setting
    c = corrective_settings(case, "pinion", "concave", U, V, pinion_measured,
                            settings=list(pert),
                            bounds={"radial_setting": (s0 - 0.01, None)})
    assert c.at_bound[0] and c.corrected[0] == pytest.approx(s0 - 0.01, abs=1e-12)
    assert c.residual_max > 1e-4


@pytest.mark.parametrize("kwargs, match", [
    ({"settings": ["radial_setting", "crade_angle"]}, r"settings: unknown setting "
                                                      r"'crade_angle'; accepted: .*cradle_angle"),
    ({"settings": ["radial_setting", "radial_setting"]}, "given twice"),
    ({"settings": ["radial_setting"], "bounds": {"tilt": (0.0, 0.1)}},
     "not among the settings corrected"),
    ({"settings": ["radial_setting"], "bounds": {"radial_setting": (-1.0, None)}},
     r"bounds.radial_setting: -1 mm lies outside the setting's valid range"),
    ({"settings": ["tilt"], "bounds": {"tilt": (None, 95 * DEG)}},
     r"bounds.tilt: 95 deg lies outside .*\(-90, 90\)"),
    ({"settings": ["blade_angle"], "bounds": {"blade_angle": (0.0, 50 * DEG)}},
     r"bounds.blade_angle: 50 deg lies outside .*\[0, 45\)"),
    ({"settings": ["radial_setting"], "bounds": {"radial_setting": (101.0, 100.0)}},
     "low < high"),
    ({"settings": ["radial_setting"], "bounds": {"foo": (0.0, 1.0)}},
     "bounds: unknown setting 'foo'"),
])
def test_bad_input(case, kwargs, match):
    dev = np.zeros((U.size, V.size))
    with pytest.raises(InputError, match=match):
        corrective_settings(case, "pinion", "concave", U, V, dev, **kwargs)


def test_bad_input_process_and_grid(case):
    dev = np.zeros((U.size, V.size))
    with pytest.raises(InputError, match="'ratio_of_roll' exists only for a generated flank"):
        corrective_settings(case, "gear", "convex", U, V, dev, settings=["ratio_of_roll"])
    with pytest.raises(InputError, match=r"deviation: must have shape"):
        corrective_settings(case, "pinion", "concave", U, V, dev.T)
    with pytest.raises(InputError, match="at least 3 measured points"):
        corrective_settings(case, "pinion", "concave", U, V, np.full(dev.shape, np.nan))


def test_cli_correct(case, pinion_measured, tmp_path, capsys):
    """``ltca correct`` prints the table and writes a corrected case that loads, with the
    corrections of the API; bad names and bounds exit 2 naming the field."""
    pin = tmp_path / "pinion.csv"
    _write_csv(pin, pinion_measured)
    out = tmp_path / "corrected.toml"
    names = list(PERTURBATIONS["pinion", "concave"])
    rc = main(["correct", str(CASE_FILE), "--deviations", str(pin), "-", "--settings", *names,
               "-o", str(out)])
    text = capsys.readouterr().out
    assert rc == 0
    assert "pinion concave (Generate)" in text and "radial_setting" in text and "wrote" in text
    loaded = load_case(out)
    assert setting_value(loaded.pinion.concave, "radial_setting") == pytest.approx(
        case.pinion.concave.machine.radial_setting - 0.02, abs=2e-4)
    assert loaded.extra["correction"]["deviation_files"] == [str(pin), "-"]
    assert loaded.gear == case.gear
    rc = main(["correct", str(CASE_FILE), "--deviations", str(pin), "-", "--settings", "foo",
               "-o", str(out)])
    assert rc == 2 and "unknown setting 'foo'" in capsys.readouterr().err
    rc = main(["correct", str(CASE_FILE), "--deviations", str(pin), "-", "--settings", "tilt",
               "--bound", "tilt", "0", "95", "-o", str(out)])
    assert rc == 2 and "bounds.tilt: 95 deg" in capsys.readouterr().err
