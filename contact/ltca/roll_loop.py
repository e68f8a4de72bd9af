"""The LTCA roll loop: every (torque, roll) contact problem of an analysis (seed §3.4).

For each computed roll position (rolls whole mesh cycles apart repeat one computed roll)
and each torque: select the segments that may touch (:mod:`contact.ltca.screening`), take
their structural compliance from the roll's pool (:mod:`contact.ltca.pool`), solve the
contact problem with Weber's compliance iterated to the loads (:mod:`contact.ltca.weber`),
check that no segment left out would close (else add it and solve again), and record the
solution (:class:`contact.ltca.results.RollResults`). The last computed roll's LTE and
forces at the same torque start the next roll's selection and solver. The first roll's
solution at the largest torque chooses the other rolls' pools, assembled in one batch.

Public functions
----------------
solve_rolls   the ``/ltca`` dataset of an analysis on its segments
RollProblem   the final contact problem of one (torque, roll), as the problem sink gets it
"""

from __future__ import annotations

import dataclasses
import logging
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import xarray as xr

from contact.errors import ProblemInputError
from contact.ltca.compliance_models import ComplianceModelError
from contact.ltca.dataset import ltca_dataset
from contact.ltca.options import LTCASetup
from contact.ltca.plastic import force_limits, pressure_limits
from contact.ltca.pool import CompliancePool
from contact.ltca.results import RollResults
from contact.ltca.screening import SCREEN_ROUNDS, Screening
from contact.ltca.segments import Segments
from contact.ltca.weber import RollSelection, WeberSolution, even_share, weber_solve
from contact.qp import ContactProblem, ContactSolution
from geometry.core.errors import InputError
from geometry.core.hertz import contact_modulus
from geometry.core.text import plain_number

__all__ = ["RollProblem", "solve_rolls"]

log = logging.getLogger(__name__)


@dataclass(frozen=True, eq=False)
class RollProblem:
    """The final contact problem of one (torque, roll) of an analysis (after the Weber
    iteration and the screening of the segments), as :func:`solve_rolls` hands it on.

    Attributes
    ----------
    torque : float — [N·m]
        Pinion torque T_p (the problem carries the gear torque).
    roll : int
        Index of the roll position in the analysis (0 … J − 1).
    problem : contact.qp.ContactProblem
    solution : contact.qp.ContactSolution or None
        Its solution (the forces whose active set the mesh interface condenses the
        compliance on, :mod:`contact.ltca.mesh_interface`).
    """

    torque: float
    roll: int
    problem: ContactProblem
    solution: ContactSolution | None = None


@dataclass(eq=False)
class _Continuation:
    """The last computed roll's solution at each torque: its LTE Θ + UTE [rad] and its
    forces (K, S) [N] (NaN where not in its problem); None before the first."""

    theta: list[float | None]
    force: list[np.ndarray | None]
    problems: dict[tuple[int, int], tuple[ContactProblem, ContactSolution]] = field(
        default_factory=dict)

    @classmethod
    def empty(cls, n_torque: int) -> _Continuation:
        return cls([None] * n_torque, [None] * n_torque)


@dataclass(frozen=True, eq=False)
class _Analysis:
    """Everything one roll's solve reads: the setup, segments, screening, pool, results."""

    setup: LTCASetup
    seg: Segments
    screening: Screening
    pool: CompliancePool
    results: RollResults
    modulus: float  # [MPa] contact modulus E* of the pair
    sink: Callable[[RollProblem], None] | None
    limits: tuple[float, float] = (np.inf, np.inf)  # [MPa] (edge, flank) pressure limits
    # [N] (J, K, S) every segment's force limit F_max (inf where its kind has none), or
    # None where no kind has one (force_limits of all segments at once)
    bounds: np.ndarray | None = None


def solve_rolls(setup: LTCASetup, seg: Segments, *, progress: bool | str = False,
                sink: list[RollProblem] | None = None,
                timing: dict[str, float]) -> tuple[xr.Dataset, float]:
    """The contact problems of every (torque, roll) of an analysis on its segments.

    Parameters
    ----------
    setup : LTCASetup
        Case, ease-off, options, torques [N·m], roll positions [rad], transitions.
    seg : Segments
        The segments of every (roll, pair) (:func:`contact.ltca.segment_geometry`).
    progress : bool or "lines"
        tqdm progress bar over the roll positions, or plain lines (``"lines"``:
        :func:`geometry.core.progress.progress_reporter`).
    sink : list, optional
        The final problem of every (torque, roll) is appended as a :class:`RollProblem`,
        roll by roll and at each roll torque by torque.
    timing : dict
        ``easeoff`` and ``segments`` times [s], recorded in the dataset.

    Returns
    -------
    xarray.Dataset
        The ``/ltca`` dataset (:func:`contact.ltca.dataset.ltca_dataset`).
    float — [mm]
        The largest R Θ the edge segments could reach (greatest boundary arm × greatest
        Θ), which must not exceed the edge limit the segments were worked out with.

    Raises
    ------
    InputError
        If some roll position has no tooth pair in contact, or a fixed separation limit
        takes in segments off the mating tooth.

    Notes
    -----
    Source: the seed's loaded TCA over the mesh cycle (§3.4), each roll's contact problem
    that of seed Eq. 3.12–3.14 with Weber's (1949) load-dependent contact compliance.
    """
    opts, torques = setup.options, setup.torques
    J, K, S = seg.shape
    screening = Screening.of(seg, float(torques.max()), setup.easeoff.ratio,
                             opts.separation_limit)
    modulus = contact_modulus(opts.youngs_modulus, opts.poisson_ratio,
                              opts.youngs_modulus, opts.poisson_ratio)
    limits = pressure_limits(setup.case, opts)
    # each segment's force limit, elementwise: once for all rolls, not per problem
    an = _Analysis(setup, seg, screening, CompliancePool(setup.case, seg, opts, setup.easeoff),
                   RollResults.empty(torques.size, J, K, S), modulus,
                   None if sink is None else sink.append, limits,
                   force_limits(seg.kind, seg.length, seg.r_eq, limits, modulus))
    cont = _Continuation.empty(torques.size)
    computed = [j for j in range(J) if int(seg.source[j]) == j and screening.usable[j].any()]
    if opts.separation_limit is not None:
        jobs = [(j, screening.first_pool(j)) for j in computed]
        if any(mask.any() for _, mask in jobs):
            an.pool.assemble([(j, mask) for j, mask in jobs if mask.any()])
    elif computed:
        an = _assemble_first_pool(an, computed[0])
    bar = None
    if progress:  # a tqdm bar, or plain lines off a terminal ("lines", as the studies)
        from geometry.core.progress import progress_reporter

        bar = progress_reporter(progress, J, desc="LTCA", unit="roll")
    for j in range(J):
        src = int(seg.source[j])
        if src != j:
            _repeat_roll(an, cont, src, j)
        else:
            for it in range(torques.size):
                _solve_roll(an, cont, j, it)
            if opts.separation_limit is None and computed and j == computed[0]:
                _assemble_other_pools(an, j, computed[1:])
        if bar is not None:
            bar.update()
    if bar is not None:
        bar.close()
    results = an.results
    results.compliance_time[:] = an.pool.time
    timing = {**timing, "compliance_asymmetry": an.pool.asymmetry}
    # the segment axis keeps the curve segments and the edge segments in some problem
    keep = (seg.kind == 0) | np.any(results.in_problem > 0, axis=(0, 1, 2))
    kept = dataclasses.replace(an.screening, separation=screening.separation[..., keep])
    reach = float(seg.edge_arm_max) * float(np.nanmax(results.rotation, initial=0.0))
    idx = np.flatnonzero(keep)
    # the kept segments' force limits taken from the solves' (elementwise: the same
    # numbers as computing them again on the kept segments, ~0.7 ms a point less)
    bounds = None if an.bounds is None else np.take(an.bounds, idx, axis=2)
    return ltca_dataset(setup, seg.keep(keep), kept, results.keep(keep), timing,
                        force_limit=bounds), reach


def _repeat_roll(an: _Analysis, cont: _Continuation, src: int, j: int) -> None:
    """Roll j lies whole mesh cycles after ``src``: its segments, separations and hence
    its contact problems are identical (segment_geometry), so are the results."""
    an.results.copy_roll(src, j)
    for it, T in enumerate(an.setup.torques):
        if an.sink is not None and (it, src) in cont.problems:
            problem, solution = cont.problems[it, src]
            an.sink(RollProblem(float(T), j, problem.renamed(
                f"{an.setup.case.name} roll {j} T {T:g}"), solution))


def _solve_roll(an: _Analysis, cont: _Continuation, j: int, it: int) -> None:
    """Roll j at torque ``it``: select, solve with Weber, check the segments left out
    (adding any that would close, up to SCREEN_ROUNDS rounds), record."""
    pool, screening, results = an.pool, an.screening, an.results
    T = float(an.setup.torques[it])
    gear_torque = float(an.setup.gear_torques[it])  # [N·mm]
    mask = pool.mask(j)
    if mask is None or not mask.any():
        results.status[it, j] = "no segment within the separation limit"
        return
    fixed = screening.fixed is not None
    # the segments that may touch: the whole pool, or (screening) those the LTE of the
    # last computed roll at this torque would close here
    if fixed or cont.theta[it] is None:
        sel = mask
    else:
        sel = screening.near(j, cont.theta[it] - screening.ute[j]) & mask
        if not sel.any():
            sel = mask
    # the last computed roll's forces on the same (pair, segment) start the Weber
    # iteration and (backends that take one) the solver
    prior = None if cont.force[it] is None else cont.force[it][sel]
    for _round in range(SCREEN_ROUNDS):
        if np.any(sel & ~pool.mask(j)):
            try:
                pool.assemble([(j, pool.mask(j) | sel)])
            except ComplianceModelError:  # the model's fault, not the torque's
                raise
            except InputError as exc:  # a segment the rotation closes has no mate
                raise InputError(
                    f"torque: {plain_number(T)} N m is beyond what the tooth model of this case "
                    f"carries: at roll {j} its loaded rotation closes segments of far "
                    "tooth pairs that lie off their mating tooth (the teeth deflect beyond "
                    f"the model's pairs; {exc})") from exc
        selection = _selection(an, j, sel)
        try:
            ws = weber_solve(selection, gear_torque, _first_load(an, j, gear_torque),
                             an.setup.options, an.modulus, prior=prior,
                             name=f"{an.setup.case.name} roll {j} T {T:g}")
        except ProblemInputError as exc:  # the force limits cannot carry the torque
            results.status[it, j] = f"plastic collapse: {exc}"
            log.warning("roll %d, torque %g N m: the segments' force limits cannot carry "
                        "the torque (%s)", j, T, exc)
            return
        results.solve_time[it, j] += ws.time
        if not ws.solution.found:
            break
        # a segment left out keeps its gap open if s + C F − R Θ ≥ 0: checked exactly
        # within the assembled pool, and beyond it by s ≥ R Θ (the compliances are
        # ≥ 0); then the solution is that of all segments
        rest = pool.mask(j) & ~sel
        coupling = pool.coupling(j, rest, sel) if rest.any() else None
        missed = screening.missed(j, sel, pool.mask(j), coupling, ws.solution.force,
                                  ws.solution.rotation)
        if not missed.any():
            break
        if fixed:
            log.warning("roll %d, torque %g N m: %d segments beyond the separation limit "
                        "%g mm would touch", j, T, int(missed.sum()), screening.fixed)
            break
        # the missed ones and, within the assembled pool, those nearly missed
        sel = sel | missed | (screening.near(j, ws.solution.rotation) & pool.mask(j))
        prior = _scatter(an.seg.shape[1:], selection,
                         np.maximum(ws.solution.force, 0.0))[sel]
    else:
        log.warning("roll %d, torque %g N m: the screening of the segments did not settle "
                    "in %d rounds", j, T, SCREEN_ROUNDS)
        ws = dataclasses.replace(ws, solution=dataclasses.replace(
            ws.solution, found=False, status="segment screening did not settle"))
    _record(an, cont, j, it, selection, ws)


def _selection(an: _Analysis, j: int, sel: np.ndarray) -> RollSelection:
    """The data of roll j's problem on the segments ``sel`` (K, S)."""
    idx = np.argwhere(sel)  # (N, 2): pair index, segment index
    kk, ss = idx[:, 0], idx[:, 1]
    structural, depth = an.pool.restricted(j, sel)
    seg, screening = an.seg, an.screening
    length, r_eq = seg.length[j, kk, ss], seg.r_eq[j, kk, ss]
    return RollSelection(j, kk, ss, structural, depth, length, r_eq,
                         screening.moment_arm[j, kk, ss], screening.separation[j, kk, ss],
                         None if an.bounds is None else an.bounds[j, kk, ss])


def _first_load(an: _Analysis, j: int, gear_torque: float) -> float:
    """[N] Weber's first loads at roll j, gear torque [N·mm]: shared
    evenly over the roll's curve segments (not the neighbour's loads, nor the selection's:
    the roll's result then depends on the roll alone, not on the path to it or on which
    edge segments were worked out)."""
    usable = an.screening.usable[j]
    on_curve = usable & (an.seg.kind == 0)
    arms = an.screening.moment_arm[j][on_curve if on_curve.any() else usable]
    return even_share(gear_torque, arms)


def _scatter(shape: tuple[int, int], selection: RollSelection,
             values: np.ndarray) -> np.ndarray:
    """(K, S) NaN but ``values`` (N,) at the selection's segments."""
    full = np.full(shape, np.nan)
    full[selection.pairs, selection.segments] = values
    return full


def _record(an: _Analysis, cont: _Continuation, j: int, it: int, selection: RollSelection,
            ws: WeberSolution) -> None:
    """Store roll j's solution at torque ``it`` and carry it on to the next roll."""
    sol = ws.solution
    an.results.record(it, j, sol, ws.iterations, selection.pairs.size)
    if an.sink is not None:
        an.sink(RollProblem(float(an.setup.torques[it]), j, ws.problem, sol))
        cont.problems[it, j] = (ws.problem, sol)
    if not sol.found:
        log.warning("roll %d, torque %g N m: %s", j, float(an.setup.torques[it]), sol.status)
        return
    cont.theta[it] = sol.rotation + an.screening.ute[j]
    cont.force[it] = _scatter(an.seg.shape[1:], selection, sol.force)
    an.results.record_loads(it, j, sol, selection.pairs, selection.segments,
                            selection.length, selection.r_eq, an.modulus,
                            sol.at_limit(ws.problem))


def _assemble_other_pools(an: _Analysis, j: int, others: list[int]) -> None:
    """The pools of the other computed rolls: the segments roll j's LTE at the largest
    torque would close there (the LTE varies little over the cycle; a segment missed is
    added when its roll is solved), in one batch."""
    screening, results = an.screening, an.results
    it_max = int(np.argmax(an.setup.torques))
    jobs = []
    for i in others:
        mask = (screening.near(i, screening.ute[j] + results.rotation[it_max, j]
                               - screening.ute[i])
                if results.found[it_max, j] else screening.first_pool(i))
        mask = mask if mask.any() else screening.first_pool(i)
        if mask.any():  # a roll with none keeps no pool: _solve_roll says so in its status
            jobs.append((i, mask))
    if jobs:
        an.pool.assemble(jobs)


def _assemble_first_pool(an: _Analysis, j: int) -> _Analysis:
    """The first computed roll's pool: the segments within the generous limit of the
    largest torque (:func:`contact.ltca.screening.generous_limit`, 0.05 mm + 0.15 mm per
    kN·m of gear torque, a bound of the loaded approach).

    Where that limit takes in segments of far tooth pairs that lie off their mating tooth
    (the bound grows with the torque alone, not with the teeth's size: 9.3 mm at the
    15.8 kN·m ISO capacity of a hypoid of m_mn 12, whose teeth approach by about a tenth of
    a millimetre there), the pool is the largest limit that keeps every segment on its
    mating tooth (found by bisection over the segments' separations). The limit only
    bounds the pool: each roll's screening adds every segment whose gap the solution would
    close (:meth:`contact.ltca.screening.Screening.missed`), so the solution does not
    depend on it (:func:`_solve_roll` says so where such a segment has no mate).

    Returns
    -------
    _Analysis
        ``an``, or ``an`` with the screening's generous limit narrowed to the largest that
        maps (the other rolls' pools before their first solution are bounded by it too).

    Raises
    ------
    InputError
        ``torque``: not even the roll's nearest segments lie on their mating teeth.
    """
    screening = an.screening
    try:
        an.pool.assemble([(j, screening.first_pool(j))])
        return an
    except ComplianceModelError:  # the model's fault, not the torque's
        raise
    except InputError as exc:
        torque = float(an.setup.torques.max())
        seps = np.unique(screening.separation[j][screening.first_pool(j)])
        lo, hi = -1, seps.size - 1  # seps[hi] fails; seps[lo] (if lo >= 0) maps
        while hi - lo > 1:
            mid = (lo + hi) // 2
            try:
                an.pool.assemble([(j, screening.usable[j]
                                   & (screening.separation[j] <= seps[mid]))])
                lo = mid
            except InputError:
                hi = mid
        if lo < 0:
            raise InputError(
                f"torque: {plain_number(torque)} N m is beyond what the tooth model of this case "
                f"carries: at roll {j} even the nearest segments of its tooth pairs lie off "
                "their mating tooth") from exc
    limit = float(seps[lo])
    narrowed = dataclasses.replace(screening, generous=limit)
    mask = narrowed.first_pool(j)
    if not np.array_equal(an.pool.mask(j), mask):  # (the bisection's last success is it)
        an.pool.assemble([(j, mask)])
    log.info("torque %g N m: the generous separation limit %.3g mm takes in segments off "
             "their mating tooth; the pool is bounded by %.3g mm instead (each roll's "
             "screening adds any segment the solution closes)", torque, screening.generous,
             limit)
    return dataclasses.replace(an, screening=narrowed)
