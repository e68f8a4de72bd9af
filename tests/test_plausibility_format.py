"""The numbers of contact.ltca.plausibility's sentences show why they exceed their limit
(issue 71): the 15x45 spiral bevel's light-load run printed "LTE peak-to-peak 0.50 times
its mean … (more than 0.5)" for a spread of 0.50x rounded down to the limit. Hand-made
/ltca numbers; the expected text is written out, not computed by the code under test."""

from __future__ import annotations

import numpy as np
import xarray as xr

from contact.ltca.plausibility import plausibility_warnings


def _ltca(pp, mean, plastic=None) -> xr.Dataset:
    ds = xr.Dataset(
        {"lte_peak_to_peak": ("torque", np.asarray(pp, float)),
         "lte_mean": ("torque", np.asarray(mean, float)),
         "unloaded_transmission_error": ("roll", np.array([0.0, 10.0]))},
        coords={"torque": [46.3, 309.2][:len(pp)]})
    if plastic is not None:
        ds["plastic_load_share"] = (("torque", "roll"), np.asarray(plastic, float))
    return ds


def test_a_spread_just_above_the_limit_prints_the_digits_that_show_it():
    (line,) = plausibility_warnings(_ltca([50.2, 20.0], [100.0, 400.0]))
    assert line.startswith("LTE spread: LTE peak-to-peak 0.502 times its mean at 46.3 N·m "
                           "(more than 0.5)")
    (line,) = plausibility_warnings(_ltca([74.0, 20.0], [100.0, 400.0]))
    assert "peak-to-peak 0.74 times" in line  # two decimals where they show it


def test_a_plastic_share_just_above_five_percent_likewise():
    lines = plausibility_warnings(_ltca([1.0, 1.0], [100.0, 400.0],
                                        plastic=[[0.0, 0.0], [0.0504, 0.01]]))
    assert len(lines) == 1 and "carry up to 5.04 % of the torque at 309.2 N·m" in lines[0]


def test_a_quiet_transfer_is_no_warning_and_the_verdict_agrees():
    """The quiet-transfer rule (contact.ltca.plausibility.quiet_transfer) in the flags
    ``ltca run`` prints as WARNINGs: a spread of 0.53 (p-p 35 of mean 66 µrad, the hypoid
    5x42's light bin of docs/own_gear_set.md) with no load on the edge segment is no
    cause; with a quarter of the torque on the gear toe, or a p-p of 70 µrad (above the
    verdict's 60), it is. At every combination the verdict's ``implausible`` findings are
    exactly the warnings (FAIL each), so the two never disagree. Hand-made /ltca: forces
    [3, edge] N on arms of 1 mm; without the segments' forces the edge share is not known
    and the spread stays flagged."""
    from contact.ltca.plausibility import plausibility_flags
    from contact.study.verdicts import verdict

    def ds(pp: float, edge_force: float | None) -> xr.Dataset:
        out = xr.Dataset({"lte_peak_to_peak": ("torque", [pp]),
                          "lte_mean": ("torque", [66.0]),
                          "unloaded_transmission_error": ("roll", [0.0, 31.0])},
                         coords={"torque": [700.0]})
        if edge_force is None:
            return out
        force = np.zeros((1, 2, 1, 2))
        force[0, :, 0] = [3.0, edge_force]
        return out.assign(force=(("torque", "roll", "pair", "segment"), force),
                          moment_arm=(("roll", "pair", "segment"), np.ones((2, 1, 2)))
                          ).assign_coords(segment_kind=("segment", ["curve", "gear_toe"]))

    for pp, edge, flagged in ((35.0, 0.0, False), (35.0, 1.0, True), (70.0, 0.0, True),
                              (35.0, None, True)):
        lt = ds(pp, edge)
        assert bool(plausibility_flags(lt)["lte_spread"][0]) is flagged, (pp, edge)
        warnings = plausibility_warnings(lt)
        assert len(warnings) == int(flagged)
        # the verdict (and ltca run's WARNING lines) leave out a spread without edge
        # contact: a loud transfer (70 µrad, no edge) is judged by the lte check instead
        loud = pp > 60.0 and edge == 0.0
        judged = plausibility_warnings(lt, edge_free_spread=False)
        assert judged == ([] if loud else warnings)
        findings = verdict(xr.DataTree.from_dict({"/ltca": lt})).findings
        found = [f for f in findings if f.check == "implausible"]
        assert [(f.severity, f.reason) for f in found] == [("fail", w) for w in judged]
        lte = [f.severity for f in findings if f.check == "lte"]
        assert lte == (["attention"] if pp > 60.0 else []), (pp, edge)
    # a custom lte limit moves the rule with it (verdict(..., lte_limit=80) likewise)
    assert not plausibility_flags(ds(70.0, 0.0), lte_limit=80.0)["lte_spread"][0]
