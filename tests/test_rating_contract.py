"""The result contract of the load-capacity methods and the findings a reader trusts (issue 72).

* A method's result holds the contract (``pitting_safety``, ``bending_safety`` and their
  minima over torque and member, finite and > 0) or the registry refuses it in one
  sentence naming the method and the variable: a method giving S_H over ``torque`` only,
  one returning NaN safeties, one without the variables, one that raises.
* The verdict, the console and the report read only the contract: ANSI/AGMA 2003-D19's
  Annex E pair at 10 × its torque (162.70 → 1627 N·m at 1750 rpm) fails on its safeties
  through the API and through ``ltca run --rating-method agma2003`` — checked against the
  standard's own equations (s_wc/s_c, s_wt/s_t of the same dataset, Eq. 1M, 2M, 5M, 6M);
  a toy method written as docs/extending.md says (one module, one registry or entry-point
  entry) is judged with no other file touched; a ``/rating`` without the contract is
  "not checked", never passed.
* Findings: an edge share below :data:`EDGE_SHARE_MIN` is no finding; findings are
  ordered by severity and then by check; the flank-pressure finding promises no finite
  life where the rating exceeds the static strength; next steps at an overload put
  ``ltca rate`` before any ``ltca optimize``.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from contact.cli import main
from contact.load_capacity import METHODS, rate, register_method, unregister_method
from contact.load_capacity.contract import check_result, safeties
from contact.study.verdicts import EDGE_SHARE_MIN, verdict
from geometry.core.errors import ModelUnavailableError, PluginError

AGMA = "agma2003_d19_annex_e"
#: Annex E's pinion torque [N·m] (1440 lb in) and speed [rpm]; ten times the torque
ANNEX_E_TORQUE, ANNEX_E_SPEED = 162.70, 1750.0
QUICK = ["--no-root-stress", "--rolls-per-cycle", "4", "--segments", "8", "--no-progress"]


def capacity_method(case, torque, speed, *, flank=None, datasets=None, capacity=400.0):
    """A toy rating method after docs/extending.md: the safeties of a stated pinion torque
    capacity [N·m] — the contact stress grows as √T (Hertz), the root stress as T — so
    S_H = √(capacity/T) and S_F = capacity/T, minima 1 and 1.3."""
    t = np.asarray(torque, float)
    ratio = np.repeat((capacity / t)[:, None], 2, axis=1)
    return xr.Dataset(
        {"pitting_safety": (("torque", "member"), np.sqrt(ratio),
                            {"units": "1", "long_name": "safety against pitting",
                             "symbol": "S_H"}),
         "pitting_safety_min": ((), 1.0, {"units": "1", "long_name": "its minimum",
                                          "symbol": "S_Hmin"}),
         "bending_safety": (("torque", "member"), ratio,
                            {"units": "1", "long_name": "safety against bending",
                             "symbol": "S_F"}),
         "bending_safety_min": ((), 1.3, {"units": "1", "long_name": "its minimum",
                                          "symbol": "S_Fmin"})},
        coords={"torque": ("torque", t, {"units": "N m", "long_name": "pinion torque"}),
                "member": ("member", ["pinion", "gear"], {"long_name": "member"})},
        attrs={"title": "torque capacity (a toy)", "case": case.name})


@pytest.fixture
def toy():
    register_method("torque_capacity", capacity_method, title="torque capacity (a toy)",
                    source="this test", standard="a toy capacity",
                    worked_example="S_H = sqrt(400/T), S_F = 400/T by hand")
    yield "torque_capacity"
    if "torque_capacity" in METHODS:
        unregister_method("torque_capacity")


# --------------------------------------------------------------------------- refusals

def _bad(**change):
    def method(case, torque, speed, *, flank=None, datasets=None):
        ds = capacity_method(case, torque, speed)
        for name, value in change.items():
            ds = ds.drop_vars(name) if value is None else ds.assign({name: value})
        return ds
    return method


@pytest.mark.parametrize(("change", "words"), [
    # S_H over torque only: the issue's ValueError 'Dimensions {member} do not exist'
    ({"pitting_safety": ("torque", [1.2])},
     "pitting_safety has dims (torque), not (torque, member)"),
    ({"bending_safety": (("torque", "member"), [[np.nan, 1.0]])},
     "bending_safety holds nan (every value finite and > 0"),
    ({"pitting_safety_min": ((), -1.0)}, "pitting_safety_min holds -1.0"),
    ({"bending_safety": None}, "the variable bending_safety is missing"),
    ({"pitting_safety_min": (("torque",), [1.0])},
     "pitting_safety_min has dims (torque), not () or (member)"),
])
def test_a_result_breaking_the_contract_is_refused_naming_the_method(change, words):
    register_method("bad_method", _bad(**change), title="t", source="s")
    try:
        with pytest.raises(PluginError) as info:
            rate("iso10300_30_sample1", [300.0], 1200.0, method="bad_method")
    finally:
        unregister_method("bad_method")
    message = str(info.value)
    assert message.startswith("load-capacity method 'bad_method' breaks the result "
                              "contract: ") and words in message
    assert message.count(". ") == 0  # one sentence


def test_a_method_that_raises_is_named():
    def fails(case, torque, speed, **_):
        return {}["missing key"]

    register_method("raising", fails, title="t", source="s")
    try:
        with pytest.raises(PluginError, match="load-capacity method 'raising' raised "
                                              "KeyError: 'missing key'"):
            rate("iso10300_30_sample1", [300.0], 1200.0, method="raising")
    finally:
        unregister_method("raising")


def test_infinite_safety_only_where_nothing_is_transmitted():
    """+inf is the safety of zero torque (nothing transmitted), refused elsewhere; the
    torque dimension has as many entries as torques were asked for."""
    case = type("Case", (), {"name": "c"})()
    ds = capacity_method(case, [1.0, 200.0], 1000.0).assign_coords(torque=[0.0, 200.0])
    idle = ds["torque"] == 0.0
    check_result("m", ds.assign(bending_safety=ds["bending_safety"].where(~idle, np.inf)),
                 [0.0, 200.0])
    with pytest.raises(PluginError, match="inf only at zero torque"):
        check_result("m", ds.assign(bending_safety=ds["bending_safety"].where(idle, np.inf)),
                     [0.0, 200.0])
    with pytest.raises(PluginError, match="the torque dimension has 2 entries for the 3"):
        check_result("m", ds, [1.0, 2.0, 3.0])


def test_both_bundled_methods_hold_the_contract():
    """ISO 10300 and AGMA 2003 each give the contract; ISO's is S_H, S_F itself, AGMA's
    the standard's stress safety s_wc S_H/s_c, s_wt S_F/s_t against S_H, S_F (Eq. 1M,
    2M, 5M, 6M), whose ratio to the minimum is the dataset's own margin s_wc/s_c."""
    iso = rate("iso10300_30_sample1", [300.0], 1200.0)
    np.testing.assert_array_equal(iso["pitting_safety"].values, iso["S_H"].values)
    np.testing.assert_array_equal(iso["bending_safety"].values, iso["S_F"].values)
    assert iso.attrs["rating_worked_example"] == "ISO/TR 10300-30:2024 samples 1-3"
    agma = rate(AGMA, [ANNEX_E_TORQUE], ANNEX_E_SPEED, method="agma2003")
    tm = ("torque", "member")
    np.testing.assert_allclose(
        (agma["pitting_safety"] / agma["pitting_safety_min"]).transpose(*tm).values,
        (agma["s_wc"] / agma["s_c"]).transpose(*tm).values, rtol=1e-14)
    np.testing.assert_allclose(
        (agma["bending_safety"] / agma["bending_safety_min"]).transpose(*tm).values,
        (agma["s_wt"] / agma["s_t"]).transpose(*tm).values, rtol=1e-14)
    assert agma.attrs["rating_standard"] == "ANSI/AGMA 2003-D19"
    assert METHODS["iso10300"].companions == ("flash_temperature",)
    assert METHODS["agma2003"].companions == ()


# --------------------------------------------------------------------------- AGMA at 10 x

def test_agma2003_at_ten_times_annex_e_fails_through_the_api():
    """Annex E at 1627 N·m: the margins fall as 1/√10 (pitting, s_c ∝ √T) and 1/10
    (bending): 1.339 → 0.423, 1.531 → 0.153 — every safety below its minimum, each a
    fail finding naming the standard (the issue measured 'no rating finding')."""
    from contact import LTCAOptions, run_analysis

    torque = 10 * ANNEX_E_TORQUE
    tree = run_analysis(AGMA, [torque], options=LTCAOptions(rolls_per_cycle=4, segments=8),
                        geometry=False, root_stress=False, mesh_interface=False,
                        steps={"load_capacity": "agma2003"})
    rt = tree["rating"].to_dataset()
    assert rt.attrs["rating_method"] == "agma2003"
    assert "flash_temperature" not in tree["rating"].children  # ISO 10300's companion
    one = rate(AGMA, [ANNEX_E_TORQUE], ANNEX_E_SPEED, method="agma2003")
    # hand check: s_c ∝ √T (Eq. 1M), s_t ∝ T (Eq. 5M); the factors do not depend on T
    np.testing.assert_allclose(rt["safety_pitting"].values,
                               one["safety_pitting"].values / np.sqrt(10), rtol=1e-12)
    np.testing.assert_allclose(rt["safety_bending"].values,
                               one["safety_bending"].values / 10, rtol=1e-12)
    v = verdict(tree)
    assert v.severity == "fail" and "rating" in v.checks
    rating = [f for f in v.findings if f.check == "rating"]
    assert len(rating) == 4 and all(f.severity == "fail" for f in rating)
    assert rating[0].reason.startswith("ANSI/AGMA 2003-D19 pitting safety s_wc S_H/s_c 0.42 "
                                       "of the pinion at 1627 N·m below S_H 1")


def test_agma2003_at_ten_times_annex_e_fails_through_ltca_run(tmp_path, capsys):
    out = tmp_path / "agma.nc"
    assert main(["run", AGMA, "--torque", "1627", "--rating-method", "agma2003", "-o",
                 str(out), *QUICK]) == 0
    text = capsys.readouterr().out
    assert "VERDICT (analysis): FAIL" in text
    assert "fail: ANSI/AGMA 2003-D19 bending safety s_wt S_F/s_t 0.15 of the pinion" in text
    assert "ANSI/AGMA 2003-D19 rating beside the LTCA (method agma2003" in text
    # the first next step answers the overload: ltca rate before any ltca optimize
    steps = [ln for ln in text.splitlines() if ln.startswith("    ltca ")]
    assert steps[0] == f"    ltca rate {AGMA} --torque 1627 --method agma2003 --speed 1750"
    assert any(s.startswith("    ltca optimize") for s in steps[1:])
    # ltca report reads the run, and recognises a rating file of the method
    rating = tmp_path / "rating.nc"
    assert main(["rate", AGMA, "--method", "agma2003", "--torque", "1627", "-o",
                 str(rating)]) == 0
    capsys.readouterr()
    assert main(["report", str(rating), "-o", str(tmp_path / "r.html")]) == 2
    err = capsys.readouterr().err
    assert f"{str(rating)!r} is a load-capacity rating file, written by `ltca rate`" in err


def test_an_unknown_rating_method_is_refused_before_the_work(capsys):
    assert main(["run", "--rating-method", "agma2001", *QUICK]) == 2
    err = capsys.readouterr().err
    assert "--rating-method: unknown load-capacity rating method 'agma2001'" in err
    assert "agma2003, iso10300" in err


def test_a_case_chooses_its_method(tmp_path):
    """``[rating] method = "agma2003"``: run_analysis and ltca rate rate by it unless the
    steps name another; an unknown name is refused naming the field."""
    import tomllib

    from contact import LTCAOptions, resolve_case, run_analysis
    from contact.load_capacity.methods import case_method
    from geometry.case import case_from_dict

    doc = tomllib.loads(resolve_case(AGMA).to_toml())
    doc["rating"]["method"] = "agma2003"
    case = case_from_dict(doc)
    assert case_method(case) == "agma2003"
    opts = LTCAOptions(rolls_per_cycle=4, segments=8)
    tree = run_analysis(case, [ANNEX_E_TORQUE], options=opts, geometry=False,
                        root_stress=False, mesh_interface=False)
    assert tree["rating"].attrs["rating_method"] == "agma2003"
    iso = run_analysis(case, [ANNEX_E_TORQUE], options=opts, geometry=False,
                       root_stress=False, mesh_interface=False,
                       steps={"load_capacity": "iso10300"})
    assert iso["rating"].attrs["rating_method"] == "iso10300"
    doc["rating"]["method"] = "agma2001"
    with pytest.raises(ModelUnavailableError, match=r"rating\.method: unknown"):
        case_method(case_from_dict(doc))


# --------------------------------------------------------------------------- the toy

def test_a_toy_method_after_the_docs_is_judged_by_the_verdict(toy):
    """Registered from outside (no toolkit file touched): at 500 N·m against its 400 N·m
    capacity, S_H = √0.8 = 0.894 < 1 and S_F = 0.8 < 1.3 (by hand) fail; at 200 N·m,
    √2 = 1.414 and 2.0 pass."""
    from contact import LTCAOptions, run_analysis

    tree = run_analysis(None, [200.0, 500.0],
                        options=LTCAOptions(rolls_per_cycle=4, segments=8), geometry=False,
                        root_stress=False, mesh_interface=False,
                        steps={"load_capacity": toy})
    rating = [f for f in verdict(tree).findings if f.check == "rating"]
    assert [f.reason for f in rating] == [
        "a toy capacity pitting safety S_H 0.89 of the pinion at 500 N·m below S_Hmin 1",
        "a toy capacity pitting safety S_H 0.89 of the gear at 500 N·m below S_Hmin 1",
        "a toy capacity bending safety S_F 0.80 of the pinion at 500 N·m below S_Fmin 1.3",
        "a toy capacity bending safety S_F 0.80 of the gear at 500 N·m below S_Fmin 1.3"]
    assert all(f.severity == "fail" for f in rating)


def test_a_toy_method_from_an_entry_point(monkeypatch):
    """An installed distribution's method (entry-point group hypoid_ltca.rating_methods)
    enters the shared registry class under its entry's name; one that is no method is
    left out with a warning."""
    from contact.load_capacity import methods
    from geometry.core import registries

    group = "hypoid_ltca.rating_methods_of_this_test"
    monkeypatch.setattr(registries, "entry_point_objects",
                        lambda g: {"ep_capacity": capacity_method, "ep_broken": 3}
                        if g == group else {})
    reg = registries.Registry("load-capacity rating method", group, (),
                              name_of=lambda m: m.name, adapt=methods._adapt)
    assert list(reg) == ["ep_capacity"]
    assert reg["ep_capacity"].function is capacity_method
    assert reg["ep_capacity"].title.startswith("A toy rating method after docs/extending.md")
    with pytest.raises(ModelUnavailableError, match="available: ep_capacity"):
        reg.entry("nothing")
    reg.unregister("ep_capacity")  # for this process, as a user's registration
    assert "ep_capacity" not in reg
    registries._group_objects.cache_clear()


def test_a_rating_without_the_contract_is_not_checked_never_passed():
    lt = xr.Dataset({"pressure_max_flank": ("torque", [700.0])}, coords={"torque": [50.0]})
    rt = xr.Dataset({"F_mt1": ("torque", [1.0])}, coords={"torque": [50.0]},
                    attrs={"rating_method": "forces_only"})
    tree = xr.DataTree.from_dict({"/ltca": lt, "/rating": rt})
    v = verdict(tree)
    assert "rating" not in v.checks
    assert dict(v.unchecked)["rating"] == (
        "/rating of forces_only lacks the result contract (pitting_safety, "
        "pitting_safety_min, bending_safety, bending_safety_min)")
    assert any(ln.startswith("  not checked: rating (/rating of forces_only")
               for ln in v.lines())
    assert safeties(rt)[0] is None


# --------------------------------------------------------------------------- findings

def _edge_tree(share: float) -> xr.DataTree:
    """One roll, a curve segment and a gear-heel edge carrying ``share`` of the torque."""
    force = np.array([[[[1.0 - share, share]]]])
    lt = xr.Dataset({"pressure_max_flank": ("torque", [700.0]),
                     "force": (("torque", "roll", "pair", "segment"), force),
                     "moment_arm": (("roll", "pair", "segment"), np.ones((1, 1, 2)))},
                    coords={"torque": [50.0],
                            "segment_kind": ("segment", ["curve", "gear_heel"])})
    return xr.DataTree.from_dict({"/ltca": lt})


def test_an_edge_share_below_the_threshold_is_no_finding():
    """0.0034 % (the issue's line) is no finding; at the threshold 0.05 % it is."""
    assert verdict(_edge_tree(3.4e-5)).findings == ()
    assert verdict(_edge_tree(0.9999 * EDGE_SHARE_MIN)).findings == ()
    (f,) = verdict(_edge_tree(EDGE_SHARE_MIN)).findings
    assert f.reason == "at 50 N·m: edge contact carries 0.05 % of the torque (gear heel 0.05 %)"


def _overloaded(flank_pressure: float) -> xr.DataTree:
    from contact.load_capacity.durability import sn_curves  # noqa: F401 (material table)

    lt = xr.Dataset({"pressure_max_flank": ("torque", [flank_pressure])},
                    coords={"torque": [2000.0]},
                    attrs={"material_pinion": "case_carburised_steel",
                           "material_gear": "case_carburised_steel"})
    rt = xr.Dataset({"pitting_safety": (("torque", "member"), [[0.5, 0.5]],
                                        {"symbol": "S_H", "life_factor": "Z_NT"}),
                     "pitting_safety_min": ((), 1.0, {"symbol": "S_Hmin"}),
                     "bending_safety": (("torque", "member"), [[0.4, 0.4]],
                                        {"symbol": "S_F", "life_factor": "Y_NT"}),
                     "bending_safety_min": ((), 1.3, {"symbol": "S_Fmin"}),
                     "load_cycles": ("member", [np.nan, np.nan]),
                     "permissible_cycles_pitting": (("torque", "member"), [[0.0, 0.0]]),
                     "permissible_cycles_bending": (("torque", "member"), [[0.0, 0.0]]),
                     "design_torque": ((), 500.0), "pinion_speed": ((), 1500.0)},
                    coords={"torque": [2000.0], "member": ["pinion", "gear"]},
                    attrs={"rating_method": "iso10300", "rating_standard": "ISO 10300"})
    return xr.DataTree.from_dict({"/ltca": lt, "/rating": rt})


def test_findings_at_an_overload_do_not_contradict_each_other():
    """At 4 × capacity the rating is beyond the static strength: the flank pressure (here
    between σ_Hlim 1500 and the static 2400 MPa) no longer promises 'a finite life at this
    torque', and the rating's clause says one thing."""
    v = verdict(_overloaded(2000.0))
    text = [f.reason for f in v.findings]
    assert not any("a finite life at this torque" in r for r in text)
    assert not any("raise it" in r for r in text)
    assert text[0] == ("ISO 10300 pitting safety S_H 0.50 of the pinion at 2000 N·m below "
                       "S_Hmin 1: beyond the static strength, no load cycles are permissible")
    flank = next(f for f in v.findings if f.check == "flank_pressure")
    assert flank.severity == "attention" and "exceeds the static strength" in flank.reason
    # ordered by severity, then check: the four rating fails before the flank's attention
    assert [f.check for f in v.findings] == ["rating"] * 4 + ["flank_pressure"]


def test_next_steps_answer_an_overload_with_ltca_rate_first():
    from contact import resolve_case
    from contact.commands.run import next_steps

    tree = _overloaded(3000.0)  # flank above its static strength: a bearing check too
    lines = next_steps(tree, resolve_case(None), None, None)
    commands = [ln for ln in lines if ln.startswith("    ltca ")]
    assert commands[0].startswith("    ltca rate kolivand2009_fm_11x41_reference --torque "
                                  "2000 --speed 1500")
    assert commands[-1].startswith("    ltca optimize")


def test_ltca_rate_prints_every_factor(capsys):
    """σ_Hlim, σ_Flim, Z_K, Z_W, Z_X, Y_X … each printed: σ_HP is their product
    (ISO 10300-2 cl. 6: 1500 × Z_NT Z_X Z_L Z_v Z_R Z_W Z_K Z_Hyp = 1617.8 for the TR's
    sample 1, whose printed σ_HP is 1617.8)."""
    assert main(["rate", "iso10300_30_sample1", "--torque", "300", "--speed", "1200"]) == 0
    text = capsys.readouterr().out
    rows = {ln.split("  ")[0].strip(): ln.split()[-1] for ln in text.splitlines()
            if ln[:1].isalpha() and "  " in ln}
    for label in ("sigma_Hlim [MPa]", "sigma_Flim [MPa]", "Z_K", "Z_W", "Z_X", "Y_X", "Y_ST",
                  "Z_L", "Z_v", "Z_R", "Z_NT", "Z_Hyp", "S_H,min", "S_F,min"):
        assert label in rows, label
    product = 1500.0
    for label in ("Z_NT", "Z_X", "Z_L", "Z_v", "Z_R", "Z_W", "Z_K", "Z_Hyp"):
        product *= float(rows[label])
    # each factor printed to 3 decimals: 8 roundings of ≤ 5e-4 relative each
    assert product == pytest.approx(float(rows["sigma_HP [MPa]"]), rel=8 * 5e-4)
    assert "K_A 1.100" in text and "K_Hbeta-be 1.100" in text


def test_ltca_report_names_the_file_whose_group_is_missing(tmp_path, capsys):
    """A file that is neither an analysis nor a duty cycle nor another command's file:
    the refusal names it and the groups it has."""
    path = tmp_path / "other.nc"
    xr.DataTree.from_dict({"/": xr.Dataset(attrs={"title": "something else"}),
                           "/stuff": xr.Dataset({"x": ("i", [1.0])})}).to_netcdf(path)
    assert main(["report", str(path), "-o", str(tmp_path / "r.html")]) == 2
    err = capsys.readouterr().err
    assert f"{str(path)!r} has no /easeoff or /duty_cycle group (groups: /stuff)" in err


def test_no_finite_life_where_the_ltca_flank_exceeds_the_static_strength():
    """At a torque whose LTCA flank peak is above the static strength (2400 MPa), the
    rating's pitting finding offers no load cycles (they would contradict 'no life at this
    torque'): a fail with the LTCA's finding named, even above the design torque."""
    tree = _overloaded(3000.0)
    rt = tree["rating"].to_dataset().assign(
        permissible_cycles_pitting=(("torque", "member"), [[2.0e7, 2.0e7]]))
    tree = xr.DataTree.from_dict({"/ltca": tree["ltca"].to_dataset(), "/rating": rt})
    v = verdict(tree)
    pitting = [f for f in v.findings if f.check == "rating" and "pitting" in f.reason]
    assert [f.severity for f in pitting] == ["fail", "fail"]
    assert all(f.reason.endswith("(rated at long life, Z_NT 1; the LTCA's flank peak at "
                                 "this torque exceeds the static strength: its finding)")
               for f in pitting)
    assert not any("permissible for" in f.reason for f in v.findings)


def test_the_rate_command_ltca_run_names_rates_the_side_it_rated(capsys):
    """`ltca run --flank coast` rates the coast side; the `ltca rate` command its lines
    name says --flank coast, and that command rates the same side (same S_H)."""
    from contact.commands.rating_text import rating_lines

    coast = rate("iso10300_30_sample1", [300.0], 1200.0, flank="coast")
    assert coast.attrs["side"] == "coast"
    lt = xr.Dataset({"pressure_max_flank": ("torque", [1500.0])}, coords={"torque": [300.0]})
    tree = xr.DataTree.from_dict({"/ltca": lt, "/rating": coast})
    last = rating_lines(tree, case_arg="iso10300_30_sample1")[-1]
    command = last[last.index("`") + 1:last.rindex("`")]
    assert command.endswith("--speed 1200 --flank coast")
    assert main(command.split()[1:]) == 0
    text = capsys.readouterr().out
    assert text.startswith("ISO 10300 Method B1: iso10300_30_sample1 (coast side)")
    s_h = float(coast["S_H"].values[0, 0])
    assert any(ln.startswith("S_H ") and f"{s_h:.3f}" in ln for ln in text.splitlines())
