"""Repeated work in ``ltca synthesize``: analyses and tip-plane placements asked for again
with the same inputs (issue 71's CPU of a new design; issue 75).

``ltca synthesize BASIC`` runs in this process with its defaults (the development on), with
two of its functions wrapped where they are looked up: every design analysis
(:func:`contact.optimize.development_evaluate.analyse_design`, the coarse search's, the
check's, the tolerance excursions' and the coast flank's) keyed by its inputs — both
members of the case, the torques, the misalignment, the LTCA options, the flank and the
kept teeth with the pinion's key — and every tip-plane placement of a synthesis (step 8,
:func:`geometry.synthesis.tip_plane.tip_plane_on_root_cone` as
:mod:`geometry.synthesis.case_synthesis` calls it) keyed by its blade, settings, blank and
hand. Printed: the calls and their CPU seconds (``time.process_time``: this process),
those repeated (a key seen before: work a memo could have kept) and the number of
distinct cases analysed. ``--calls FILE`` writes one line per call (kind, key, case key,
CPU s, flank, torques).

Measured (cpu71c, 2026-11-26; hypoid 10x37 at Σ 75° of tests/data/designs, empty FE
cache): 149 analyses (57.8 s; 99 distinct cases, the others the same case at other
torques or excursions) and 32 tip placements (21.8 s), none repeated
(docs/own_gear_set.md, "Re-measured on the merged tree of 2026-11-26").

``--by-development`` (branch cpu97) wraps three more: each development
(:func:`contact.optimize.development.develop`, so that the LTE window's re-developments at
their own design torques are told apart: its CPU with and without the developments nested
in it, and its check steps', :func:`contact.optimize.development_check.check_steps`), each
ease-off the per-process memo computes (``contact.utca.easeoff._memoised_ease_off``: with
the misses an LRU memo of 8–256 entries would have on the same keys) and each synthesis'
steps 3–6 (``_unrelieved_flank`` of :mod:`geometry.synthesis.case_synthesis`, keyed by
the blanks, the gear's settings, the hands and every prescription the memo keys it by; not
by the pinion's cutter options, the same in one basic design's developments). It prints
each development's CPU and, per kind of call, the repeats within the development that
first made the call and those in another one or after the developments ("outside any
development": the remedy note's syntheses), work a memo shared by the developments of one
``ltca synthesize`` could keep.

Measured (cpu97, 2026-11-29; the FM spiral bevel 17x23 of benchmarks/data/unseen_designs,
≈ 179 s CPU under load 7–10): its developments 46.8 s (the Formate gear, stopped at its
foreseen cut), 31.7 (the generated gear's own), 25.1, 27.0 and 38.6 (the LTE window's
re-developments at 926.9, 638.9 and 530.4 N m); of 281 ease-offs computed 11 had been
computed before (0.5 s), of 308 cold analyses none, of 129 syntheses' steps 3–6 17 in an
earlier development (2.7 s) (docs/performance.md, "The 17×23's window re-developments:
what they repeat").

``--by-development`` also counts the ease-offs of the development's trials (branch cpu102:
``ease-off (a trial)``), which a trial's warm-seed block computes without the per-process
memo and the count above did not see: on the 17x23 (main ``26b22062``, 2026-11-29) 127
of its 381 ease-offs, 4 of them repeated across developments (the window re-development's
first four trials, the rated development's designs again: ≈ 0.2 s).

``--fe`` (branch cpu104) wraps the FE coefficient requests
(:func:`contact.compliance.fe.contact_compliance.shared_coefficients`, through which the
root-stress checks and the FE compliance read them, keyed by the member's cache key, each
recorded once answered) and each entry the builds write (``influence._cached``), with
the CPU (this process and its FE solver workers,
:func:`contact.compliance.fe.worker_cpu.cpu_seconds`) of each call of
:func:`contact.optimize.development_root.both_flanks_built`: it prints each build, and the
entries written that no request asked for afterwards nor ``ltca run`` of the case written
reads (its members' drive and coast entries at the FE level it names) — work that only a
build deferring an entry until it is asked for could save. Measured (cpu104, 2026-11-29;
the FM hypoid 8x37 of benchmarks/data/unseen_designs): docs/performance.md, "The 8×37's
`ltca synthesize`: where the CPU goes".

Usage: ``python benchmarks/repeated_work.py BASIC.toml [-o CASE.toml] [--calls FILE]
[--by-development] [--fe]``.
One design takes 2–4 min of CPU; point ``HYPOID_LTCA_CACHE`` at an empty directory for a
new design's FE builds.
"""

from __future__ import annotations

import argparse
import collections
import functools
import hashlib
import sys
import tempfile
import time
from pathlib import Path


def _key(*parts: object) -> str:
    return hashlib.sha1(repr(parts).encode()).hexdigest()[:16]


def _warm() -> bool:
    """Inside a development trial's warm-seed block (its envelope seeds continued)."""
    from geometry.machine.meshing import warm_seeds_active

    return warm_seeds_active()


class Developments:
    """The development each wrapped call runs in (``"n: <gear process> at <design
    torque>"``, numbered in the order the developments began) and each development's CPU
    seconds (``time.process_time``): all of it (``total``), that of the developments nested
    in it (``nested``: the window re-developments) and its check steps' (``steps``)."""

    OUTSIDE = "outside any development"

    def __init__(self) -> None:
        self.stack: list[str] = []
        self.order: list[str] = []
        self.total: dict[str, float] = {}
        self.nested: collections.Counter = collections.Counter()
        self.steps: collections.Counter = collections.Counter()

    @property
    def current(self) -> str:
        return self.stack[-1] if self.stack else self.OUTSIDE

    def wrap(self, develop):
        """``develop`` with its calls tagged and timed."""
        @functools.wraps(develop)
        def developed(basic, **kw):
            options = getattr(basic, "options", None)
            torque = getattr(options, "design_torque", None)
            at = "its rated torque" if torque is None else f"{torque:g} N m"
            tag = f"{len(self.order) + 1}: {getattr(options, 'gear_process', '?')} at {at}"
            self.order.append(tag)
            outer = self.stack[-1] if self.stack else None
            self.stack.append(tag)
            t0 = time.process_time()
            try:
                return develop(basic, **kw)
            finally:
                self.stack.pop()
                self.total[tag] = time.process_time() - t0
                if outer is not None:
                    self.nested[outer] += self.total[tag]
        return developed

    def timed_steps(self, steps):
        """``steps`` with its CPU added to the current development's ``steps``."""
        @functools.wraps(steps)
        def wrapped(*a, **kw):
            t0 = time.process_time()
            try:
                return steps(*a, **kw)
            finally:
                self.steps[self.current] += time.process_time() - t0
        return wrapped


def lru_misses(keys: list[str], size: int) -> int:
    """The misses of an LRU memo of ``size`` entries asked for ``keys`` in turn (as
    ``functools.lru_cache(maxsize=size)`` counts them)."""
    kept: collections.OrderedDict[str, None] = collections.OrderedDict()
    misses = 0
    for key in keys:
        if key in kept:
            kept.move_to_end(key)
            continue
        misses += 1
        kept[key] = None
        if len(kept) > size:
            kept.popitem(last=False)
    return misses


def repeats_by_development(calls: list[tuple[str, str, float, str]]
                           ) -> dict[str, tuple[int, float, int, float]]:
    """Per kind of call, (repeats within the development that made the key's first call,
    their CPU s, repeats in another development, their CPU s); ``calls`` are (kind, key,
    CPU s, development) in the order made. The first call of a key is no repeat."""
    first: dict[tuple[str, str], str] = {}
    out: dict[str, list] = {}
    for kind, key, seconds, dev in calls:
        counts = out.setdefault(kind, [0, 0.0, 0, 0.0])
        where = first.get((kind, key))
        if where is None:
            first[(kind, key)] = dev
        elif where == dev:
            counts[0] += 1
            counts[1] += seconds
        else:
            counts[2] += 1
            counts[3] += seconds
    return {kind: tuple(c) for kind, c in out.items()}


def repeats_across(calls: list[tuple[str, str, float, str]]
                   ) -> dict[tuple[str, str, str], tuple[int, float]]:
    """The repeats in another development than the key's first call's, per (kind, that
    first development, the repeating one): (count, CPU s). ``calls`` as
    :func:`repeats_by_development`'s."""
    first: dict[tuple[str, str], str] = {}
    out: dict[tuple[str, str, str], list] = {}
    for kind, key, seconds, dev in calls:
        where = first.setdefault((kind, key), dev)
        if where != dev:
            counts = out.setdefault((kind, where, dev), [0, 0.0])
            counts[0] += 1
            counts[1] += seconds
    return {k: (int(c[0]), float(c[1])) for k, c in out.items()}


def _wrap_memo(memo, record):
    """The lru_cache ``memo`` with each call recorded: ``record(key, computed, CPU s)``,
    the key the hash of the arguments as the memo hashes them (their ``repr`` may tell
    equal keys apart)."""
    def wrapped(*args):
        before = memo.cache_info().misses
        t0 = time.process_time()
        result = memo(*args)
        record(str(hash(args)), memo.cache_info().misses > before, time.process_time() - t0)
        return result
    wrapped.cache_clear = memo.cache_clear
    wrapped.cache_info = memo.cache_info
    return wrapped


def _wrap_trial_ease_off(compute, record, warm=_warm):
    """``easeoff._ease_off`` with each call made inside a development trial's warm-seed
    block recorded as ``record("ease-off (a trial)", key, CPU s)`` (branch cpu102): those
    the per-process memo never sees (:func:`contact.utca.easeoff._memo_ease_off` computes
    them unmemoised; the development's :class:`~contact.optimize.development_evaluate.
    KeptTeeth` keeps them for that development alone), keyed as the memo keys the others
    (the teeth, the misalignment's ``repr``, the flank, the grid and the phases). Calls
    outside a block go through the memo and are counted there (not here: once each)."""
    def wrapped(case, flank, misalignment, grid, pinion_phase, gear_phase):
        if not warm():
            return compute(case, flank, misalignment, grid, pinion_phase, gear_phase)
        t0 = time.process_time()
        try:
            return compute(case, flank, misalignment, grid, pinion_phase, gear_phase)
        finally:
            mis = case.misalignment if misalignment is None else misalignment
            grid_key = tuple(sorted((grid or {}).items()))
            record("ease-off (a trial)",
                   str(hash((case.teeth_key(), repr(mis), flank, repr(grid_key),
                             float(pinion_phase), float(gear_phase)))),
                   time.process_time() - t0)
    return wrapped


def _wrap_development(devs: Developments, record, record_ease_off) -> None:
    """Wrap the developments, their check steps, the ease-off memo and the synthesis'
    steps 3–6 where they are looked up; ``record(kind, key, CPU s)``,
    ``record_ease_off(key, computed, CPU s)``."""
    import contact.optimize.development as development
    import contact.optimize.development_check as check
    import contact.utca.easeoff as easeoff
    import geometry.synthesis.case_synthesis as case_synthesis

    development.develop = devs.wrap(development.develop)
    steps = devs.timed_steps(check.check_steps)
    check.check_steps = development.check_steps = steps

    easeoff._memoised_ease_off = _wrap_memo(easeoff._memoised_ease_off, record_ease_off)
    easeoff._ease_off = _wrap_trial_ease_off(easeoff._ease_off, record)
    unrelieved = case_synthesis._unrelieved_flank

    def _unrelieved_flank(pair, pf, fo, ref_gear_rotation, **kw):
        t0 = time.process_time()
        try:
            return unrelieved(pair, pf, fo, ref_gear_rotation, **kw)
        finally:
            # (the pinion's cutter options, which the synthesis memo keys by, are not in
            # pair: the same options assumed, as in one basic design's developments)
            record("synthesis steps 3-6",
                   _key(repr(pair.geom.design), repr(pair.gear.settings),
                        repr(pair.pinion_blank), repr(pair.gear_blank), pair.pinion_hand,
                        pair.gear_hand, repr(sorted(pair.kw.items())), pair.pinion_crown,
                        pair.third_order, pf, fo.path_angle, fo.te_level,
                        fo.ellipse_length, fo.approach, ref_gear_rotation,
                        kw.get("conjugate"), fo.mean_point_shift),
                   time.process_time() - t0)

    case_synthesis._unrelieved_flank = _unrelieved_flank


def unread_entries(events: list[tuple[str, str, str]], final: set[str]
                   ) -> list[tuple[str, str]]:
    """The FE entries written and never asked for afterwards: ``events`` are ``("written",
    member, key)`` and ``("asked", member, key)`` (a request answered: one that built its
    entry comes after that entry's write) in the order made; ``final`` the keys
    ``ltca run`` of the case written reads (counted as asked for at the end). Returns
    (member, key) of each unread entry in the order written; a key written twice counts
    once (its last write)."""
    last: dict[str, tuple[int, str]] = {}
    asked_at: dict[str, int] = {}
    for i, (kind, member, key) in enumerate(events):
        if kind == "written":
            last[key] = (i, member)
        elif kind == "asked":
            asked_at[key] = i
    return [(member, key) for key, (i, member) in sorted(last.items(), key=lambda kv: kv[1][0])
            if key not in final and asked_at.get(key, -1) <= i]


def _wrap_fe(events: list[tuple[str, str, str]], builds: list[tuple[float, list[str]]]
             ) -> None:
    """Record the FE requests and written entries in ``events`` (:func:`unread_entries`)
    and each ``both_flanks_built`` call's CPU with the keys it wrote in ``builds``."""
    import contact.compliance.fe.contact_compliance as contact_compliance
    import contact.compliance.fe.influence as influence
    import contact.optimize.development_root as development_root
    from contact.compliance.fe.cache import cache_key
    from contact.compliance.fe.options import FEOptions, member_flank
    from contact.compliance.fe.worker_cpu import cpu_seconds

    reader = contact_compliance.shared_coefficients

    @functools.wraps(reader)
    def shared_coefficients(case, member, flank="drive", options=None, *a, **kw):
        # recorded once answered: a request that built its entry (a miss) read it
        try:
            return reader(case, member, flank, options, *a, **kw)
        finally:
            opt = options if options is not None else FEOptions()
            events.append(("asked", member, cache_key(
                case.member(member), member_flank(case, member, flank), opt)))

    contact_compliance.shared_coefficients = shared_coefficients
    cached = influence._cached

    def _cached(ds, case, member, path, key, *a, **kw):
        events.append(("written", member, key))
        return cached(ds, case, member, path, key, *a, **kw)

    influence._cached = _cached
    built = development_root.both_flanks_built

    @functools.wraps(built)
    def both_flanks_built(*a, **kw):
        c0, n0 = cpu_seconds(), len(events)
        try:
            return built(*a, **kw)
        finally:
            builds.append((cpu_seconds() - c0, [key for kind, _, key in events[n0:]
                                                if kind == "written"]))

    development_root.both_flanks_built = both_flanks_built


def _written_case_keys(path: str) -> set[str]:
    """The cache keys ``ltca run`` of the case file ``path`` reads: each member's drive and
    coast entries at the FE level the case names."""
    from contact.compliance.fe.cache import cache_key
    from contact.compliance.fe.options import case_fe_options, member_flank
    from geometry.case import load_case

    case = load_case(path)
    opt = case_fe_options(case)
    return {cache_key(case.member(m), member_flank(case, m, f), opt)
            for m in ("pinion", "gear") for f in ("drive", "coast")}


def _print_fe(events: list[tuple[str, str, str]], builds: list[tuple[float, list[str]]],
              final: set[str]) -> None:
    print("FE builds (both_flanks_built), CPU s with the solver workers': entries written")
    for seconds, keys in builds:
        print(f"  {seconds:.1f}: {', '.join(k[:12] for k in keys) or 'none (cached)'}")
    unread = unread_entries(events, final)
    n = sum(1 for e in events if e[0] == "written")
    print(f"FE entries written {n}; never asked for afterwards nor read by ltca run of the "
          f"case written {len(unread)}: " + ", ".join(f"{m} {k[:12]}" for m, k in unread))


def _print_by_development(devs: Developments, calls: list[tuple[str, str, float, str]],
                          eo_keys: list[str]) -> None:
    print("developments, CPU s: all / own (less those nested in it) / its check steps")
    for tag in devs.order:
        total = devs.total.get(tag, float("nan"))
        print(f"  {tag}: {total:.1f} / {total - devs.nested[tag]:.1f} / "
              f"{devs.steps[tag]:.1f}")
    for kind, (n_in, s_in, n_out, s_out) in sorted(repeats_by_development(calls).items()):
        n = sum(1 for c in calls if c[0] == kind)
        cpu = sum(c[2] for c in calls if c[0] == kind)
        print(f"{kind}: {n} ({cpu:.1f} s); the same inputs again within a development "
              f"{n_in} ({s_in:.1f} s), in a later development {n_out} ({s_out:.1f} s)")
    for (kind, where, dev), (n, seconds) in sorted(repeats_across(calls).items()):
        print(f"  {kind}: {n} ({seconds:.1f} s) first in {where}, again in {dev}")
    if eo_keys:
        sizes = (8, 16, 32, 64, 128, 256)
        print("ease-offs an LRU memo of " + ", ".join(map(str, sizes)) + " entries computes: "
              + ", ".join(str(lru_misses(eo_keys, n)) for n in sizes)
              + f" (of {len(eo_keys)} asked, {len(set(eo_keys))} distinct)")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("basic", help="basic design file (TOML)")
    parser.add_argument("-o", "--output", help="case file to write (default a temporary one)")
    parser.add_argument("--calls", help="write one line per wrapped call to this file")
    parser.add_argument("--by-development", action="store_true",
                        help="each development's CPU and the repeats across developments")
    parser.add_argument("--fe", action="store_true",
                        help="the FE builds' CPU and the entries written but never read")
    args = parser.parse_args(argv)

    import contact.optimize.development_evaluate as evaluation
    import geometry.synthesis.case_synthesis as case_synthesis
    from contact.cli import main as ltca

    calls: list[tuple[str, str, str, float, str, tuple[float, ...]]] = []
    devs = Developments()
    # (kind, key, CPU s, development): --by-development's calls
    by_dev: list[tuple[str, str, float, str]] = []
    eo_keys: list[str] = []

    def record(kind: str, key: str, seconds: float) -> None:
        by_dev.append((kind, key, seconds, devs.current))

    def record_ease_off(key: str, computed: bool, seconds: float) -> None:
        eo_keys.append(key)
        if computed:
            record("ease-off computed", key, seconds)

    if args.by_development:
        _wrap_development(devs, record, record_ease_off)
    fe_events: list[tuple[str, str, str]] = []
    fe_builds: list[tuple[float, list[str]]] = []
    if args.fe:
        _wrap_fe(fe_events, fe_builds)
    analyse = evaluation.analyse_design
    place = case_synthesis.tip_plane_on_root_cone

    def analyse_design(case, torques, misalignment=None, options=evaluation.COARSE_LTCA,
                       teeth=None, pinion_key=(), flank="drive"):
        t0, trial = time.process_time(), _warm()
        try:
            return analyse(case, torques, misalignment, options, teeth, pinion_key, flank)
        finally:
            ts = tuple(float(t) for t in torques)
            key = _key(repr(case.pinion), repr(case.gear), repr(case.misalignment),
                       repr(misalignment), ts, repr(options), flank,
                       pinion_key if teeth is not None else None, id(teeth))
            calls.append(("analyse", key, _key(repr(case.pinion), repr(case.gear)),
                          time.process_time() - t0, flank, ts))
            # across developments: the same inputs, whichever development's kept teeth
            # (each builds a pinion tooth from the first case of its key)
            record(f"analyse ({'a trial' if trial else 'cold'})",
                   _key(repr(case.pinion), repr(case.gear),
                        repr(case.misalignment), repr(misalignment), ts, repr(options),
                        flank, pinion_key if teeth is not None else None),
                   time.process_time() - t0)

    def tip_plane_on_root_cone(blade, settings, blank, hand, **kw):
        t0 = time.process_time()
        try:
            return place(blade, settings, blank, hand, **kw)
        finally:
            key = _key(repr(blade), repr(settings), repr(blank), hand)
            calls.append(("tip plane", key, "", time.process_time() - t0, blade.side, ()))
            record("tip plane", key, time.process_time() - t0)

    evaluation.analyse_design = analyse_design
    case_synthesis.tip_plane_on_root_cone = tip_plane_on_root_cone
    with tempfile.TemporaryDirectory() as tmp:
        out = args.output or str(Path(tmp) / "case.toml")
        rc = ltca(["synthesize", args.basic, "-o", out, "--no-progress"])
        final = _written_case_keys(out) if args.fe and not rc else set()
    seen: set[tuple[str, str]] = set()
    n, cpu = collections.Counter(), collections.Counter()
    n_rep, cpu_rep = collections.Counter(), collections.Counter()
    cases = set()
    for kind, key, case_key, seconds, _, _ in calls:
        n[kind] += 1
        cpu[kind] += seconds
        if (kind, key) in seen:
            n_rep[kind] += 1
            cpu_rep[kind] += seconds
        seen.add((kind, key))
        if case_key:
            cases.add(case_key)
    for kind in n:
        print(f"{kind}: {n[kind]} calls, {cpu[kind]:.1f} s CPU; repeated with the same "
              f"inputs {n_rep[kind]} ({cpu_rep[kind]:.1f} s)")
    print(f"distinct cases analysed: {len(cases)}")
    if args.by_development:
        _print_by_development(devs, by_dev, eo_keys)
    if args.fe:
        _print_fe(fe_events, fe_builds, final)
    if args.calls:
        with open(args.calls, "w", encoding="utf-8") as f:
            for kind, key, case_key, seconds, flank, ts in calls:
                f.write(f"{kind}\t{key}\t{case_key}\t{seconds:.3f}\t{flank}\t{ts}\n")
    return int(rc or 0)


if __name__ == "__main__":
    sys.exit(main())
