"""``ltca duty-cycle``'s static check judges the flank peak ``ltca run``'s verdict judges
(issue 71): each bin's ``flank_peak_pressure``, the bin's ``pressure_max_flank`` without
the contact curves shorter than their own Hertz contact width 2b that carry <= 1 % of
their roll's load (:func:`contact.ltca.summary.flank_peak`: a curve clipped into a flank
corner, µm long, whose load per length is a ratio of vanishing numbers), against the
bin's static contact strength. Before, a duty cycle could FAIL on a corner clip that
``ltca run`` and ``ltca synthesize`` do not count.

Synthetic bins, no analysis: one bin's ``/ltca``-like dataset (the pattern of
tests/test_verdict_corner.py) gives the bin's variables through ``flank_peak`` (the call
:func:`contact.study.duty_cycle.analyse_bin` makes; tests/test_duty_cycle.py checks it
against a real bin), :func:`contact.study.duty_cycle.duty_cycle_result` the cycle on the
default case's rating. The pressures are put at 0.5× and 1.3× the bin's static strength
(σ_Hlim × Z_NT on the rating), far from it on both sides, so the verdict's side does not
hang on the strength's last digit; the expected words are the numbers put in.
"""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr

from contact.catalogue import resolve_case
from contact.ltca import LTCAOptions
from contact.ltca.summary import flank_peak
from contact.plots.duty_report import render_duty_report
from contact.study.duty_cycle import DutyInputs, bin_envelopes, duty_cycle_result
from contact.study.duty_cycle_inputs import DutyCycle
from contact.study.verdicts import verdict

TORQUE, SPEED = 250.0, 1500.0


@pytest.fixture(scope="module")
def case():
    return resolve_case(None)


@pytest.fixture(scope="module")
def strength(case) -> float:
    """The bin's static contact strength of the weaker member [MPa], as the cycle writes
    it (a bin with no load at all: nothing above it)."""
    out = _cycle(case, 100.0, 100.0)
    return float(out["contact_static_strength"].values.min())


def _ltca(p_long: float, p_corner: float) -> xr.Dataset:
    """One torque, one roll, two pairs: pair 0 a line contact (4 segments of 2 mm, half
    width 0.3 mm, 1000 N each) at ``p_long``, pair 1 a corner clip (4 segments of 1e-5 mm,
    half width 0.44 mm, 0.01 N each: 1e-5 of the roll's load) at ``p_corner``."""
    dims = ("torque", "roll", "pair", "segment")
    p, b, f = np.zeros((1, 1, 2, 4)), np.zeros((1, 1, 2, 4)), np.zeros((1, 1, 2, 4))
    length = np.zeros((1, 2, 4))
    p[0, 0, 0], b[0, 0, 0], f[0, 0, 0], length[0, 0] = p_long, 0.3, 1000.0, 2.0
    p[0, 0, 1], b[0, 0, 1], f[0, 0, 1], length[0, 1] = p_corner, 0.44, 0.01, 1e-5
    return xr.Dataset(
        {"pressure_max": (dims, p), "half_width": (dims, b), "force": (dims, f),
         "segment_length": (dims[1:], length),
         "pressure_max_flank": (("torque",), [max(p_long, p_corner)])},
        coords={"torque": [TORQUE], "segment_kind": ("segment", np.array(["curve"] * 4))})


def _placed(p_long: float, p_corner: float) -> xr.Dataset:
    """:func:`_ltca` with its segments on a 3×3 gear grid: the line contact's 4 segments
    on the middle node (u, v 0.5), the corner clip's on the toe-tip node (u 0, v 1)."""
    lt = _ltca(p_long, p_corner)
    su, sv = np.zeros((1, 2, 4)), np.zeros((1, 2, 4))
    su[0, 0], sv[0, 0] = 0.5, 0.5
    su[0, 1], sv[0, 1] = 0.0, 1.0
    grid = np.linspace(0.0, 1.0, 3)
    return lt.assign({"segment_u": (("roll", "pair", "segment"), su),
                      "segment_v": (("roll", "pair", "segment"), sv)}).assign_coords(
        u=grid, v=grid)


def _cycle(case, p_long: float, p_corner: float) -> xr.Dataset:
    """The /duty_cycle of one bin whose flank reads these peaks (the corner clip's on the
    grid's toe-tip node, the line contact's in the middle), its envelopes as
    :func:`contact.study.duty_cycle.analyse_bin` makes them."""
    lt = _placed(p_long, p_corner)
    fp = flank_peak(lt)
    u = v = np.linspace(0.0, 1.0, 3)
    line, corner, edge = bin_envelopes(lt, fp)
    env = line[None]
    one = ("bin",)
    bins = xr.Dataset(
        {"lte_mean": (one, [10.0]), "lte_peak_to_peak": (one, [5.0]),
         "pressure_max_flank": (one, fp.dataset), "pressure_max_edge": (one, [0.0]),
         "flank_peak_pressure": (one, fp.pressure),
         "flank_corner_curves": (one, fp.corner_curves),
         "edge_load_share": (one, [0.0]), "plastic_load_share": (one, [0.0]),
         "efficiency": (one, [0.99]), "power_loss": (one, [100.0]),
         "lte_harmonics": (("bin", "harmonic"), [[1.0, 0.5, 0.2]]),
         "pressure_envelope": (("bin", "u", "v"), env),
         "edge_pressure_envelope": (("bin", "u", "v"), edge[None]),
         "corner_pressure_envelope": (("bin", "u", "v"), corner[None]),
         "plausibility": (one, np.zeros(1, np.int8)),
         "status": (one, np.zeros(1, np.int8)), "reason": (one, np.array([""], object))},
        coords={"u": u, "v": v})
    duty = DutyCycle(torque=[TORQUE], pinion_speed=[SPEED], revolutions=[1e3])
    return duty_cycle_result(DutyInputs(case, duty, LTCAOptions()), bins)


def _static(v) -> list:
    return [f for f in v.findings if f.check == "static"]


def test_a_corner_clip_above_the_static_strength_fails_no_duty_cycle(case, strength):
    """Only the corner clip above the static strength: no static finding, the dataset's
    ``contact_static_limit_exceeded`` 0, and a note saying what was left out — in the
    verdict's lines and on the duty report's page."""
    line, corner = 0.5 * strength, 1.3 * strength
    out = _cycle(case, line, corner)
    assert float(out["pressure_max_flank"][0]) == corner  # as written: every curve
    assert float(out["flank_peak_pressure"][0]) == line
    assert int(out["flank_corner_curves"][0]) == 1
    assert out.attrs["contact_static_limit_exceeded"] == 0
    v = verdict(out)
    assert "static" in v.checks and not _static(v)
    (note,) = v.notes
    assert note.startswith(f"static: flank peak pressure {line:.0f} MPa in bin 0 (250 N·m), "
                           f"within the static contact strength {strength:.0f} MPa; "
                           f"/duty_cycle pressure_max_flank reads {corner:.0f} MPa with 1 "
                           "contact curve shorter than its Hertz contact width 2b")
    assert f"  note: {note}" in v.lines()
    page = render_duty_report(out, figures=False)
    assert page.count('<p class="note">Note: static: flank peak pressure') == 1
    assert "Hertz contact width 2b" in page


def test_a_line_contact_above_the_static_strength_fails_as_before(case, strength):
    """A long curve above the static strength fails the static check, naming the bin, the
    peak and the strength; with a corner clip higher still the finding also names the
    dataset's number and the curve left out (the wording of ltca run's verdict)."""
    line = 1.3 * strength
    out = _cycle(case, line, 0.0)
    assert out.attrs["contact_static_limit_exceeded"] == 1
    v = verdict(out)
    (f,) = _static(v)
    assert (f.severity, v.severity) == ("fail", "fail")
    assert f.reason.startswith(f"flank peak pressure {line:.0f} MPa in bin 0 (250 N·m) above "
                               f"the static contact strength {strength:.0f} MPa")
    assert "pressure_max_flank reads" not in f.reason and not v.notes
    corner = 1.6 * strength
    v = verdict(_cycle(case, line, corner))
    (f,) = _static(v)
    assert (f"flank peak pressure {line:.0f} MPa in bin 0 (250 N·m) (/duty_cycle "
            f"pressure_max_flank reads {corner:.0f} MPa with 1 contact curve") in f.reason
    assert not v.notes


def test_a_file_before_the_flank_peak_is_judged_by_its_attribute(case, strength):
    """A /duty_cycle written before ``flank_peak_pressure``: the attribute alone judges."""
    out = _cycle(case, 1.3 * strength, 0.0).drop_vars(
        ["flank_peak_pressure", "flank_corner_curves"])
    (f,) = _static(verdict(out))
    assert f.reason.startswith("a flank pressure exceeds the static contact strength")
    out.attrs["contact_static_limit_exceeded"] = 0
    assert not _static(verdict(out))


def test_the_bin_envelopes_split_the_flank_by_the_flank_peak_rule():
    """The line contacts' envelope peaks at the flank peak (the rule's identity), the
    corner clip's lands on its own node, and the largest of the three is the envelope of
    every segment (:func:`contact.load_capacity.durability.pressure_envelopes`, the rule of
    ``/ltca/pressure_envelope``): no segment is lost, none counted twice."""
    from contact.load_capacity.durability import pressure_envelopes

    lt = _placed(900.0, 2500.0)
    line, corner, edge = bin_envelopes(lt)
    assert line.max() == flank_peak(lt).pressure[0] == 900.0
    assert (line[1, 1], corner[0, 2]) == (900.0, 2500.0)
    assert corner.sum() == 2500.0 and not edge.any()
    every, _ = pressure_envelopes(lt["pressure_max"].values[0], lt["segment_u"].values,
                                  lt["segment_v"].values, np.zeros(4, bool), lt["u"].values,
                                  lt["v"].values)
    np.testing.assert_array_equal(np.maximum(line, corner), every)
    # a short curve that carries a share of its roll's load is a contact: it stays in
    heavy = _placed(900.0, 2500.0)
    heavy["force"][0, 0, 1] = 100.0  # 100 N per segment: 9 % of the roll's 4.4 kN
    line, corner, _ = bin_envelopes(heavy)
    assert line[0, 2] == 2500.0 and not corner.any()


def test_a_corner_clip_sets_no_damage_and_no_safety(case, strength):
    """The damage, the life, S_H at the peak bin and the local S_H of a bin with a corner
    clip far above the static strength are those of the same bin without it, to the bit
    (the clip is in no number the flank is judged by); the clip stays readable in the
    cycle's ``corner_pressure_envelope`` and ``pressure_max_flank``."""
    line, corner = 0.9 * strength, 1.3 * strength
    with_clip, without = _cycle(case, line, corner), _cycle(case, line, 0.0)
    for name in ("flank_damage", "damage", "life", "contact_safety_factor",
                 "local_contact_safety"):
        np.testing.assert_array_equal(with_clip[name].values, without[name].values,
                                      err_msg=name)
    assert float(with_clip["flank_damage"].sel(member="pinion").values[0, 0, 2]) == 0.0
    assert float(with_clip["flank_damage"].sel(member="pinion").values[0, 1, 1]) > 0.0
    assert float(with_clip["corner_pressure_envelope"].values[0, 0, 2]) == corner
    assert float(with_clip["pressure_max_flank"][0]) == corner
    assert "corner_pressure_envelope" in with_clip.attrs["flank_damage_curves"]
