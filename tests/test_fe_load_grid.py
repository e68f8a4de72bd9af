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


def test_hat_weights_are_the_canonical_csr_of_the_four_corners():
    """The hat weights' sparse matrix made directly as canonical CSR holds the arrays the
    COO constructor makes of each point's four corner weights (its sort, no duplicates;
    issue 75): the same indices, entries and row pointers, so the same products; each row
    sums to 1, a point outside has the boundary's weights (``clip``) or none (``zero``)."""
    import scipy.sparse as sp

    rng = np.random.default_rng(3)
    gu, gv = np.linspace(0.0, 1.0, 7), np.array([0.0, 0.3, 0.5, 1.0])
    u, v = rng.uniform(-0.1, 1.1, 500), rng.uniform(-0.1, 1.1, 500)
    for outside in ("clip", "zero"):
        got = hat_weights(gu, gv, u, v, outside=outside)
        iu = np.clip(np.searchsorted(gu, u, side="right") - 1, 0, gu.size - 2)
        iv = np.clip(np.searchsorted(gv, v, side="right") - 1, 0, gv.size - 2)
        tu = np.clip((u - gu[iu]) / (gu[iu + 1] - gu[iu]), 0.0, 1.0)
        tv = np.clip((v - gv[iv]) / (gv[iv + 1] - gv[iv]), 0.0, 1.0)
        w = np.stack([(1 - tu) * (1 - tv), tu * (1 - tv), (1 - tu) * tv, tu * tv], axis=1)
        out = (u < 0) | (u > 1) | (v < 0) | (v > 1)
        if outside == "zero":
            w[out] = 0.0
        cols = np.stack([iu * gv.size + iv, (iu + 1) * gv.size + iv, iu * gv.size + iv + 1,
                         (iu + 1) * gv.size + iv + 1], axis=1)
        want = sp.csr_matrix((w.ravel(), (np.repeat(np.arange(u.size), 4), cols.ravel())),
                             shape=(u.size, gu.size * gv.size))
        for name in ("indptr", "indices", "data"):
            assert np.array_equal(getattr(got, name), getattr(want, name)), name
        assert got.has_canonical_format and got.shape == want.shape
        rows = np.asarray(got.sum(axis=1)).ravel()
        assert np.allclose(rows[~out], 1.0) and np.allclose(rows[out], outside == "clip")
