"""The µm-sized defaults of the synthesis and the development follow the tooth size below a
mean normal module of 3 mm (``geometry.synthesis.basic_design.size_scale``, issue 71).

Checked against the rule as the docstring states it (an independent product, exact to
round-off: the scaled values are one multiplication of the stated defaults), on the two
basic files of tests/data/limits whose m_mn (1.62 and 1.82 mm) is below the reference
module and on the designs of tests/data/designs, every one of which is at or above it and
must keep the defaults bit for bit (their developed cases were measured with them).
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import replace
from pathlib import Path

import pytest

from contact.optimize.development import (
    SIZE_SCALED_VARIABLES,
    VARIABLES,
    DevelopmentTargets,
    targets_from_table,
)
from geometry.core.errors import InputError
from geometry.synthesis.basic_design import (
    REFERENCE_MODULE,
    SIZE_SCALED_OPTIONS,
    FlankOptions,
    basic_from_dict,
    load_basic,
    size_scale,
)

DATA = Path(__file__).parent / "data"
SMALL = DATA / "limits" / "spiral_bevel_11x27_b43_m0.toml"


def test_size_scale_rule():
    assert size_scale(REFERENCE_MODULE) == 1.0
    assert size_scale(7.4) == 1.0  # a truck hypoid keeps the amounts it was checked with
    assert size_scale(1.5) == pytest.approx(1.5 / REFERENCE_MODULE, rel=1e-15)
    for bad in (0.0, -1.0, math.nan, math.inf):
        with pytest.raises(InputError, match="m_mn"):
            size_scale(bad)


def test_small_module_defaults_scaled():
    basic = load_basic(SMALL)
    m = basic.blank().m_mn
    assert m < REFERENCE_MODULE  # the 11x27 of module 2.6 (m_mn 1.62 mm)
    scale = m / REFERENCE_MODULE
    assert basic.size_scale() == pytest.approx(scale, rel=1e-15)
    default = FlankOptions()
    for flank in ("concave", "convex"):
        o = basic.options.flank(flank)
        for name in SIZE_SCALED_OPTIONS:
            assert getattr(o, name) == pytest.approx(scale * getattr(default, name),
                                                     rel=1e-12), (flank, name)
        # the other prescriptions are not lengths of µm: unchanged
        assert o.ellipse_length == default.ellipse_length
        assert o.te_level == pytest.approx(default.te_level, rel=1e-12)


def test_given_values_win():
    raw = tomllib.loads(SMALL.read_text(encoding="utf-8"))
    raw["synthesis"] = {"approach": 0.005, "concave": {"tip_relief": 20.0}}
    basic = basic_from_dict(raw)
    scale = basic.size_scale()
    assert basic.options.concave.approach == 0.005
    assert basic.options.convex.approach == 0.005
    assert basic.options.concave.tip_relief == pytest.approx(0.020, rel=1e-12)
    # what the file leaves out is still scaled
    assert basic.options.concave.root_relief == pytest.approx(scale * 0.015, rel=1e-12)
    assert basic.options.convex.tip_relief == pytest.approx(scale * 0.015, rel=1e-12)


@pytest.mark.parametrize("name", ["pc_hypoid_10x43", "truck_hypoid_9x37", "spiral_bevel_15x45_m0",
                                  "hypoid_7x37_rc2p5"])
def test_normal_modules_unchanged(name):
    """The designs the defaults were developed on keep them exactly (the smallest m_mn of
    tests/data/designs is the 15x45's 3.12 mm)."""
    basic = load_basic(DATA / "designs" / f"{name}.toml")
    assert basic.size_scale() == 1.0
    # a flank's options are the file-wide ones with its own given (dataclasses.replace,
    # whose unit round trip moves te_level by an ulp): the same path, nothing given
    assert basic.options.concave == replace(FlankOptions())
    assert basic.options.convex == replace(FlankOptions())
    assert targets_from_table(basic.development, size_scale=basic.size_scale()) == \
        DevelopmentTargets()


def test_development_bounds_scaled():
    scale = 0.54
    t = targets_from_table({}, size_scale=scale)
    assert t.size_scale == scale
    for name, (lo, hi) in VARIABLES.items():
        want = (scale * lo, scale * hi) if name in SIZE_SCALED_VARIABLES else (lo, hi)
        assert t.variables[name] == pytest.approx(want, rel=1e-15), name
    assert DevelopmentTargets().variables == dict(VARIABLES)
    # the table's own size_scale, or its own bounds, win
    assert targets_from_table({"size_scale": 1.0}, size_scale=scale).variables == dict(VARIABLES)
    own = {"tip_relief": [0.0, 60.0], "path_angle": [-80.0, -25.0]}
    t = targets_from_table({"variables": own}, size_scale=scale)
    assert t.variables == {"tip_relief": (0.0, 60.0), "path_angle": (-80.0, -25.0)}
    with pytest.raises(InputError, match=r"development\.size_scale"):
        targets_from_table({"size_scale": 0.0})
