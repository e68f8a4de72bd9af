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
