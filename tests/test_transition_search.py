"""The transitions M1, M2 by the batched search equal those of the sequential search
(issue 32), which the toolkit used before, to 1e-12 rad.

The batched search (``contact.utca.transitions._batched_search``) evaluates a dozen rolls
of the UTE difference per contact-curve call and keeps the sub-interval where its sign
changes; the sequential search (false position, Illinois) evaluates one roll per call.
Both stop on a bracket of 1e-12 rad with M1 on the reference pair's side, so the two must
agree to 1e-12 rad wherever the bracket holds one crossing — at a smooth crossing
(the default case at its Table 3.1 mounting) and where the UTE difference jumps (the
second-order curve of a pair leaving the contact region: ΔE = ΔP = −0.12 mm), which the
sequential search needs 40 calls for, the batched one 10. M2 of the batched search is the
same handover one pitch later; it, too, must agree. (Where the difference changes sign
more than once in a bracket, the batched search leaves the transition to the sequential
one, whose choice it keeps: not tested here.)

Cheap enough for CI: two ease-offs of the default case (~0.3 s each on a quiet core) and
four transition searches (≤ 0.5 s each).
"""

from __future__ import annotations

import importlib

import numpy as np
import pytest

from contact.catalogue import resolve_case
from contact.utca import EaseOffFields, ease_off
from geometry.pair.assembly import Misalignment

# the module (contact.utca.transitions is also the name of its function)
transitions_module = importlib.import_module("contact.utca.transitions")


class _Counting(transitions_module._PairDifference):
    """The UTE difference, counting the contact-curve calls."""

    calls = 0

    def __call__(self, x, k):
        type(self).calls += 1
        return super().__call__(x, k)


@pytest.mark.parametrize("misalignment", [None, Misalignment(delta_E=-0.12, delta_P=-0.12)],
                         ids=["table_3_1", "jump"])
def test_batched_search_equals_the_sequential_one(misalignment):
    case = resolve_case(None)
    eo = ease_off(case, misalignment=misalignment)
    h = _Counting(eo, EaseOffFields(eo), "second_order", 41)
    i0 = np.nanargmin(np.where(eo.valid, eo.ease_off_angle, np.nan))
    r_star = float(eo.roll_angle.ravel()[i0])
    u_all = transitions_module._roll_scan(h, r_star, 8)
    x, hx = transitions_module._scan_brackets(u_all, r_star, eo.pitch, 8)
    found = np.any(hx > 0, axis=1)
    assert found.all()
    rows = np.arange(2)
    j = np.argmax(hx > 0, axis=1)
    a, fa, b, fb = x[rows, j - 1], hx[rows, j - 1], x[rows, j], hx[rows, j]
    assert np.all(np.abs(np.r_[fa, fb]) < transitions_module._OUT_OF_MESH)  # smooth ends

    _Counting.calls = 0
    sequential = transitions_module._sequential_search(h, a, fa, b, fb, found)
    n_sequential = _Counting.calls
    _Counting.calls = 0
    batched = transitions_module._solve_transitions(h, x, hx)
    n_batched = _Counting.calls
    # both end within 1e-12 rad of the crossing on the reference pair's side
    np.testing.assert_allclose(batched, sequential, rtol=0.0, atol=1e-12)
    # the UTE of the reference pair at M1 and M2 is the carrying pair's (the same side
    # of a jump as the sequential search's): equal to round-off of the curve ends
    ute = transitions_module._PairDifference.ute(h, np.r_[batched, sequential])
    np.testing.assert_allclose(ute[:2], ute[2:], rtol=0.0, atol=1e-12)
    # the batched search ran (it did not leave the transitions to the sequential one)
    assert n_batched < n_sequential


def test_one_handover_where_the_pinion_corner_holes_are():
    """At ΔE = −0.15, ΔP = −0.06 mm the contact curves of rolls 0.61–0.64 rad cross the
    pinion's flankrem corner (gear column v = 5, where the mapped corner nodes give way to
    the corner's strip of unmapped ones: nodes u = 32–40 there, at rolls 0.60–0.77 rad).
    Pair 0's UTE is smooth there, so its difference to the preceding pair changes sign once
    in that bracket (the handover). Measured: once, at 0.625 rad. Before the corner holes
    were filled from the two faces (contact.utca.easeoff), on the design bundled then, at
    ΔE = ΔP = −0.12 mm (where its corner nodes were at rolls 0.61–0.71 rad; the
    re-optimised design's strip falls between that misalignment's grid nodes there), 7
    times (a ±50 µrad zig-zag from the 65 µrad step of the spline's fill).
    """
    case = resolve_case(None)
    eo = ease_off(case, misalignment=Misalignment(delta_E=-0.15, delta_P=-0.06))
    h = transitions_module._PairDifference(eo, EaseOffFields(eo), "second_order", 41)
    x = np.linspace(0.61, 0.64, 121)  # 0.25 mrad steps
    d = h(x, np.full_like(x, -1.0))
    assert np.all(np.abs(d) < transitions_module._OUT_OF_MESH)  # both pairs in mesh
    s = np.sign(d[d != 0.0])
    assert int(np.count_nonzero(s[1:] != s[:-1])) == 1


def test_the_cycles_transitions_are_searched_once_per_ease_off():
    """The transitions the LTCA starts from (``cycle_transitions``, issue 75): those of
    :func:`transitions` on splines of its own, bit for bit, though searched on the
    ease-off's shared splines (``fields_of``); memoised per ease-off object (an equal
    ease-off, another object, is searched again) and emptied by ``clear_caches``."""
    from contact.utca.easeoff import clear_ease_off_memo
    from geometry.core.caches import clear_caches

    memo = transitions_module._memo_cycle_transitions
    clear_caches()
    eo = ease_off(resolve_case(None))
    own = transitions_module.transitions(eo, fields=EaseOffFields(eo))
    got = transitions_module.cycle_transitions(eo)
    assert np.array(got).tobytes() == np.array(own).tobytes()
    assert np.all(np.isfinite(got))
    assert transitions_module.cycle_transitions(eo) is got  # read again, not searched
    assert memo.cache_info().hits == 1 and memo.cache_info().currsize == 1
    clear_ease_off_memo()
    other = ease_off(resolve_case(None))
    assert other is not eo
    assert np.array(transitions_module.cycle_transitions(other)).tobytes() == \
        np.array(own).tobytes()
    assert memo.cache_info().currsize == 2
    clear_caches()
    assert memo.cache_info().currsize == 0
