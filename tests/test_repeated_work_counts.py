"""The counts ``benchmarks/repeated_work.py --by-development`` prints its repeats with
(branch cpu97, issue 71/75: the 17x23's window re-developments measured for work repeated
across developments)."""

from __future__ import annotations

import functools
import importlib.util
import random
from pathlib import Path

import pytest

_PATH = Path(__file__).resolve().parent.parent / "benchmarks" / "repeated_work.py"


@pytest.fixture(scope="module")
def counts():
    if not _PATH.exists():  # an installed copy without the benchmarks folder
        pytest.skip("benchmarks/repeated_work.py not in this tree")
    spec = importlib.util.spec_from_file_location("repeated_work", _PATH)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("size", [1, 2, 8, 64])
def test_the_simulated_memo_misses_what_lru_cache_misses(counts, size):
    """Identity: the misses simulated for an LRU memo of ``size`` entries equal those
    ``functools.lru_cache(maxsize=size)`` counts on the same keys (exact: integers), on
    a sequence with repeats near and far (400 keys of 40)."""
    rng = random.Random(97)
    keys = [str(rng.randrange(40)) for _ in range(400)]
    memo = functools.lru_cache(maxsize=size)(lambda key: key)
    for key in keys:
        memo(key)
    assert counts.lru_misses(keys, size) == memo.cache_info().misses
    # and the bounds: at least the distinct keys, at most every call
    assert len(set(keys)) <= counts.lru_misses(keys, size) <= len(keys)


def test_repeats_are_told_apart_by_the_development_of_the_first_call(counts):
    """A key's first call is no repeat; a repeat in the development of its first call is
    counted within, one in another development across (its CPU with it); kinds apart."""
    calls = [("synthesis", "a", 1.0, "1"), ("synthesis", "a", 0.5, "1"),
             ("synthesis", "a", 0.25, "2"), ("synthesis", "b", 2.0, "2"),
             ("ease-off", "a", 3.0, "2"), ("ease-off", "a", 4.0, "3")]
    out = counts.repeats_by_development(calls)
    assert out["synthesis"] == (1, 0.5, 1, 0.25)
    assert out["ease-off"] == (0, 0.0, 1, 4.0)
    assert counts.repeats_by_development([]) == {}
    # the repeats across, by the development of the first call and the repeating one
    across = counts.repeats_across(calls)
    assert across == {("synthesis", "1", "2"): (1, 0.25), ("ease-off", "2", "3"): (1, 4.0)}
    assert sum(n for n, _ in across.values()) == sum(
        v[2] for v in out.values())


def test_trial_ease_offs_are_recorded_once_each_and_keyed_by_their_inputs(counts):
    """``--by-development``'s trial ease-offs (branch cpu102): a call inside a trial's
    warm-seed block is recorded (kind ``"ease-off (a trial)"``), one outside is not (the
    per-process memo's wrapper counts it); equal inputs give equal keys, another flank or
    misalignment another key; the result is the computation's, unchanged."""
    class Teeth:  # a case's teeth key: hashable, equal for equal teeth
        def __init__(self, name):
            self.name = name

        def teeth_key(self):
            return ("teeth", self.name)

        misalignment = "aligned"

    warm = [True]
    recorded = []
    computed = []

    def compute(case, flank, misalignment, grid, pinion_phase, gear_phase):
        computed.append(flank)
        return (case.name, flank)

    wrapped = counts._wrap_trial_ease_off(
        compute, lambda kind, key, seconds: recorded.append((kind, key, seconds)),
        warm=lambda: warm[0])
    a, b = Teeth("a"), Teeth("a")
    assert wrapped(a, "concave", None, None, 0.0, 0.0) == ("a", "concave")
    assert wrapped(b, "concave", None, None, 0.0, 0.0) == ("a", "concave")
    assert wrapped(a, "convex", None, None, 0.0, 0.0) == ("a", "convex")
    assert wrapped(a, "concave", "dE 0.05", None, 0.0, 0.0) == ("a", "concave")
    warm[0] = False
    assert wrapped(a, "concave", None, None, 0.0, 0.0) == ("a", "concave")
    assert len(computed) == 5  # every call computed: the wrapper only counts
    assert [r[0] for r in recorded] == ["ease-off (a trial)"] * 4
    keys = [r[1] for r in recorded]
    assert keys[0] == keys[1] and len(set(keys)) == 3
    assert all(r[2] >= 0.0 for r in recorded)
    # the repeat is told apart as the other kinds are (within its development here)
    out = counts.repeats_by_development([(k, key, 0.1, "1") for k, key, _ in recorded])
    assert out["ease-off (a trial)"][0] == 1


def test_fe_entries_unread_are_those_no_request_asked_for_after_their_write(counts):
    """``--fe`` (branch cpu104): an entry counts as read where a request asked for its key
    after it was written (a request that built it on a miss is recorded once answered,
    after the write), or where ``ltca run`` of the case written reads it; the rest, in the
    order written, are unread. Counted on stand-in events (exact: a list of keys)."""
    events = [
        ("written", "pinion", "p1d"), ("written", "pinion", "p1c"),  # a build of both flanks
        ("written", "gear", "g1d"), ("written", "gear", "g1c"),
        ("asked", "pinion", "p1d"), ("asked", "gear", "g1d"),  # the drive check reads
        ("asked", "pinion", "p2d"),  # asked before its write: the build that follows
        ("written", "pinion", "p2d"), ("written", "pinion", "p2c"),
        ("written", "pinion", "p3c"), ("asked", "pinion", "p3c"),  # built on a miss
        ("asked", "gear", "g1c"),  # the coast check reads the gear's coast entry
    ]
    assert counts.unread_entries(events, final=set()) == [
        ("pinion", "p1c"), ("pinion", "p2d"), ("pinion", "p2c")]
    # the written case's entries are read by ltca run
    assert counts.unread_entries(events, final={"p2d", "p2c"}) == [("pinion", "p1c")]
    # an entry written again after its last request is unread again (its last write counts)
    again = [*events, ("written", "gear", "g1d")]
    assert counts.unread_entries(again, final=set())[-1] == ("gear", "g1d")
    assert counts.unread_entries([], final={"x"}) == []
