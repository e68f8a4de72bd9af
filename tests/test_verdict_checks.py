"""The verdict's root-stress and scuffing checks (issue 72 item 2,
contact/study/verdict_checks.py), against hand calculations on synthetic analyses and on
the default case's own analysis.

The synthetic trees hold only what the checks read: ``/ltca`` with ``root_stress_max``
(torque, member) and the members' materials, ``/rating`` with ISO 10300-3's σ_FP, K_A, K_v,
S_Fmin, the design torque and Y_NT, ``/scuffing_micropitting`` with the LTCA's S_B and
``/rating/flash_temperature`` with the standard's two variants and their spread. The hand
calculations are written out in each test; they are exact arithmetic, so the tolerance is
the two decimals the finding prints.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from contact import verdict
from contact.study.verdict_checks import root_stress_safety

MAT = "case_carburised_steel"  # σ_Flim·Y_ST 850 MPa, Y_NT static 2.5 at grade MQ


def _ltca(torques, root):
    return xr.Dataset(
        {"root_stress_max": (("torque", "member"), np.asarray(root, float))},
        coords={"torque": np.asarray(torques, float),
                "member_label": ("member", ["pinion", "gear"])},
        attrs={"material_pinion": MAT, "material_gear": MAT})


def _rating(torques, sigma_fp, k_a, k_v, design):
    return xr.Dataset(
        {"sigma_FP": ("member", np.asarray(sigma_fp, float)), "K_A": k_a,
         "K_v": ("torque", np.asarray(k_v, float)), "S_Fmin": 1.3,
         "Y_NT": ("member", [1.0, 1.0]), "load_cycles": ("member", [np.nan, np.nan]),
         "design_torque": design},
        coords={"torque": np.asarray(torques, float)})


def _tree(groups, attrs=None):
    tree = xr.DataTree.from_dict({"/": xr.Dataset(attrs=attrs or {}), **groups})
    return tree


def _found(v, check):
    return [f for f in v.findings if f.check == check]


def test_root_stress_against_sigma_fp_by_hand():
    """σ_FP = σ_Flim Y_ST Y_NT Y_δrelT Y_RrelT Y_X = 425·2·1·0.99·0.98·1 = 824.67 MPa.
    At 100 N·m (the design torque), pinion FE peak 500 MPa, K_A 1.25, K_v 1.1:
    σ_F,FE = 500·1.25·1.1 = 687.5 MPa, S_F = 824.67/687.5 = 1.20 < 1.3: fail.
    Gear 400 MPa: 550 MPa, S_F 1.50: no finding.
    At 150 N·m, above the design torque at long life, pinion 600 MPa, K_v 1.05:
    787.5 MPa, S_F 1.05: attention (a finite life); gear 1600 MPa: 2100 MPa, above the
    static strength 824.67·2.5 = 2061.7 MPa: fail, no life."""
    fp = 425 * 2 * 1.0 * 0.99 * 0.98 * 1.0
    torques = [100.0, 150.0]
    root = [[500.0, 400.0], [600.0, 1600.0]]
    rt = _rating(torques, [fp, fp], 1.25, [1.1, 1.05], 100.0)
    s = root_stress_safety(np.asarray(root), rt)
    np.testing.assert_allclose(s, [[fp / 687.5, fp / 550.0], [fp / 787.5, fp / 2100.0]],
                               rtol=1e-12)
    v = verdict(_tree({"/ltca": _ltca(torques, root), "/rating": rt}))
    assert "root_stress" in v.checks
    found = _found(v, "root_stress")
    assert sorted((f.severity, f.reason.split(":")[0]) for f in found) == sorted([
        ("fail", "FE root stress of the pinion at 100 N·m"),
        ("attention", "FE root stress of the pinion at 150 N·m"),
        ("fail", "FE root stress of the gear at 150 N·m")])
    text = " | ".join(f.reason for f in found)
    assert "500 MPa × K_A 1.25 × K_v 1.100 = 688 MPa against σ_FP 825 MPa" in text
    assert "S_F 1.20 below S_Fmin 1.3" in text
    assert "S_F 1.05 below S_Fmin 1.3 at long life: above the design torque 100 N·m" in text
    assert "above the static strength 2062 MPa" in text


def test_root_stress_without_a_rating_against_the_material():
    """No ISO 10300 rating: σ_FE = σ_Flim·Y_ST = 425·2 = 850 MPa (grade MQ), static
    850·2.5 = 2125 MPa, K_A = K_v = 1. 900 MPa: attention; 2200 MPa: fail; 800: none."""
    v = verdict(_tree({"/ltca": _ltca([50.0], [[900.0, 800.0]])}))
    (f,) = _found(v, "root_stress")
    assert f.severity == "attention" and "above σ_FE = σ_Flim·Y_ST 850 MPa" in f.reason
    v = verdict(_tree({"/ltca": _ltca([50.0], [[2200.0, 800.0]])}))
    (f,) = _found(v, "root_stress")
    assert f.severity == "fail" and "static strength 2125 MPa" in f.reason


@pytest.mark.parametrize("said, why", [
    ("not requested (steps)", "no root stress: the chain skipped its step"),
    ("root stress not computed: the FE model failed (mesh)",
     "no root stress: root stress not computed: the FE model failed (mesh)"),
    (None, "no root stress: /ltca has no root_stress_max"),
])
def test_root_stress_missing_is_listed_not_checked(said, why):
    lt = _ltca([50.0], [[1.0, 1.0]]).drop_vars("root_stress_max")
    v = verdict(_tree({"/ltca": lt}, {"root_stress_not_run": said} if said else None))
    assert "root_stress" not in v.checks
    assert dict(v.unchecked)["root_stress"].startswith(why)
    assert any(line.startswith("  not checked: ") and "root_stress" in line
               for line in v.lines())


def test_the_standard_scuffing_method_not_applied_says_why():
    """A 7-tooth pinion's virtual gears have ε_α 0.987 < 1, outside the standard's
    flash-temperature method: the chain records why on /rating and the verdict's "not
    checked" says it (it said "the rating method gives no virtual gears for it")."""
    from contact.chain import _flash_temperature_or_reason

    friction = xr.Dataset(attrs={"lubricant": "75W90", "inlet_temperature_degC": 90.0,
                                 "roughness_rq_um": 0.8})
    flash, why = _flash_temperature_or_reason(xr.Dataset(), friction, None)
    assert flash is None and why.startswith("the standard's method does not apply here")
    rt = _rating([50.0], [800.0, 800.0], 1.0, [1.0], 50.0)
    rt.attrs["flash_temperature_not_run"] = "the standard's method does not apply here (x)"
    v = verdict(_tree({"/ltca": _ltca([50.0], [[1.0, 1.0]]), "/rating": rt,
                       "/friction": xr.Dataset()}))
    assert dict(v.unchecked)["scuffing_standard"] == (
        "no /rating/flash_temperature: the standard's method does not apply here (x)")


def _flash(torques, s, low, high):
    return xr.Dataset(
        {"scuffing_safety": (("variant", "torque"), np.asarray(s, float)),
         "scuffing_safety_low": (("variant", "torque"), np.asarray(low, float)),
         "scuffing_safety_high": (("variant", "torque"), np.asarray(high, float))},
        coords={"torque": np.asarray(torques, float),
                "variant_label": ("variant", ["standard", "lengthwise_sliding"])})


def test_scuffing_standard_below_its_minimum_is_said_beside_the_judged_one():
    """The issue's 300 N·m case: the LTCA's S_B 1.82 (judged, passes), the standard's 1.40
    (1.02–1.40), the lengthwise-sliding variant's 1.09 (0.83–1.09): one attention finding,
    for the variant whose uncertain constants put S_B below 1, naming the judged S_B. At
    400 N·m the standard's own S_B 0.95 is below 1: a finding for each variant."""
    sm = xr.Dataset({"scuffing_safety": ("torque", [1.82, 1.30])},
                    coords={"torque": [300.0, 400.0]})
    flash = _flash([300.0, 400.0], [[1.40, 0.95], [1.09, 0.80]],
                   [[1.02, 0.70], [0.83, 0.60]], [[1.40, 0.95], [1.09, 0.80]])
    tree = _tree({"/ltca": _ltca([300.0, 400.0], [[1.0, 1.0], [1.0, 1.0]]),
                  "/scuffing_micropitting": sm, "/rating": xr.Dataset(
                      coords={"torque": [300.0, 400.0]}),
                  "/rating/flash_temperature": flash})
    v = verdict(tree)
    assert "scuffing" in v.checks and "scuffing_standard" in v.checks
    found = _found(v, "scuffing_standard")
    assert all(f.severity == "attention" for f in found)
    assert len(found) == 3
    text = " | ".join(f.reason for f in found)
    assert ("ISO/TS 6336-20 with the hypoid's lengthwise sliding (not a standard) gives S_B "
            "1.09 at 300 N·m, but its uncertain constants (μ_m's form, θ_S with η^−0.05) put "
            "it down to 0.83, below 1; the verdict judges the LTCA's S_B, 1.82") in text
    assert ("(the standard) gives S_B 0.95 (0.70–0.95 over its uncertain constants) at "
            "400 N·m, below 1; the verdict judges the LTCA's S_B, 1.30") in text
    assert not _found(v, "scuffing")  # the judged S_B passes


def test_a_spiral_bevels_variant_with_the_standards_numbers_is_said_once():
    """Issue 71, round 26d (branch api87): the FH spiral bevel 18x22 at Σ 60° (no offset)
    listed the scuffing_standard finding twice, the second "with the hypoid's lengthwise
    sliding" with the standard's numbers (S_B 1.12, 0.80 at the low end, equal to the
    last digit in its /rating/flash_temperature). Equal numbers: one finding, saying the
    variant gives the same; a hypoid's different numbers keep both (the test above)."""
    sm = xr.Dataset({"scuffing_safety": ("torque", [2.54, 1.73])},
                    coords={"torque": [163.9, 1093.0]})
    flash = _flash([163.9, 1093.0], [[3.417, 1.117], [3.417, 1.117]],
                   [[2.458, 0.8035], [2.458, 0.8035]], [[3.417, 1.117], [3.417, 1.117]])
    tree = _tree({"/ltca": _ltca([163.9, 1093.0], [[1.0, 1.0], [1.0, 1.0]]),
                  "/scuffing_micropitting": sm, "/rating": xr.Dataset(
                      coords={"torque": [163.9, 1093.0]}),
                  "/rating/flash_temperature": flash})
    (f,) = _found(verdict(tree), "scuffing_standard")
    assert f.reason.startswith("ISO/TS 6336-20 on the ISO 10300 virtual cylindrical gears "
                               "(the standard) gives S_B 1.12 at 1093 N·m, but its uncertain "
                               "constants")
    assert ("put it down to 0.80, below 1; its lengthwise-sliding variant (not a standard) "
            "gives the same numbers (no offset); the verdict judges the LTCA's S_B, 1.73"
            ) in f.reason
    assert "the hypoid's" not in f.reason


def test_the_judged_scuffing_safety_is_named():
    sm = xr.Dataset({"scuffing_safety": ("torque", [0.9])}, coords={"torque": [300.0]})
    v = verdict(_tree({"/ltca": _ltca([300.0], [[1.0, 1.0]]),
                       "/scuffing_micropitting": sm}))
    (f,) = _found(v, "scuffing")
    assert f.severity == "fail"
    assert "S_B 0.9 at 300 N·m below 1 (the LTCA's: Blok's flash" in f.reason
    assert dict(v.unchecked)["scuffing_standard"].startswith(
        "no /rating/flash_temperature: no /rating group")


def test_a_root_stress_not_computed_at_a_torque_is_said():
    """A NaN root stress (the FE model could not place a torque's loads) is not passed
    silently: an attention finding with the reason the step stored."""
    lt = _ltca([50.0, 500.0], [[100.0, 90.0], [300.0, np.nan]])
    lt["root_stress_max"].attrs["not_computed"] = (
        "gear at 500 N m: not computed (NaN): 2.1 % of the load lies off its FE load grid.")
    v = verdict(_tree({"/ltca": lt}))
    (f,) = _found(v, "root_stress")
    assert f.severity == "attention"
    assert f.reason == ("root stress of the gear at 500 N·m not checked: not computed (NaN): "
                        "2.1 % of the load lies off its FE load grid.")


def test_a_rating_made_outside_the_chain_is_said_so_not_blamed_on_its_method():
    """A /rating of ISO 10300 put in the tree by hand (``tree["rating"] =
    contact.iso10300_rating(...)``, as the gallery's own-gear-set example did on an unseen
    hypoid 9x37, issue 71 unseen (6)) has no flash temperature because the chain's rating
    step did not run, not because ISO 10300 gives no virtual gears (it does: the chain
    computes /rating/flash_temperature beside it). The reason names that; a method without
    the companion keeps the old reason."""
    rt = _rating([50.0], [800.0, 800.0], 1.0, [1.0], 50.0)
    rt.attrs["rating_method"] = "iso10300"
    v = verdict(_tree({"/ltca": _ltca([50.0], [[1.0, 1.0]]), "/rating": rt,
                       "/friction": xr.Dataset()}))
    why = dict(v.unchecked)["scuffing_standard"]
    assert "not written by the analysis chain's rating step" in why
    assert "gives no virtual gears" not in why
    rt.attrs["rating_method"] = "agma2003"
    v = verdict(_tree({"/ltca": _ltca([50.0], [[1.0, 1.0]]), "/rating": rt,
                       "/friction": xr.Dataset()}))
    assert dict(v.unchecked)["scuffing_standard"].endswith("gives no virtual gears for it")


def test_a_variant_with_the_standards_numbers_is_not_printed_twice():
    """Round 14: a spiral bevel (no offset) printed the lengthwise-sliding variant of the
    standard's flash temperature method with the standard's numbers, line for line; the
    second line now says so, a hypoid's different numbers are printed."""
    import xarray as xr

    from contact.commands.run import _standard_lines

    def iso(second):
        values = {"contact_temperature_max": [180.0, second],
                  "flash_temperature_max": [80.0, second - 100.0],
                  "mean_friction_coefficient": [0.05, 0.05],
                  "scuffing_safety": [1.5, 1.5 if second == 180.0 else 1.2]}
        return xr.Dataset({k: ("variant", v) for k, v in values.items()},
                          coords={"variant": ["standard", "lengthwise_sliding"]})

    same = _standard_lines(iso(180.0))
    assert same[0].endswith("180 degC (flash 80 K, mu_m 0.050), S_B 1.50")
    assert same[1].endswith("(not a standard): the same numbers as the line above")
    other = _standard_lines(iso(210.0))
    assert other[1].endswith("210 degC (flash 110 K, mu_m 0.050), S_B 1.20")


def test_duty_cycle_judges_a_bin_as_ltca_run_judges_its_torque():
    """Issue 71: the truck hypoid 8x47 FAILed `ltca run` on the gear's S_F,FE 1.25 < 1.3
    at its design torque while `ltca duty-cycle` at the same torque said nothing (its S_F
    against 1). The same numbers as test_root_stress_against_sigma_fp_by_hand, now as
    duty-cycle bins (S_F,FE = σ_FP / (FE peak · K_A K_v), long life): bin 0 at the design
    torque 100 N·m, pinion S_F,FE 824.67/687.5 = 1.20 — fail in both; bin 1 at 150 N·m,
    pinion 824.67/787.5 = 1.05 — attention in both; the gears at 1.50 and 4.40 of bin
    0 / a bin 1 gear above 1.3 — no finding. The duty cycle's findings come from the same
    rule (root_safety_severity) as the run's; the severities are compared, not copied."""
    from contact.study.verdict_checks import root_safety_severity

    fp = 425 * 2 * 1.0 * 0.99 * 0.98 * 1.0
    torques = [100.0, 150.0]
    root = [[500.0, 400.0], [600.0, 250.0]]
    k_v = [1.1, 1.05]
    rt = _rating(torques, [fp, fp], 1.25, k_v, 100.0)
    run = {(f.severity, f.reason.split(" at ")[0].split()[-1], f.reason.split(" at ")[1]
            .split(":")[0]) for f in _found(verdict(_tree({"/ltca": _ltca(torques, root),
                                                          "/rating": rt})), "root_stress")}
    assert run == {("fail", "pinion", "100 N·m"), ("attention", "pinion", "150 N·m")}
    safety = root_stress_safety(np.asarray(root), rt)  # (bin, member), the bins' S_F,FE
    ds = xr.Dataset(
        {"contact_safety_factor": ("member", [2.0, 2.0]),
         "root_stress_safety": (("bin", "member"), safety),
         "bending_safety_min": 1.3, "rating_design_torque": 100.0,
         "torque": ("bin", torques)},
        coords={"bin": [0, 1], "member": ["pinion", "gear"]})
    found = _found(verdict(ds), "root_stress")
    assert sorted((f.severity, f.reason.split(":")[0]) for f in found) == [
        ("attention", "pinion"), ("fail", "pinion")]
    (fail,) = [f for f in found if f.severity == "fail"]
    assert "S_F,FE 1.20 below S_Fmin 1.3" in fail.reason and "bin 0 (" in fail.reason
    (att,) = [f for f in found if f.severity == "attention"]
    assert "S_F,FE 1.05 below S_Fmin 1.3" in att.reason and "bin 1 (" in att.reason
    # the next step under the FAIL: ltca run at the failing bin's torque
    from contact.commands.next_steps import duty_cycle_lines

    lines = duty_cycle_lines(ds, "x.toml", None, ["root_stress"])
    assert "bin 0 (100 N m) has the lowest FE root safety S_F,FE 1.20" in lines[0]
    assert lines[1] == "    ltca run x.toml --torque 100"
    # the rule itself: at the minimum no finding; NaN not judged; static always fails
    assert root_safety_severity(1.3, 1.3, 100.0, 100.0) is None
    assert root_safety_severity(float("nan"), 1.3, 100.0, 100.0) is None
    assert root_safety_severity(1.29, 1.3, 100.0, float("nan")) == "fail"
    assert root_safety_severity(1.29, 1.3, 150.0, 100.0, long_life=False) == "fail"
    assert root_safety_severity(0.3, 1.3, 150.0, 100.0, above_static=True) == "fail"



def test_a_duty_root_safety_just_below_its_minimum_is_shown_below_it():
    """Round 27 (the FM hypoid 12x37 at Σ 95°, its design torque the ISO capacity where the
    gear's S_F is 1.30): the illustrative duty cycle's top bin, at its made-up deflection,
    FAILed the gear's root with "S_F,FE 1.30 below S_Fmin 1.3", and its next step said the
    same. Both now print as many decimals as show the value below (shown_below): 1.2996 →
    "1.2996". The severity is root_safety_severity's, unchanged (exact strings)."""
    from contact.commands.next_steps import duty_cycle_lines

    ds = xr.Dataset(
        {"contact_safety_factor": ("member", [2.0, 2.0]),
         "root_stress_safety": (("bin", "member"), [[3.0, 2.5], [1.76, 1.2996]]),
         "bending_safety_min": 1.3, "rating_design_torque": 536.5,
         "torque": ("bin", [53.65, 536.5])},
        coords={"bin": [0, 1], "member": ["pinion", "gear"]})
    (fail,) = _found(verdict(ds), "root_stress")
    assert fail.severity == "fail"
    assert fail.reason.startswith("gear: FE root safety S_F,FE 1.2996 below S_Fmin 1.3 ")
    lines = duty_cycle_lines(ds, "x.toml", None, ["root_stress"])
    assert "has the lowest FE root safety S_F,FE 1.2996, below S_Fmin 1.3" in lines[0]

def test_duty_root_fail_names_the_bins_misalignment():
    """Issue 71: the pc_hypoid_10x43's illustrative duty cycle FAILed its gear root at 357
    N·m (S_F,FE 1.29 < 1.3) where `ltca run` at 357 N·m reads 1.32: the bin carries the
    spectrum's deflection (ΔE 0.05, ΔP -0.03, ΔG 0.03 mm, ΔΣ 0.01°), the run the
    assembly's alone. The finding said "as `ltca run` fails it at that torque"; it now
    names the bin's misalignment (ΔΣ stored in rad, said in degrees: 0.01° exactly) and,
    in the bundled spectrum, that its deflections are made up."""
    import math

    ds = xr.Dataset(
        {"contact_safety_factor": ("member", [2.0, 2.0]),
         "root_stress_safety": (("bin", "member"), [[1.29, 1.5]]),
         "bending_safety_min": 1.3, "rating_design_torque": 357.0,
         "torque": ("bin", [357.0]),
         "delta_E": ("bin", [0.05], {"units": "mm"}),
         "delta_P": ("bin", [-0.03], {"units": "mm"}),
         "delta_G": ("bin", [0.03], {"units": "mm"}),
         "delta_Sigma": ("bin", [math.radians(0.01)], {"units": "rad"})},
        coords={"bin": [0], "member": ["pinion", "gear"]}, attrs={"illustrative": 1})
    (fail,) = [f for f in _found(verdict(ds), "root_stress") if f.severity == "fail"]
    assert "as `ltca run` fails it at that torque" not in fail.reason
    assert "ΔE 0.05, ΔP -0.03, ΔG 0.03 mm, ΔΣ 0.01 deg" in fail.reason, fail.reason
    assert "analyses the assembly's alone" in fail.reason and "made-up" in fail.reason
    ds.attrs["illustrative"] = 0  # a user's deflection table: no "made-up" clause
    (fail,) = [f for f in _found(verdict(ds), "root_stress") if f.severity == "fail"]
    assert "made-up" not in fail.reason and "ΔE 0.05" in fail.reason
    # the next step analyses the bin the duty cycle judged: its torque and misalignment
    # (ΔΣ in degrees, as ltca run's --dSigma takes it)
    from contact.commands.next_steps import duty_cycle_lines

    lines = duty_cycle_lines(ds, "x.toml", None, ["root_stress"])
    assert "at the bin's misalignment" in lines[0], lines
    assert lines[1] == ("    ltca run x.toml --torque 357 --dE 0.05 --dP -0.03 --dG 0.03 "
                        "--dSigma 0.01"), lines
