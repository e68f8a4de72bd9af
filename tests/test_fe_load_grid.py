"""The FE load grid's coverage message (contact.compliance.fe.influence): where a load grid
point has no meshed surface around it, the error says where and how high the surface
reaches (issue 71: the generated-gear spiral bevel 19x23 at beta_m 46 deg, whose pinion's
concave flank is generated only up to v 0.55-0.6 at the toe)."""

from __future__ import annotations

import numpy as np

from contact.compliance.fe.influence import _uncovered, hat_weights


def test_a_grid_point_without_surface_is_named_with_the_surface_height_there():
    """A 3 x 3 grid on [0, 1]²; facet points cover v ≤ 1 from u 0.5 on and reach v 0.4
    only below it: the hats' areas (the hat weights summed over the points, unit weights)
    are 0 at (u 0, v 1) alone (its hat's support u < 0.5, v > 0.5 holds no point), and the
    text names u 0.00 with the surface's top v 0.40 there and the grid's 1.00
    (hand-counted)."""
    grid_u = grid_v = np.linspace(0.0, 1.0, 3)
    uu, vv = np.meshgrid(np.linspace(0.0, 1.0, 51), np.linspace(0.0, 1.0, 51), indexing="ij")
    keep = (uu >= 0.5) | (vv <= 0.4)
    u, v = uu[keep], vv[keep]
    area = np.asarray(hat_weights(grid_u, grid_v, u, v).sum(axis=0)).ravel()
    assert np.flatnonzero(area <= 0.0).tolist() == [2]  # column i nv + j: (u 0, v 1)
    text = _uncovered(grid_u, grid_v, area, u, v)
    assert "u 0.00: surface up to v 0.40, grid to 1.00" in text
    assert "u 0.50" not in text
