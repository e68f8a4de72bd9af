"""The envelope solver's seed search (geometry.machine.meshing._seed) is the same search,
only cheaper (issue 32).

The seed search decides the reference of every batch the solver runs without a usable
guess at its middle target: the root that starts the first-order predictions, the blade
section that wins where a place has roots on two sections, and the sign of ∂f/∂q that the
undercut test (reason 4) compares with. The ease-off's placement iterations call it about
ten times per analysis of the default case, each time at a new target. The fast search
memoises the target-independent part (the generated points of the coarse candidate grid
per blade section and q range) and runs Newton's method on the first pass's candidates,
then on those of all the other passes in one batch (issue 75). These tests compare it with
the search as it was written before (every pass in turn, the candidate grid evaluated
afresh: :func:`_seed_reference`, kept here as the reference), and the ease-offs that
depend on it:

* the seeds themselves, bit for bit, on targets of every blade section (the profile,
  edge, relief sections; face milling and face hobbing), and the per-process memo of seeds
  the solver takes them from (the same seed, repeated);
* the ease-off of ISO sample 2 (face milled; the case whose gear-tip nodes a different
  reference masked when a relief-section root was accepted, commit cf68d5a) and of the
  face-hobbed reference design, drive and coast flank: valid masks and reasons node for
  node, values to 1e-9 (the tolerance of the request; the paths agree bit for bit).

Cost: each ease-off ≈ 0.1–0.3 s with the fast search and ≈ 0.2–0.7 s with the reference,
each seed test ≤ 9 targets of one flank; measured at load 13 on the 2 cores every test
≤ 5 s and the file ≈ 25 s (about half that on a quiet machine), cheap enough for CI.
"""

from __future__ import annotations

from functools import cache

import numpy as np
import pytest

import geometry.machine.meshing as meshing
from contact.catalogue import resolve_case
from contact.utca import conjugate_map
from contact.utca.easeoff import ease_off
from geometry.core.errors import InputError
from geometry.machine.cutter import profile_sections
from geometry.machine.family import chain, meshing_buffer
from geometry.machine.flank import blank_outline


def _seed_reference(ctx, z0, p0, depth):
    """The seed search as written before issue 32's speed-up: each pass (section, q range)
    in turn, its candidate grid evaluated afresh, Newton on its 12 best candidates."""
    sec = ctx.sections
    s_max = sec.s_lo[sec.main] + 4.0 * depth + 5.0
    searches = [np.zeros(1)]
    if ctx.generate:
        searches.append(np.linspace(-0.5, 0.5, 21))
    for k in [sec.main] + [j for j in range(len(sec.s_lo)) if j != sec.main]:
        for q_vals in searches:
            hi = min(sec.s_hi[k], sec.s_lo[k] + 2.0 * depth + 2.0)
            s_vals = np.linspace(sec.s_lo[k], hi, 9)
            t_vals = np.linspace(-np.pi, np.pi, 72, endpoint=False)
            sg, tg, qg = (a.ravel() for a in np.meshgrid(s_vals, t_vals, q_vals,
                                                         indexing="ij"))
            buf = meshing._family(ctx, sg, tg, qg, np.full(sg.shape, k))
            r = buf[:, 0]
            obj = (r[2] - z0) ** 2 + (np.hypot(r[0], r[1]) - p0) ** 2
            if ctx.generate and len(q_vals) > 1:
                f, _ = meshing_buffer(buf, ctx.length_scale)
                obj = obj + 0.1 * (ctx.length_scale * f) ** 2
            order = np.argsort(obj)[:12]
            x0 = np.stack([sg[order], tg[order], qg[order]], -1)[:, : 3 if ctx.generate else 2]
            n = len(x0)
            x, ok = meshing._newton(ctx, x0, np.full(n, k), np.full(n, z0), np.full(n, p0))
            valid = (ok & (x[:, 0] >= sec.s_lo[k] - 1e-9) & (x[:, 0] <= sec.s_hi[k] + 1e-9)
                     & (x[:, 0] <= s_max))
            if valid.any():
                pick = np.flatnonzero(valid)
                if ctx.settings.indexing_ratio != 0.0:
                    distance = np.abs(x[pick, 1:]).sum(axis=-1)
                    pick = pick[np.argsort(distance, kind="stable")]
                xs = x[pick[0]]
                _, jac, _ = meshing._evaluate(ctx, xs[None], np.array([k]), np.array([z0]),
                                              np.array([p0]))
                return xs, jac[0], k
    raise InputError("machine settings: no envelope solution at the middle of the flank")


def _context(case_name, member, flank):
    mem = resolve_case(case_name).member(member)
    tool = mem.flank(flank)
    bl = mem.blank
    ctx = meshing._Context(tool.blade, tool.machine, profile_sections(tool.blade),
                           tool.machine.process == "Generate", float(bl.outer_cone_distance),
                           chain(tool.machine))
    return ctx, bl, bl.outer_addendum + bl.outer_dedendum


def _section_targets(ctx, blank, depth):
    """Targets on every blade section that generates part of the flank (the first and the
    middle valid node of each on a 17 × 9 projection grid over an extended blank: the
    relief sections generate the flank's ends, where the ease-off seeds), and a masked
    node (every pass of the search runs, and fails)."""
    uu, vv = np.meshgrid(np.linspace(-0.15, 1.15, 17), np.linspace(-0.05, 1.2, 9),
                         indexing="ij")
    z, rho = conjugate_map._bilinear(blank_outline(blank).corners, uu, vv)
    sol = meshing.solve_envelope(ctx.blade, ctx.settings, z, rho,
                                 length_scale=ctx.length_scale, depth=depth)
    z, rho = z.ravel(), rho.ravel()
    reason, section = sol.reason.ravel(), sol.section.ravel()
    rows = []
    for k in np.unique(section[reason == 0]):
        on = np.flatnonzero((reason == 0) & (section == k))
        rows += [on[0], on[len(on) // 2]]
    rows += list(np.flatnonzero(reason != 0)[:1])
    return [(z[i], rho[i]) for i in rows], set(section[reason == 0].tolist())


@pytest.mark.parametrize("case_name", ["kolivand2009_fm_11x41_reference", "iso23509_sample2_fm",
                                       "kolivand2009_fh_12x41_reference"])
@pytest.mark.parametrize("member, flank", [("pinion", "concave"), ("pinion", "convex"),
                                           ("gear", "convex")])
def test_seed_equals_the_search_pass_by_pass(case_name, member, flank):
    """The fast seed search returns the reference search's root, Jacobian and section bit
    for bit (Newton runs each point on its own, so batching the passes changes nothing; the
    memoised candidate grid is the same array), or fails alike; a second call reads the
    memo. Cheap: ≤ 9 targets of one flank, the reference search ≤ 0.4 s each."""
    ctx, blank, depth = _context(case_name, member, flank)
    targets, sections = _section_targets(ctx, blank, depth)
    found = set()
    for z0, p0 in targets:
        try:
            ref = _seed_reference(ctx, z0, p0, depth)
        except InputError:
            with pytest.raises(InputError, match="no envelope solution"):
                meshing._seed(ctx, z0, p0, depth)
            continue
        found.add(ref[2])
        for _ in range(2):
            x, jac, k = meshing._seed(ctx, z0, p0, depth)
            assert k == ref[2]
            np.testing.assert_array_equal(x, ref[0])
            np.testing.assert_array_equal(jac, ref[1])
    assert found == sections  # a seed on each section that generates the flank
    assert meshing._candidate_grid.cache_info().hits > 0


@pytest.mark.parametrize("case_name", ["kolivand2009_fm_11x41_reference",
                                       "kolivand2009_fh_12x41_reference"])
def test_memoised_seed_is_the_search(case_name):
    """solve_envelope takes its seeds from a per-process memo (_memo_seed): the seed of a
    target is the search's own, bit for bit, the first time and when repeated (read-only),
    on targets of every blade section; a target without a seed raises each time."""
    ctx, blank, depth = _context(case_name, "pinion", "convex")
    targets, _ = _section_targets(ctx, blank, depth)
    meshing._seed_memoised.cache_clear()
    found = 0
    for z0, p0 in targets:
        try:
            alone = meshing._seed(ctx, z0, p0, depth)
        except InputError:
            with pytest.raises(InputError):
                meshing._memo_seed(ctx, z0, p0, depth)
            continue
        found += 1
        for _ in range(2):
            memo = meshing._memo_seed(ctx, z0, p0, depth)
            assert memo[2] == alone[2]
            np.testing.assert_array_equal(memo[0], alone[0])
            np.testing.assert_array_equal(memo[1], alone[1])
            assert not memo[0].flags.writeable
    assert found >= 3
    assert meshing._seed_memoised.cache_info().hits >= found


@cache
def _ease_offs(case_name, flank, reference):
    conjugate_map.clear_memos()  # the memoised forward map and gear nodes ran _seed too
    meshing._candidate_grid.cache_clear()
    meshing._seed_memoised.cache_clear()  # (the seeds of the other search's run)
    if reference:
        mp = pytest.MonkeyPatch()
        mp.setattr(meshing, "_seed",
                   lambda ctx, z0, p0, depth: _seed_reference(ctx, z0, p0, depth))
        try:
            return ease_off(resolve_case(case_name), flank=flank)
        finally:
            mp.undo()
            conjugate_map.clear_memos()
            meshing._seed_memoised.cache_clear()
    return ease_off(resolve_case(case_name), flank=flank)


@pytest.mark.parametrize("case_name", ["iso23509_sample2_fm", "kolivand2009_fh_12x41_reference"])
@pytest.mark.parametrize("flank", ["drive", "coast"])
def test_easeoff_equals_the_reference_search(case_name, flank):
    """The ease-off with the fast seed search equals the one with the reference search:
    the same reasons node for node (ISO sample 2's gear-tip nodes included, which another
    seed reference masked as no_conjugate_mate), the same pinion sections, and the values to
    1e-9 (mm, rad; the tolerance the issue asks for: the two agree bit for bit, any
    difference would be a different root or branch, far above it)."""
    fast = _ease_offs(case_name, flank, False)
    ref = _ease_offs(case_name, flank, True)
    np.testing.assert_array_equal(fast.reason, ref.reason)
    np.testing.assert_array_equal(fast.smooth, ref.smooth)
    np.testing.assert_array_equal(fast.pinion_section, ref.pinion_section)
    valid = ref.reason == 0
    assert valid.sum() > 600  # of 41 × 21 nodes
    for name in ("ease_off", "ease_off_angle", "roll_angle", "pinion_axial", "pinion_radius",
                 "gap_curvature", "normal_arm", "placement_error"):
        a, b = getattr(fast, name), getattr(ref, name)
        np.testing.assert_array_equal(np.isnan(a), np.isnan(b), err_msg=name)
        np.testing.assert_allclose(a[valid], b[valid], rtol=0, atol=1e-9, err_msg=name)


def test_smallest_is_the_full_sorts_head():
    """The seed's partial sort returns ``np.argsort(values)[:k]`` exactly: on random values,
    with ties inside and at the edge of the head (then the full sort decides), with NaN, and
    on arrays no longer than k + 1."""
    rng = np.random.default_rng(7)
    cases = [rng.random(13608), rng.integers(0, 40, 13608).astype(float),
             np.r_[rng.random(100), np.full(5, np.nan)], np.r_[np.zeros(3), rng.random(50)],
             rng.random(12), rng.random(13)]
    tie = rng.random(200)
    tie[np.argsort(tie)[12]] = tie[np.argsort(tie)[11]]  # a tie between the 12th and 13th
    cases.append(tie)
    for values in cases:
        np.testing.assert_array_equal(meshing._smallest(values, 12), np.argsort(values)[:12])


@pytest.mark.parametrize("case_name", ["kolivand2009_fm_11x41_reference",
                                       "kolivand2009_fh_12x41_reference"])
def test_nearest_candidates_are_the_full_sorts_head(case_name):
    """The seed passes take their 12 candidates from a k-d tree of the candidate grid:
    the same indices, in the same order, as ``np.argsort`` of the objective over the whole
    grid, on every section and q range, for targets on the flank, beyond it and far off
    (then the tree's neighbours may not hold the head and the grid is sorted)."""
    ctx, blank, depth = _context(case_name, "pinion", "convex")
    rng = np.random.default_rng(3)
    targets, _ = _section_targets(ctx, blank, depth)
    z = np.r_[[t[0] for t in targets], rng.uniform(-40, 40, 60)]
    p = np.r_[[t[1] for t in targets], rng.uniform(5, 80, 60)]
    wides = (False, True) if ctx.generate else (False,)
    for k in range(len(ctx.sections.s_lo)):
        for wide in wides:
            g = meshing._candidate_grid(ctx.blade, ctx.settings, ctx.length_scale,
                                        float(depth), k, wide)
            for z0, p0 in zip(z, p, strict=True):
                want = np.argsort(meshing._objective(g, z0, p0))[:12]
                np.testing.assert_array_equal(
                    meshing._nearest_candidates(g, z0, p0, 12), want)
