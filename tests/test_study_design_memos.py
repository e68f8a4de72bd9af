"""What a study repeated at every point though it depends on the design alone, kept once
(issue 75, study102): the blank outline (:func:`geometry.machine.flank.blank_outline`, per
blank object), the blade's profile sections
(:func:`geometry.machine.cutter.profile_sections`, per blade object) and the gear flank's
field splines of the ease-off fields (:func:`contact.utca.fields._gear_splines`, per
value).

Each memo runs the same computation on the same numbers as the uncached call, so the
tests hold a hit to the uncached result **bit for bit** (tolerance zero: the identity
relied on is that the arithmetic is the same, not an approximation) and check that a
changed input is a miss that gives the changed input's own result.
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from contact.catalogue import resolve_case
from contact.utca import fields as fields_mod
from contact.utca.conjugate_map import clear_memos
from contact.utca.easeoff import ease_off
from contact.utca.fields import EaseOffFields
from geometry.core.caches import cache_sizes, clear_caches
from geometry.machine import cutter, flank


def _same_arrays(a, b) -> bool:
    """Every field of two named tuples equal bit for bit (arrays with their NaN)."""
    for x, y in zip(a, b, strict=True):
        if isinstance(x, np.ndarray):
            if x.dtype != y.dtype or x.shape != y.shape or not np.array_equal(
                    x, y, equal_nan=x.dtype.kind == "f"):
                return False
        elif x != y:
            return False
    return True


def _same_spline(s, t) -> bool:
    """Two ``RectBivariateSpline`` objects with the same knots and coefficients, bit for
    bit, and the same degrees."""
    return (s.degrees == t.degrees
            and all(np.array_equal(a, b) for a, b in zip(s.tck, t.tck, strict=True)))


def test_blank_outline_kept_per_blank_equals_uncached_and_changes_with_the_blank():
    case = resolve_case(None)
    blank = case.gear.blank
    clear_caches()
    first = flank.blank_outline(blank)
    assert flank.blank_outline(blank) is first  # a hit: the kept outline
    assert _same_arrays(first, flank._blank_outline(blank))
    # another blank (a wider face): a miss, its own outline
    wider = dataclasses.replace(blank, face_width=blank.face_width + 1.0)
    other = flank.blank_outline(wider)
    assert other is not first
    assert _same_arrays(other, flank._blank_outline(wider))
    assert not np.array_equal(other.corners, first.corners)
    # clear_caches forgets it: computed again, the same numbers
    assert "geometry.machine.flank._memo_blank_outline" in clear_caches()
    again = flank.blank_outline(blank)
    assert again is not first and _same_arrays(again, first)


def test_profile_sections_kept_per_blade_equal_uncached_and_change_with_the_blade():
    case = resolve_case(None)
    blade = case.pinion.flank("concave").blade
    clear_caches()
    first = cutter.profile_sections(blade)
    assert cutter.profile_sections(blade) is first
    assert _same_arrays(first, cutter._profile_sections(blade))
    # another blade (a larger blade angle): a miss, its own sections
    steeper = dataclasses.replace(blade, blade_angle=blade.blade_angle + 0.01)
    other = cutter.profile_sections(steeper)
    assert _same_arrays(other, cutter._profile_sections(steeper))
    assert not np.array_equal(other.psi_ref, first.psi_ref)
    assert cutter.working_sections(blade) == cutter.working_sections(
        cutter._profile_sections(blade))


def _gear_inputs(eo):
    ok = np.all(np.isfinite(eo.gear_position), axis=-1)
    return [eo.normal_arm, *np.moveaxis(eo.gear_position, -1, 0),
            *np.moveaxis(eo.gear_normal, -1, 0)], ok


def test_gear_splines_kept_by_value_equal_uncached_and_miss_on_a_changed_value():
    case = resolve_case(None)
    clear_caches()
    eo = ease_off(case)
    fields, ok = _gear_inputs(eo)
    for plain in (True, False):
        kept = fields_mod._gear_splines(eo.u, eo.v, fields, ok, plain)
        fresh = fields_mod._field_splines(eo.u, eo.v, fields, ok, None, plain)
        assert len(kept) == len(fresh) == 7
        assert all(_same_spline(s, t) for s, t in zip(kept, fresh, strict=True))
        # copies of the same values: a hit (the same spline objects)
        again = fields_mod._gear_splines(eo.u.copy(), eo.v.copy(),
                                         [f.copy() for f in fields], ok.copy(), plain)
        assert all(s is t for s, t in zip(kept, again, strict=True))
    # one node of one field changed (by its last bit): a miss, the changed field's splines
    changed = [f.copy() for f in fields]
    i, j = np.argwhere(ok)[len(np.argwhere(ok)) // 2]
    changed[1][i, j] = np.nextafter(changed[1][i, j], np.inf)
    moved = fields_mod._gear_splines(eo.u, eo.v, changed, ok, True)
    fresh = fields_mod._field_splines(eo.u, eo.v, changed, ok, None, True)
    assert all(_same_spline(s, t) for s, t in zip(moved, fresh, strict=True))
    assert not _same_spline(moved[1], fields_mod._gear_splines(eo.u, eo.v, fields, ok,
                                                               True)[1])
    fields_mod.clear_fields_memo()
    assert cache_sizes()["contact.utca.fields._memo_gear_splines"] == 0


def test_ease_off_fields_at_two_misalignments_equal_those_built_without_the_memo():
    """The fields of a second misalignment share the first's gear splines, and every
    field equals the one built from emptied memos, bit for bit, at the grid's nodes and
    between them."""
    case = resolve_case(None)
    mis = case.misalignment
    other = case.replaced(misalignment=dataclasses.replace(
        mis, delta_E=mis.delta_E + 0.05, delta_P=mis.delta_P - 0.03))
    clear_caches()
    clear_memos()
    f1 = EaseOffFields(ease_off(case))
    eo2 = ease_off(other)
    f2 = EaseOffFields(eo2)
    assert f2.arm is f1.arm and all(a is b for a, b in zip(f2.pos, f1.pos, strict=True))
    # the same fields built with the gear splines' memo emptied first
    fields_mod.clear_fields_memo()
    cold = EaseOffFields(eo2)
    assert cold.arm is not f2.arm
    rng = np.random.default_rng(102)
    u = np.r_[eo2.u, rng.uniform(eo2.u[0], eo2.u[-1], 50)]
    v = rng.uniform(eo2.v[0], eo2.v[-1], u.size)
    for name in ("q", "eps", "gap", "arm", "margin", "pu", "pv"):
        a, b = getattr(f2, name), getattr(cold, name)
        assert _same_spline(a, b), name
        assert np.array_equal(a.ev(u, v), b.ev(u, v)), name
    for a, b in zip((*f2.pos, *f2.nrm), (*cold.pos, *cold.nrm), strict=True):
        assert _same_spline(a, b)


def test_kept_outline_and_profile_sections_are_read_only():
    """The kept results are shared by every caller: a write in place raises at the
    writing line (ValueError, NumPy's read-only assignment) instead of changing what
    later callers read; the uncached computation's arrays stay writable (a caller's own)."""
    case = resolve_case(None)
    clear_caches()
    outline = flank.blank_outline(case.gear.blank)
    sections = cutter.profile_sections(case.pinion.flank("concave").blade)
    for kept in (outline, sections):
        arrays = [x for x in kept if isinstance(x, np.ndarray)]
        assert arrays
        for a in arrays:
            assert not a.flags.writeable
            with pytest.raises(ValueError, match="read-only"):
                a[...] = 0.0
    assert flank._blank_outline(case.gear.blank).corners.flags.writeable
