"""Loaded tooth contact analysis over the mesh cycle (seed §3.3–3.4, Eq. 3.12–3.14).

At each pinion roll position the instantaneous contact curves of every tooth pair that
may share the load (from the ease-off UTCA, :mod:`contact.utca`) are split into
segments; each segment carries its midpoint, normal, length, initial separation
s = (ease-off − UTE) along the normal, moment arm R about the gear axis and the
equivalent radius R_eq across the contact line. The compliance of the segments
(:func:`contact.compliance.mesh_compliance`: both members' shells, Sainsot foundation,
Weber contact) and these data form a :class:`contact.ContactProblem`, solved by any
registered solver; the multiplier Θ is the loaded rotation, and the loaded transmission
error is LTE = UTE + Θ (gear lag, the seed's Fig. 3.6 convention).

The steps, each in its module: the segments of every (roll, pair)
(:mod:`contact.ltca.segments`); the segments a roll's problem must take
(:mod:`contact.ltca.screening`); their structural compliance, assembled once per roll
(:mod:`contact.ltca.pool`); Weber's load-dependent contact compliance by Newton's method
(:mod:`contact.ltca.weber`); the loop over rolls and torques
(:mod:`contact.ltca.roll_loop`); the ``/ltca`` dataset (:mod:`contact.ltca.dataset`).
Here: the roll positions (from the transition M1, :func:`contact.utca.transitions`), the
pair window, which widens itself where an outermost pair is loaded at its end of the
window (one more pair must change nothing), and the edge segments' separation bound,
checked against the solution's R Θ and widened if it was too tight.

Moment arm: a gear rotation δ closes the gap at a point by ρ |n·e_θ| δ — the distance of
the normal's line of action from the gear axis — which is the ``normal_arm`` of the
ease-off; so R = normal_arm, and s = R (ε + gap − UTE) with ε the angular ease-off.

Discretisation (seed §3.3, Fig. 3.3, made convergent here): each curve is sampled at
2S + 1 places (cosine spacing by default: the segments are graded towards the curve's
ends, where the load of the entering and leaving pairs rises into the flank edge); each
segment follows the quadratic through its ends and middle, is clipped where the real
pinion's mate leaves the pinion blank (so the line ends on the blank edge whatever S is),
and carries the mean separation over its clipped part at the middle of that part. Pairs
whose iso-line has just left the contact region keep a curve through the pinion's own gap
(:func:`contact.utca.contact_curves` with ``near_misses``), so a leaving pair's load fades
instead of vanishing. Doubling S or the roll positions changes the LTE by well under
0.5 µrad (tests/test_ltca_discretisation.py).

Edge contact (:mod:`contact.ltca.edges`, on by default): where a pair's curve passes
outside the contact region, the region's boundary (gear tip, heel, toe; the pinion's tip edge and
ends) carries edge segments with the separation ε + ½ K (Q − q)² of the pinion at roll q,
which continues the curve's own at its end, and R_eq = 1/(1/r_e + κ_other) from the
edges' rounding radius r_e; they follow the curve segments along the ``segment`` axis
(``segment_kind``), and the flank and edge peak pressures are reported apart.

R_eq across the contact line: κ_rel(w) = κ_p(w) + κ_g(w) along w = n × t (t the
contact-line tangent), each member's normal curvature from its principal curvatures
(Euler), evaluated on the real surfaces at the segment midpoints
(:func:`geometry.machine.flank.flank_at`); R_eq = 1/κ_rel (seed Eq. 2.13).
"""

from __future__ import annotations

import dataclasses
import logging
import math
import time
from collections.abc import Callable, Sequence

import numpy as np
import xarray as xr

from contact.ltca.options import LTCAOptions, LTCASetup, edge_radii
from contact.ltca.roll_loop import RollProblem, solve_rolls
from contact.ltca.screening import generous_limit
from contact.ltca.segments import segment_geometry
from contact.qp import ContactProblem
from contact.utca import EaseOff, ease_off
from contact.utca.transitions import cycle_transitions
from geometry.core.errors import InputError
from geometry.core.validation import real_array
from geometry.pair.assembly import Misalignment

__all__ = ["loaded_tca", "ltca_problems"]

log = logging.getLogger(__name__)

#: the pair window grows (LTCAOptions.pairs) up to this many pairs
_MAX_PAIRS = 8


def loaded_tca(
    case,
    torque: Sequence[float] | float,
    *,
    misalignment: Misalignment | None = None,
    flank: str | None = None,
    options: LTCAOptions | None = None,
    easeoff: EaseOff | None = None,
    progress: bool | str = False,
    problem_sink: Callable[[ContactProblem], None] | None = None,
    transitions: tuple[float, float] | None = None,
    roll_problems: list[RollProblem] | None = None,
) -> xr.Dataset:
    """Loaded TCA of a case at one or more torques over whole mesh cycles (seed §3.3–3.4).

    Parameters
    ----------
    case : geometry.case.Case
    torque : float or sequence of float — [N·m]
        Pinion torques T_p (> 0), the seed's operating variable (Fig. 3.6, Table 3.1).
        The contact problem carries the gear torque T_g = T_p z_g/z_p (static and
        lossless: friction enters only in the efficiency stage).
    misalignment : geometry.pair.assembly.Misalignment, optional
        ΔE, ΔP, ΔG [mm], ΔΣ [rad]; defaults to the case's own.
    flank : str, optional
        ``"drive"`` (default) or ``"coast"``.
    options : LTCAOptions, optional
    easeoff : contact.utca.easeoff.EaseOff, optional
        A precomputed ease-off of the same case, flank and misalignment.
    progress : bool or "lines"
        Show a progress bar over roll positions, or plain lines (``"lines"``).
    problem_sink : callable, optional
        Called with the final :class:`contact.ContactProblem` of every (torque, roll)
        (after the Weber iteration), e.g. to collect real problems for a solver study.
    transitions : (float, float), optional — [rad]
        The transition rolls (M1, M2) of the same ease-off, as
        :func:`contact.utca.transitions` gives them with its defaults (e.g. the
        ``transition_roll`` of :func:`contact.utca.unloaded_tca`, which the pipeline has
        already computed); default: computed here. The roll positions start at M1.
    roll_problems : list, optional
        Extended with a :class:`~contact.ltca.roll_loop.RollProblem` (torque, roll index,
        final problem and its solution) per (torque, roll) of every mesh cycle, roll by
        roll: what :func:`contact.ltca.mesh_interface.mesh_interface` condenses.

    Returns
    -------
    xarray.Dataset
        The ``/ltca`` dataset (exchange names: ``transmission_error`` [µrad] over
        (``torque``, ``roll``); ``force`` [N] and ``pressure_max`` [MPa] over
        (``torque``, ``roll``, ``pair``, ``segment``); ``load_share`` [1] over
        (``torque``, ``roll``, ``pair``); ``torque`` coordinate [N·m]), plus load per
        length, half-width, contact and edge flags, separations, residuals, solver
        status and times, and the LTE summary over the mesh cycles.

    Raises
    ------
    InputError
        For bad torques or options (the message names the field).
    """
    wanted = problem_sink is not None or roll_problems is not None
    sink: list[RollProblem] | None = [] if wanted else None
    ds = _analyse(case, torque, misalignment, flank, options, easeoff, transitions, progress,
                  sink)
    if problem_sink is not None:
        for rp in sink:
            problem_sink(rp.problem)
    if roll_problems is not None:
        roll_problems.extend(sink)
    return ds


def _analyse(case, torque, misalignment: Misalignment | None, flank: str | None,
             options: LTCAOptions | None, easeoff: EaseOff | None,
             transitions: tuple[float, float] | None, progress: bool | str,
             problem_sink: list[RollProblem] | None) -> xr.Dataset:
    """The analysis of :func:`loaded_tca`; the final problem of every (torque, roll) of the
    last pass (the pair window and edge limit settled) is appended to ``problem_sink``."""
    setup, t_easeoff = _setup(case, torque, misalignment, flank, options, easeoff,
                              transitions)
    opts = setup.options
    # edge segments surely separated by more than a generous limit are not worked out
    # (segment_geometry's edge_limit); the limit is checked against the solution's
    # R Θ and the analysis repeated with a wider one if it was too tight
    edge_limit = None
    if opts.edge_contact:
        edge_limit = opts.separation_limit or generous_limit(float(setup.torques.max()),
                                                             setup.easeoff.ratio)
    while True:
        opts = setup.options
        sink: list[RollProblem] | None = [] if problem_sink is not None else None
        t1 = time.perf_counter()
        seg = segment_geometry(setup.case, setup.easeoff, setup.roll, opts.pairs,
                               opts.segments, opts.spacing,
                               (opts.edge_step, edge_radii(setup.case, opts))
                               if opts.edge_contact else None, edge_limit=edge_limit)
        t_segments = time.perf_counter() - t1
        ds, reach = solve_rolls(setup, seg, progress=progress, sink=sink,
                                timing={"easeoff": t_easeoff, "segments": t_segments})
        more = _outer_pairs_loaded(ds, opts)
        widen = edge_limit is not None and opts.separation_limit is None and reach > edge_limit
        if (more == (None, None) or len(opts.pairs) >= _MAX_PAIRS) and not widen:
            break
        if more != (None, None) and len(opts.pairs) < _MAX_PAIRS:
            pairs = tuple(sorted({*opts.pairs, *(k for k in more if k is not None)}))
            log.info("pairs %s: an outermost pair is loaded at the end of the window; "
                     "again with %s", opts.pairs, pairs)
            setup = dataclasses.replace(setup, options=dataclasses.replace(opts, pairs=pairs))
        if widen:
            log.info("edge segments: R Θ reached %.3g mm beyond the limit %.3g mm; again "
                     "with %.3g mm", reach, edge_limit, 2.0 * reach)
            edge_limit = 2.0 * reach
    if problem_sink is not None:
        problem_sink.extend(sink)
    return ds


def _setup(case, torque, misalignment: Misalignment | None, flank: str | None,
           options: LTCAOptions | None, easeoff: EaseOff | None,
           transitions: tuple[float, float] | None) -> tuple[LTCASetup, float]:
    """Check the inputs of :func:`loaded_tca` and gather what the analysis runs on: the
    ease-off (computed unless given), the transitions and the roll positions from M1;
    with the ease-off's time [s]."""
    opts = options or LTCAOptions()
    torques = real_array("torque", torque, unit="N m", low=0.0, low_open=True)
    torques = np.atleast_1d(torques)
    if torques.ndim != 1 or torques.size == 0:
        raise InputError(f"torque: must be finite values > 0 [N m], got {torque!r}")
    if misalignment is not None:
        case = dataclasses.replace(case, misalignment=misalignment)
    t0 = time.perf_counter()
    eo = easeoff if easeoff is not None else ease_off(case, flank=flank)
    t_easeoff = time.perf_counter() - t0
    if transitions is None:  # on the splines the segment geometry reads (issue 75)
        m1, m2 = cycle_transitions(eo)
    else:
        try:
            m1, m2 = (float(m) for m in transitions)
        except (TypeError, ValueError) as exc:
            raise InputError("transitions: must be (M1, M2) [rad] (NaN where none), got "
                             f"{transitions!r}") from exc
    start = m1 if math.isfinite(m1) else 0.0
    n_roll = opts.cycles * opts.rolls_per_cycle
    roll = start + np.arange(n_roll) * eo.pitch / opts.rolls_per_cycle
    return LTCASetup(case, eo, opts, torques, roll, (m1, m2)), t_easeoff


def _outer_pairs_loaded(ds: xr.Dataset, opts: LTCAOptions) -> tuple[int | None, int | None]:
    """The pair beyond each end of the window, where its outermost pair is loaded at its
    end of the window (None where not).

    The pairs must span every tooth pair in mesh: the window of roll values they cover
    ends at the last roll of each cycle for the lowest pair and at the first roll for
    the highest; a pair loaded there (share > 1e-6) has a neighbour beyond it that may be
    loaded too.
    """
    share = np.nan_to_num(ds["load_share"].values)  # (torque, roll, pair)
    last = np.arange(opts.cycles) * opts.rolls_per_cycle + opts.rolls_per_cycle - 1
    lo, hi = int(np.argmin(opts.pairs)), int(np.argmax(opts.pairs))
    return (min(opts.pairs) - 1 if np.any(share[:, last, lo] > 1e-6) else None,
            max(opts.pairs) + 1 if np.any(share[:, last - opts.rolls_per_cycle + 1, hi]
                                         > 1e-6) else None)


def ltca_problems(case, torque, *, misalignment: Misalignment | None = None,
                  flank: str | None = None, options: LTCAOptions | None = None,
                  easeoff: EaseOff | None = None,
                  transitions: tuple[float, float] | None = None) -> list:
    """The real contact problems of a case's LTCA over one mesh cycle, as a solver study's
    test set.

    The analysis is :func:`loaded_tca`'s with the same arguments; the problem of every
    (torque, roll) is the final one of its roll (after the Weber iteration and the
    screening of the segments). Rolls of the later mesh cycles repeat the first cycle's
    problems exactly and are left out.

    Parameters
    ----------
    case : geometry.case.Case
    torque : float or sequence — [N·m]
        Pinion torques.
    misalignment, flank, options, easeoff, transitions
        As :func:`loaded_tca` (e.g. the ease-off of deviated surfaces).

    Returns
    -------
    list of contact.qp.benchmark_problems.TestProblem
        Roll by roll and at each roll torque by torque; kind ``ltca``, named
        ``"<case>_T<torque>_roll<j>"``; ``reference`` holds ``torque`` [N·m], ``roll``
        (index in the cycle) and ``roll_angle`` [rad] (pinion roll, from the transition M1).
    """
    from contact.qp.benchmark_problems import TestProblem

    opts = options or LTCAOptions()
    collected: list[RollProblem] = []
    setup, _ = _setup(case, torque, misalignment, flank, opts, easeoff, transitions)
    _analyse(case, torque, misalignment, flank, opts, setup.easeoff, setup.transitions,
             False, collected)
    out = []
    for rp in collected:
        if rp.roll >= opts.rolls_per_cycle:
            continue
        name = f"{case.name}_T{rp.torque:g}_roll{rp.roll:02d}"
        out.append(TestProblem(name, "ltca", dataclasses.replace(rp.problem, name=name),
                               {"torque": rp.torque, "roll": rp.roll,
                                "roll_angle": float(setup.roll[rp.roll])}))
    return out
