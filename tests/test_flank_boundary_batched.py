"""The flank boundary's lines evaluated in one batch (contact.ltca.edges, issue 75 item 4).

:func:`contact.ltca.edges.flank_boundary` evaluates the ease-off's field splines for all
its boundary lines together (one call per field group) instead of line by line. The
splines are evaluated point by point (each place's own knot cell; FITPACK's ``ev`` or the
compiled piecewise-polynomial kernel), so the batch must give every sample the numbers the
per-line calls gave, bit for bit: the reference below is the per-line loop the library had
(``_piece``, applied to the library's own boundary lines), kept here and not in the
library. Checked on two designs whose boundaries have all four kinds of line, the default
case's and the face-milled 11×41 of the edge tests, at two segment lengths; on the NumPy
kernels (``LTCA_KERNELS=numpy``: FITPACK) too.
"""

from __future__ import annotations

import dataclasses
import math
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from contact.catalogue import SEED_TABLE_3_1, bundled_case_path
from contact.ltca.edges import EDGE_KINDS, FlankBoundary, _boundary_lines, flank_boundary
from contact.utca import EaseOffFields
from contact.utca.easeoff import ease_off
from geometry.case import load_case

ROOT = Path(__file__).resolve().parents[1]


@cache
def _easeoff(name: str):
    if name == "default":
        return ease_off(load_case(bundled_case_path()))
    case = load_case(ROOT / "cases" / "kolivand2009_fm_11x41.toml")
    return ease_off(dataclasses.replace(case, misalignment=SEED_TABLE_3_1["misalignment"]))


def _piece(f, kind: int, uu: np.ndarray, vv: np.ndarray, step: float):
    """One boundary line as segments of at most ``step`` mm: the library's former
    per-line evaluation, verbatim (the reference)."""
    pos = f.values(("pos",), uu, vv)
    arc = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(pos, axis=0), axis=-1))]
    if arc[-1] <= 1e-9:
        return None
    n = max(1, math.ceil(arc[-1] / step))
    at = np.linspace(0.0, arc[-1], 2 * n + 1)
    us, vs = np.interp(at, arc, uu), np.interp(at, arc, vv)
    val = f.values(("q", "eps", "arm", "pos", "nrm"), us, vs)
    q = val[:, 0]
    if kind == 0:  # tip edge: inward is −v
        slope = -f.values(("q",), us, vs, dy=1)[:, 0]
    elif kind == 1:  # heel: inward is −u
        slope = -f.values(("q",), us, vs, dx=1)[:, 0]
    elif kind == 2:  # toe: inward is +u
        slope = f.values(("q",), us, vs, dx=1)[:, 0]
    else:  # pinion edge: inward is up the margin
        d_u = f.values(("q", "margin"), us, vs, dx=1)
        d_v = f.values(("q", "margin"), us, vs, dy=1)
        slope = d_u[:, 0] * d_u[:, 1] + d_v[:, 0] * d_v[:, 1]
    nrm = val[:, 6:9]
    nrm /= np.linalg.norm(nrm, axis=-1, keepdims=True)
    xyz = val[:, 3:6]
    idx = 2 * np.arange(n)[:, None] + np.arange(3)[None, :]
    return (np.full(n, kind), us[idx], vs[idx], q[idx], val[:, 1][idx],
            f.gap_at(us, vs)[idx], val[:, 2][idx], slope[idx], xyz[idx], nrm[idx])


def _per_line(f, step: float) -> FlankBoundary:
    """The boundary by the library's former per-line evaluation (:func:`_piece`, the
    reference) of the library's own lines (:func:`contact.ltca.edges._boundary_lines`:
    the lines are not what the batch changed)."""
    lines = _boundary_lines(f)
    pieces = [_piece(f, kind, uu, vv, step) for kind, uu, vv in lines]
    pieces = [p for p in pieces if p is not None]
    return FlankBoundary(*(np.concatenate(a) for a in zip(*pieces, strict=True)))


@pytest.mark.parametrize("kernels", ["default", "numpy"])
@pytest.mark.parametrize("design", ["default", "fm_11x41"])
def test_batched_boundary_equals_the_per_line_loop(design, kernels, monkeypatch):
    """Every field of every sample equal to the per-line loop's, bit for bit (NaN at the
    same places), with the same kinds, at segment lengths 0.5 and 0.25 mm; every kind of
    line present, so each slope branch is compared."""
    if kernels == "numpy":
        monkeypatch.setenv("LTCA_KERNELS", "numpy")
    f = EaseOffFields(_easeoff(design))
    for step in (0.5, 0.25):
        new, old = flank_boundary(f, step), _per_line(f, step)
        assert set(np.unique(new.kind)) == set(range(len(EDGE_KINDS)))
        assert new.kind.size > 20
        for name in FlankBoundary._fields:
            a, b = getattr(new, name), getattr(old, name)
            assert a.shape == b.shape and a.dtype == b.dtype, name
            np.testing.assert_array_equal(a, b, err_msg=f"{design} {name} step {step}")
