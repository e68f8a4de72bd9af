"""``contact.iso10300_capacity``: the long-life capacity through the public API (issue 71,
round 26d, branch api87).

A script user asked to give a design torque "at 1.0 x its ISO capacity" had only ``ltca
synthesize --no-development`` to print it, or the internal
``contact.load_capacity.iso10300.capacity.capacity_torque``. The public function is
checked against ``contact.iso10300_rating`` itself (independent of the bracketing): at the
capacity the smallest of S_H/S_H,min and S_F/S_F,min is 1, below it above 1.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import contact
import geometry
from geometry.core.errors import InputError

CASE = "hypoid_iso23509_s2"
DESIGNS = Path(__file__).resolve().parents[1] / "tests" / "data" / "designs"


def _least_safety(case, torque: float, side: str | None = None) -> float:
    """min over members of S_H/S_H,min and S_F/S_F,min at long life (no load_cycles)."""
    table = {k: v for k, v in dict(contact.resolve_case(case).extra.get("rating") or {}).items()
             if k != "load_cycles"}
    if side is not None:
        table["side"] = side
    ds = contact.iso10300_rating(case, torque, rating=table)
    s_h = (ds["S_H"] / ds["S_Hmin"]).min()
    s_f = (ds["S_F"] / ds["S_Fmin"]).min()
    return float(min(s_h, s_f))


def test_the_capacity_is_where_the_rating_reaches_its_minimum():
    """The rating at the returned torque gives the least safety ratio 1 (to 1e-5: the
    capacity is found to 1e-6 relative in torque, and S_H goes as T^-1/2), 1 % below it
    above 1 (S_H ~ T^-1/2: ~1.005)."""
    t = contact.iso10300_capacity(CASE)
    assert t == pytest.approx(contact.iso10300_capacity(contact.resolve_case(CASE)), rel=0)
    assert _least_safety(CASE, t) == pytest.approx(1.0, abs=1e-5)
    assert _least_safety(CASE, 0.99 * t) > 1.004


def test_the_coast_flank_rates_the_other_side():
    """flank="coast" is the rating's coast side (the pinion's concave flank drives)."""
    t = contact.iso10300_capacity(CASE, flank="coast")
    assert _least_safety(CASE, t, side="coast") == pytest.approx(1.0, abs=1e-5)


def test_a_synthesised_basic_design_gives_what_ltca_synthesize_takes():
    """On a basic file without [synthesis] design_torque, the capacity rounded down to 4
    digits is the design torque the synthesised case's rating is written with (the one
    ``ltca synthesize --no-development`` prints)."""
    from contact.load_capacity.iso10300.capacity import floor_capacity, with_design_torque

    case, _ = geometry.synthesize(geometry.load_basic(DESIGNS / "truck_hypoid_9x37.toml"))
    t = contact.iso10300_capacity(case)
    _, written, why = with_design_torque(case)
    assert "ISO 10300 capacity" in why
    assert floor_capacity(t) == written


@pytest.mark.parametrize("kwargs, match", [
    ({"pinion_speed": 0.0}, r"^pinion_speed: "),
    ({"pinion_speed": float("nan")}, r"^pinion_speed: "),
    ({"flank": "reverse"}, r"^flank: must be one of"),
])
def test_bad_arguments_name_the_field(kwargs, match):
    with pytest.raises(InputError, match=match):
        contact.iso10300_capacity(CASE, **kwargs)
