"""The development's informational ``[development]`` table stays TOML-safe where an
analysis gave a NaN metric (branch unseen98, round 36 of issue 71's unseen designs): the
FM spiral bevel 14x19 at Sigma 60 deg's coast flank as synthesised read LTE p-p
"2280/nan" at its design torque, and ``ltca synthesize`` stopped on "to_toml: non-finite
value nan at [development.coast.as_synthesised] lte_peak_to_peak" (said as the unloaded
contact's failure), writing no case."""

from __future__ import annotations

import math
import tomllib

import numpy as np

from contact.optimize.development_result import NOT_COMPUTED, _rounded
from geometry.core.toml_files import dump_toml


def test_a_nan_metric_is_written_as_not_computed_and_round_trips():
    """The round trip (dump_toml then tomllib) is the identity on every finite value
    (rounded to 6 decimals, exact as text) and gives NOT_COMPUTED where the metric was
    NaN; the unwritten edge-pressure metrics stay out."""
    metrics = {"lte_peak_to_peak": np.array([2280.123456789, math.nan]),
               "plastic_share": np.array([0.0, 0.055]),
               "edge_pressure_gear_tip": np.array([1.0, math.nan])}
    table = _rounded(metrics)
    assert table == {"lte_peak_to_peak": [2280.123457, NOT_COMPUTED],
                     "plastic_share": [0.0, 0.055]}
    again = tomllib.loads(dump_toml({"development": {"coast": {"as_synthesised": table}}}))
    assert again["development"]["coast"]["as_synthesised"] == table


def test_a_case_that_cannot_be_written_is_not_called_an_unloaded_contact_failure():
    """``checked_contact`` on a case whose TOML text fails says the case cannot be written
    (the key named by ``to_toml``), not "the unloaded contact … cannot be computed", which
    it said of the 14x19's NaN (its analyses never ran: the stand-in has no flanks)."""
    import pytest

    from contact.optimize.written_contact import checked_contact
    from geometry.core.errors import InputError

    class Unwritable:
        def to_toml(self):
            return dump_toml({"development": {"coast": {"as_synthesised": {
                "lte_peak_to_peak": [2280.0, math.nan]}}}})

    with pytest.raises(InputError) as info:
        checked_contact(Unwritable(), design=None)
    text = str(info.value)
    assert text.startswith("the synthesised case cannot be written: to_toml: non-finite "
                           "value nan at [development.coast.as_synthesised] "
                           "lte_peak_to_peak")
    assert "unloaded contact" not in text
