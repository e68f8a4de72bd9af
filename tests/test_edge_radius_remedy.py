"""The cutter edge radius as ``ltca run``'s root remedy (issue 71, branch remedy84;
:mod:`contact.study.edge_radius_remedy`, :mod:`contact.commands.run_remedy`).

The verdicts are stated (no analysis runs): what is tested is the offer (a root finding,
a face-milled case with a ``[design]`` table, a largest radius above the case's), the
case written with it, the keep rule (root improved by ROOT_GAIN, no met criterion lost)
and the least S_F,FE recomputed from its definition. The whole command on the truck
hypoid 8×47 is measured in docs/verdicts.md ("The edge radius as ltca run's root remedy").
"""

from __future__ import annotations

import math
import shlex
import tomllib

import numpy as np
import pytest
import xarray as xr

import contact.study.edge_radius_remedy as er
import contact.study.verdicts
from contact.catalogue import resolve_case
from contact.cli import build_parser
from contact.commands.run import next_steps
from contact.commands.run_remedy import apply_remedy
from contact.study.verdicts import Finding, Verdict
from geometry.case import case_from_dict
from geometry.core.errors import InputError

FM = "kolivand2009_fm_11x41_reference"
FH = "kolivand2009_fh_12x41_reference"
ROOT_FAIL = ("fail", "root_stress", "FE root stress of the gear at 250 N·m: 900 MPa × K_A 1 "
             "× K_v 1.01 = 909 MPa against σ_FP 850 MPa (ISO 10300-3 …): S_F 0.94 below "
             "S_Fmin 1.3")


def _verdict(*findings, checks=("rating", "root_stress", "lte", "edge_contact")) -> Verdict:
    return Verdict("analysis", tuple(Finding(*f) for f in findings), tuple(checks))


def test_the_remedy_is_the_largest_edge_radius_of_the_case_design():
    """The bundled 11×41 (edge radius 0.813 mm on every blade): the largest its pinion's
    point width allows is 0.97 mm (docs/own_gear_set.md's table of root83: pinion W
    limit 0.973, clearance 1.570, gear 1.593 mm), 1.19 × the case's, above EDGE_GAIN."""
    case = resolve_case(FM)
    remedy, why = er.edge_radius_offer(case, _verdict(ROOT_FAIL))
    assert why == "" and remedy is not None
    assert remedy.current == 0.813
    assert remedy.radius == 0.97  # rounded down to 0.01 mm (EDGE_RADIUS_STEP), exact
    assert remedy.limit.binding == "pinion point width"
    assert remedy.limit.pinion_width == pytest.approx(0.973, abs=5e-4)  # 3 decimals printed
    assert "0.813 -> 0.97 mm" in remedy.text()


@pytest.mark.parametrize("case_name, findings, said", [
    (FM, (), "no root below its minimum"),
    (FM, (("attention", "root_stress", "root stress of the gear at 250 N·m not checked: "
           "FE failed"),), "no root below its minimum"),
    (FM, (("attention", "root_stress", "root stress not computed: the FE model failed; the "
           "bending side rests on the ISO 10300 rating alone"),), "no root below"),
    (FH, (ROOT_FAIL,), "face-hobbed"),
])
def test_no_remedy_without_a_root_finding_or_on_a_face_hobbed_case(case_name, findings, said):
    remedy, why = er.edge_radius_offer(resolve_case(case_name), _verdict(*findings))
    assert remedy is None and said in why


def test_no_remedy_where_the_case_has_the_largest_already():
    case = er.with_edge_radius(resolve_case(FM), 0.95)  # 0.97 < 1.05 × 0.95
    remedy, why = er.edge_radius_offer(case, _verdict(ROOT_FAIL))
    assert remedy is None and "within 5%" in why and "0.97" in why


def test_the_case_written_with_the_edge_radius():
    """Every blade's edge radius changed, nothing else of the teeth; the TOML text reads
    back to the same case (the schema's round trip)."""
    case = resolve_case(FM)
    new = er.with_edge_radius(case, 0.97)
    for m in ("pinion", "gear"):
        for f in ("concave", "convex"):
            old_tool, new_tool = case.member(m).flank(f), new.member(m).flank(f)
            assert new_tool.blade.edge_radius == 0.97
            assert new_tool.machine == old_tool.machine
            assert new_tool.blade.point_radius == old_tool.blade.point_radius
    assert new.name == f"{case.name}_edge_radius" and "0.813 -> 0.97 mm" in new.source
    back = case_from_dict(tomllib.loads(new.to_toml()))
    assert back.gear.concave.blade.edge_radius == 0.97
    assert back.to_toml() == new.to_toml()
    with pytest.raises(InputError, match="edge_radius"):
        er.with_edge_radius(case, math.nan)
    with pytest.raises(InputError, match="edge_radius"):
        er.with_edge_radius(case, 0.0)


def test_a_rating_table_that_gives_the_tool_radius_follows():
    import dataclasses
    from types import MappingProxyType

    case = resolve_case(FM)
    rated = dataclasses.replace(case, extra=MappingProxyType(
        {**case.extra, "rating": {**case.extra["rating"], "edge_radius": [0.813, 0.813]}}))
    assert er.with_edge_radius(rated, 0.97).extra["rating"]["edge_radius"] == [0.97, 0.97]
    assert "edge_radius" not in er.with_edge_radius(case, 0.97).extra["rating"]


def test_kept_only_where_the_root_improves_and_nothing_met_is_lost():
    before = _verdict(ROOT_FAIL, ("attention", "edge_contact", "edge 3 %"))
    same = _verdict(ROOT_FAIL, ("attention", "edge_contact", "edge 3.1 %"))
    kept = er.judged_remedy(before, same, 0.94, 1.05)
    assert kept.kept and "0.940 -> 1.050" in kept.reason
    assert "still below its minimum (fail)" in kept.reason
    held = er.judged_remedy(before, _verdict(("attention", "edge_contact", "e")), 0.94, 1.4)
    assert held.kept and "still below" not in held.reason
    # a rise below ROOT_GAIN (0.005) is no improvement
    assert not er.judged_remedy(before, same, 0.94, 0.944).kept
    # a met criterion (lte: no finding before) with a finding after is lost
    lost = er.judged_remedy(before, _verdict(ROOT_FAIL, ("attention", "edge_contact", "e"),
                                             ("attention", "lte", "LTE 61 urad")), 0.94, 1.2)
    assert not lost.kept and lost.lost == ("lte",) and "lte is worse" in lost.reason
    # an attention that fails after, and a check no longer made, are lost too
    worse = er.judged_remedy(before, _verdict(ROOT_FAIL, ("fail", "edge_contact", "e"),
                                              checks=("rating", "root_stress", "edge_contact")),
                             0.94, 1.2)
    assert worse.lost == ("lte", "edge_contact")
    assert not er.judged_remedy(before, same, math.nan, 1.2).kept


def _tree(root, torques=(250.0, 500.0), k_v=(1.01, 1.02), fp=(820.0, 850.0), lte=(20., 30.)):
    members = ["pinion", "gear"]
    lt = xr.Dataset({"root_stress_max": (("torque", "member"), np.asarray(root, float)),
                     "lte_peak_to_peak": ("torque", np.asarray(lte)),
                     "pressure_max_flank": ("torque", np.asarray([1200.0, 1600.0]))},
                    coords={"torque": list(torques), "member": members})
    rt = xr.Dataset({"sigma_FP": ("member", np.asarray(fp)), "K_A": 1.25,
                     "K_v": ("torque", np.asarray(k_v)), "S_Fmin": 1.3,
                     "safety_S_F": (("torque", "member"), np.ones((2, 2))),
                     "safety_S_H": (("torque", "member"), np.ones((2, 2)))},
                    coords={"torque": list(torques), "member": members})
    return xr.DataTree.from_dict({"/ltca": lt, "/rating": rt})


def test_the_least_root_safety_from_its_definition(monkeypatch):
    """S_F,FE = σ_FP / (σ_FE,max K_A K_v) (ISO 10300-3 with the FE stress): by hand, the
    gear at 500 N·m, 850 / (700 × 1.25 × 1.02) = 0.95238; to 1e-12 (one division)."""
    monkeypatch.setattr("contact.study.verdict_checks.has_iso_rating", lambda rt: True)
    sf, where = er.least_root_safety(_tree([[300.0, 350.0], [600.0, 700.0]]))
    assert sf == pytest.approx(850.0 / (700.0 * 1.25 * 1.02), rel=1e-12)
    assert where == "gear at 500 N m"
    assert math.isnan(er.least_root_safety(xr.DataTree.from_dict({"/ltca": xr.Dataset()}))[0])


def test_apply_remedy_analyses_the_remedied_case_and_judges_it(monkeypatch):
    """The analysis is a stand-in: the remedied case (every blade 0.97 mm) is the one
    analysed, and the comparison prints the numbers of both trees."""
    monkeypatch.setattr("contact.study.verdict_checks.has_iso_rating", lambda rt: True)
    before, after = _tree([[300.0, 350.0], [600.0, 700.0]]), _tree([[290.0, 320.0],
                                                                    [570.0, 620.0]])
    verdicts = {id(before): _verdict(ROOT_FAIL), id(after): _verdict(ROOT_FAIL)}
    monkeypatch.setattr(contact.study.verdicts, "verdict", lambda t: verdicts[id(t)])
    seen = []
    done = apply_remedy(resolve_case(FM), before, lambda c: seen.append(c) or after)
    assert [c.gear.convex.blade.edge_radius for c in seen] == [0.97]
    assert done.kept and done.case is seen[0] and done.tree is after
    text = "\n".join(done.lines)
    assert "gear at 500 N m: 700 -> 620 MPa (-11.4 %)" in text  # 620/700 - 1 = -11.43 %
    assert "S_F,FE 0.952 -> 1.075" in text  # 850/(620 × 1.25 × 1.02) = 1.0753
    assert "kept: the root improves" in text
    # the remedied case worse elsewhere: not kept, and the finding that lost it printed
    verdicts[id(after)] = _verdict(ROOT_FAIL, ("fail", "lte", "LTE 130 urad"))
    done = apply_remedy(resolve_case(FM), before, lambda c: after)
    assert not done.kept and "fail: LTE 130 urad" in "\n".join(done.lines)
    # nothing offered: said, nothing analysed
    verdicts[id(before)] = _verdict()
    done = apply_remedy(resolve_case(FM), before, lambda c: pytest.fail("analysed"))
    assert done.lines == ["--apply-remedy: no remedy applied: the verdict finds no root "
                          "below its minimum"]


@pytest.mark.parametrize("severity", ["fail", "attention"])
def test_the_verdict_offers_the_edge_radius_with_a_command_to_paste(monkeypatch, severity):
    v = _verdict((severity, *ROOT_FAIL[1:]))
    monkeypatch.setattr(contact.study.verdicts, "verdict", lambda result: v)
    tree = xr.DataTree.from_dict({"/ltca": xr.Dataset(coords={"torque": [50.0, 250.0]})})
    lines = next_steps(tree, resolve_case(FM), "my.toml", None)
    assert any("next, the root: edge radius 0.813 -> 0.97 mm" in ln for ln in lines)
    command = [shlex.split(ln) for ln in lines if ln.startswith("    ltca run")]
    assert command == [["ltca", "run", "my.toml", "--flank", "drive", "--torque", "50", "250",
                        "--apply-remedy"]]
    args = build_parser().parse_args(command[0][1:])
    assert args.apply_remedy and args.torque == [50.0, 250.0]
    # --apply-remedy given: applied, not offered again
    assert not any("edge radius" in ln for ln in next_steps(tree, resolve_case(FM), "my.toml",
                                                            None, remedy=False))
