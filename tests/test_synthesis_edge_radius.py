"""The largest blade edge radius a design's slots and clearance allow
(geometry/synthesis/edge_radius.py; issue 71, the fillet as the lever of a root that binds
at a given torque).

* the point width's limit checked against the arc constructed apart: the circle of radius
  r tangent to the tip plane and to the flank line (the centre at distance r from both
  lines, by a 2×2 solve), its tangent points' span along the tip;
* the clearance's limit against the arc's tangent point on the flank, its height above
  the tip plane from the same construction;
* the truck hypoid 8×47 at a = 45 mm (round 21, benchmarks/data/unseen_designs): the
  pinion's slot binds (2.36 mm) against the synthesis' default 0.25 m_mn = 1.574 mm;
* bad input named.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from geometry.core.errors import InputError
from geometry.synthesis.basic_design import load_basic
from geometry.synthesis.edge_radius import edge_radius_limit, largest_edge_radius

DATA = Path(__file__).resolve().parents[1] / "benchmarks" / "data" / "unseen_designs"


def _arc(r: float, alpha: float) -> tuple[float, float]:
    """(horizontal offset of the arc's tip-plane tangent point from the flank's foot, the
    height of its flank tangent point above the tip plane) [mm] of the circle of radius
    ``r`` tangent to the tip plane y = 0 and to a flank line through the origin leaning
    ``alpha`` [rad] from the vertical, the blade y ≥ 0, x ≥ −y tan α (wider away from its
    tip) — constructed: the centre (x_c, y_c) is r from both lines (y_c = r; the flank's
    unit normal n into the blade, n·(x_c, y_c) = r), the flank tangent point the centre
    less r n."""
    n = np.array([math.cos(alpha), math.sin(alpha)])  # the flank's normal into the blade
    centre = np.linalg.solve(np.array([[0.0, 1.0], n]), np.array([r, r]))
    touch = centre - r * n
    return float(centre[0]), float(touch[1])


@pytest.mark.parametrize("alpha_d, alpha_c", [(20.0, 20.0), (19.7047, 22.7953), (15.0, 25.0)])
def test_the_point_width_limit_is_the_span_of_both_arcs(alpha_d, alpha_c):
    """At the width's limit the two arcs' tangent points on the tip meet: their offsets
    from each flank's foot, constructed (:func:`_arc`), sum to the point width (to
    1e-12 mm: the same geometry by a solve instead of the tangent half-angle)."""
    a_d, a_c = math.radians(alpha_d), math.radians(alpha_c)
    w = 3.2375
    lim = edge_radius_limit(10.0, w, 100.0, a_d, a_c)
    assert lim.binding == "pinion point width"
    span = _arc(lim.pinion_width, a_d)[0] + _arc(lim.pinion_width, a_c)[0]
    assert span == pytest.approx(w, abs=1e-12)
    assert lim.radius == pytest.approx(math.floor(lim.pinion_width * 100) / 100, abs=1e-12)
    assert lim.gear_width == pytest.approx(lim.pinion_width * 10.0 / w, rel=1e-12)


def test_the_clearance_limit_puts_the_fillet_top_at_the_clearance():
    """At the clearance's limit the arc meets the flank of the smaller pressure angle
    (the higher fillet) at the clearance's height above the tip plane, constructed
    (:func:`_arc`, to 1e-12 mm), and the other flank's below it."""
    a_d, a_c = math.radians(19.7047), math.radians(22.7953)
    c = 1.574
    lim = edge_radius_limit(10.0, 10.0, c, a_d, a_c)
    assert lim.binding == "clearance"
    assert _arc(lim.clearance, a_d)[1] == pytest.approx(c, abs=1e-12)
    assert _arc(lim.clearance, a_c)[1] < c
    assert lim.radius == 2.37  # 1.574 / (1 - sin 19.7047°) = 2.3747, down to 0.01 mm


def test_the_truck_hypoid_8x47_takes_its_pinion_slot_as_the_limit():
    """The 8×47 (m_mn 6.296 mm, c = 0.125 × 2 m_mn = 1.574 mm, α_nD / α_nC 19.70 /
    22.80°): the pinion's slot width at the mean root 3.2375 mm limits the edge radius to
    2.366 mm, the clearance to 2.375 mm, the gear's 4.498 mm slot to 3.287 mm; 2.36 mm
    written, 1.50 × the synthesis' default 0.25 m_mn = 1.574 mm. The gear's width is the
    point width the synthesis writes into the case (4.498348 mm, its gear blades) over the
    two tangents (to 1e-5 mm, the case's digits)."""
    basic = load_basic(DATA / "truck_hypoid_8x47_a45.toml")
    geom = basic.blank()
    lim = largest_edge_radius(geom)
    assert geom.c == pytest.approx(1.574, abs=5e-4)
    assert (lim.radius, lim.binding) == (2.36, "pinion point width")
    assert lim.pinion_width == pytest.approx(2.366, abs=1e-3)
    assert lim.clearance == pytest.approx(2.375, abs=1e-3)
    insets = sum(math.tan(math.pi / 4 - a / 2) for a in (geom.pitch.alpha_nD,
                                                         geom.pitch.alpha_nC))
    assert lim.gear_width * insets == pytest.approx(4.498348, abs=1e-5)
    assert lim.radius / (0.25 * geom.m_mn) == pytest.approx(1.50, abs=0.005)


def test_bad_input_is_named():
    a = math.radians(20.0)
    with pytest.raises(InputError, match="pinion_point_width"):
        edge_radius_limit(3.0, 0.0, 1.0, a, a)
    with pytest.raises(InputError, match="clearance"):
        edge_radius_limit(3.0, 2.0, math.nan, a, a)
    with pytest.raises(InputError, match="alpha_c"):
        edge_radius_limit(3.0, 2.0, 1.0, a, math.radians(50.0))
    fh = load_basic(Path(__file__).resolve().parents[1] / "cases" / "basic"
                    / "kolivand2009_fh_12x41.toml")
    with pytest.raises(InputError, match=r"design\.z0"):
        largest_edge_radius(fh.blank())
