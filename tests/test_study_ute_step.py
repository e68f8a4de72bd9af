"""A study point's ``utca`` step: ``/utca`` of the UTE alone (issue 75, study101).

A study point's summary reads one number of the unloaded TCA, the UTE peak-to-peak, and
its LTCA the transitions M1, M2; the contact curves' flank points, normals and arms, the
separations, contact lines and paths of ``/utca`` are read by neither (≈ 9 ms of a
≈ 0.19 s point, docs/performance.md "A study point's UTCA without its curves").
The chain's ``utca="ute"`` step (:func:`contact.chain.utca_ute`) evaluates the same
curves without their flank fields: the identity relied on is that the flank fields are
evaluated *after* the curves' solve (:func:`contact.utca.contact_curves._curves_second_order`,
``flank_fields``), so the places, ease-off, UTE and transitions are the same floating-point
operations on the same inputs — equal **bit for bit**, not within a tolerance; and the
LTCA, which reads only the ease-off and the transitions, is then the same bit for bit too.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from contact.catalogue import resolve_case
from contact.chain import AnalysisChain, available_steps
from contact.ltca import LTCAOptions
from contact.pipeline import run_analysis
from contact.study import point_summary
from contact.study.engine import analyse_point
from contact.study.points import StudyInputs
from contact.utca.conjugate_map import clear_memos
from contact.utca.datasets import unloaded_cycle, unloaded_tca, utca_dataset, ute_dataset
from contact.utca.easeoff import ease_off

#: coarse, as tests/test_study.py (the identity does not depend on the resolution)
OPTIONS = LTCAOptions(rolls_per_cycle=8, segments=8, cycles=1)
TORQUE = 250.0


def _misaligned(case, d_e: float, d_p: float):
    mis = dataclasses.replace(case.misalignment, delta_E=case.misalignment.delta_E + d_e,
                              delta_P=case.misalignment.delta_P + d_p)
    return dataclasses.replace(case, misalignment=mis)


def _same(a, b) -> bool:
    """Equal bit for bit, NaN where NaN (the arrays' bytes)."""
    a, b = np.asarray(a), np.asarray(b)
    return a.shape == b.shape and a.dtype == b.dtype and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("d", [(0.03, -0.02), (-0.05, 0.04)])
def test_the_cycle_without_flank_fields_is_the_same_cycle(d):
    """unloaded_cycle(flank_fields=False): the curves' places, ease-off, gap, UTE, contact
    points and the cycle's rolls, envelope, transitions and UTE range equal the full
    cycle's bit for bit; only the flank fields are left out (None)."""
    eo = ease_off(_misaligned(resolve_case(None), *d))
    full = unloaded_cycle(eo)
    lean = unloaded_cycle(eo, flank_fields=False)
    assert lean.curves.position is None and lean.curves.normal is None
    assert lean.curves.normal_arm is None
    for name in ("target", "shift", "u", "v", "ease_off_angle", "gap", "ute", "contact_u",
                 "contact_v", "index"):
        assert _same(getattr(lean.curves, name), getattr(full.curves, name)), name
    for name in ("roll", "pairs", "envelope"):
        assert _same(getattr(lean, name), getattr(full, name)), name
    assert lean.transitions == full.transitions
    assert lean.transition_te == full.transition_te
    assert lean.te_range == full.te_range


def test_the_ute_dataset_holds_utca_datasets_values():
    """ute_dataset's variables are utca_dataset's of the same cycle, bit for bit, with the
    same attributes but ``curves``; unloaded_tca(curves=False) returns it and the same
    /easeoff."""
    case = _misaligned(resolve_case(None), 0.02, 0.01)
    eo = ease_off(case)
    full = utca_dataset(eo, unloaded_cycle(eo), case=case)
    lean = ute_dataset(eo, unloaded_cycle(eo, flank_fields=False), case=case)
    assert set(lean.data_vars) == {
        "unloaded_transmission_error", "pair_transmission_error", "active",
        "transition_roll", "transition_transmission_error",
        "peak_to_peak_transmission_error", "separation_threshold"}
    for name, var in lean.data_vars.items():
        assert _same(var.values, full[name].values), name
        assert var.variable.identical(full[name].variable), name  # dims, attributes
    assert {k: v for k, v in lean.attrs.items() if k != "curves"} == full.attrs
    eo_full, _ = unloaded_tca(case, easeoff=eo)
    eo_lean, ds = unloaded_tca(case, easeoff=eo, curves=False)
    assert "curve_position" not in ds and "curves" in ds.attrs
    assert eo_lean.identical(eo_full)


def test_the_ute_step_gives_the_same_ltca_and_summary():
    """run_analysis with the chain's ``utca="ute"`` step: /easeoff and /ltca identical to
    the default step's, /utca's common variables bit for bit; so the point summary is the
    same bit for bit; analyse_point (which runs the "ute" step) gives it too."""
    assert "ute" in available_steps()["utca"]
    case = resolve_case(None)
    d_e, d_p = 0.04, -0.02
    misaligned = _misaligned(case, d_e, d_p)
    kw = dict(options=OPTIONS, theoretical=False)
    # each from empty memos: the LTCA of the "ute" run builds the splines of the flank
    # fields itself (the default step's curves built them first) — from the same splines
    clear_memos()
    lean = run_analysis(misaligned, [TORQUE],
                        steps=AnalysisChain.contact_only().with_steps(utca="ute"), **kw)
    clear_memos()
    full = run_analysis(misaligned, [TORQUE], steps=AnalysisChain.contact_only(), **kw)
    assert lean["/easeoff"].to_dataset().identical(full["/easeoff"].to_dataset())
    ltca_full, ltca_lean = full["/ltca"].to_dataset(), lean["/ltca"].to_dataset()
    assert set(ltca_lean.variables) == set(ltca_full.variables)
    for name in ltca_full.variables:
        if ltca_full[name].attrs.get("units") == "s":  # wall-clock timings (solve_time)
            continue
        assert _same(ltca_lean[name].values, ltca_full[name].values), name
    utca = lean["/utca"].to_dataset()
    for name in utca.data_vars:
        assert _same(utca[name].values, full["/utca"][name].values), name
    ref = point_summary(full, case)
    got = point_summary(lean, case)
    for name in ref:
        assert _same(got[name], ref[name]), name
    res = analyse_point(StudyInputs(case=case, torque=(TORQUE,), options=OPTIONS), 0,
                        {"delta_E": misaligned.misalignment.delta_E,
                         "delta_P": misaligned.misalignment.delta_P})
    assert res.status == 0, res.reason
    for name in ref:
        np.testing.assert_array_equal(res.summary[name], ref[name], err_msg=name)
