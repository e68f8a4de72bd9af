"""The LTE peak-to-peak between the torques an analysis runs at (issue 71: "LTE p-p ≤ 60
µrad at every torque").

``ltca run`` analyses a case at its ``[operating]`` torques, a synthesised case's at two:
the development's light and design torque. The LTE p-p of a localised bearing is no smooth
function of the torque — it may peak between them: on the hypoid FH 8×35 k_d 2.16 it is 47
and 62 µrad at the light and the design torque and 64 / 76 µrad between them; on the
ratio-1 spiral bevel 16×16 at Σ 60° it stays at 45–47 µrad up to 281 N·m and jumps to 111
at 465 N·m. :func:`lte_range` analyses the contact alone (the LTCA's contact QP at every
roll position, the same options, ease-off and transitions as the run's: no friction, no FE
stress, no mesh interface) at the torques of :func:`lte_range_torques` the run has not
analysed, and returns the LTE p-p at every one of them and the run's own: the curve the
verdict's ``lte`` check judges and its ``within`` torque is read from
(:mod:`contact.study.lte_within`). ``ltca synthesize``'s deflection note analyses the same
torques (:func:`contact.optimize.development_deflection.analysed`), so that both commands
say the same torque for the same case.

Where the LTE first exceeds the verdict's limit (:data:`contact.ltca.plausibility.LTE_LIMIT`,
60 µrad) between two of these torques, :func:`bisected` analyses the middle of that
interval :data:`LTE_BISECTIONS` times, so that the torque up to which it keeps the limit is
bracketed four times closer than the grid alone (the LTE of a localised bearing may jump
between two torques: interpolating over a wide interval says a torque the bearing does not
keep). Both commands bisect alike.

Public names
------------
LTE_TORQUES, LTE_BISECTIONS, lte_range_torques, bisected, lte_range
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import numpy as np
import xarray as xr

__all__ = ["LTE_BISECTIONS", "LTE_TORQUES", "bisected", "lte_range", "lte_range_torques"]

#: torques [1] from the lightest analysed torque to the heaviest one up to the design
#: torque (both included, evenly spaced) at which the LTE p-p is judged: on the 16x16 at
#: Σ 60° the LTE p-p 45 / 47 / 111 / 122 µrad at 97.4 / 281 / 465 / 649.4 N m
LTE_TORQUES = 4

#: bisections [1] of the interval where the LTE p-p first exceeds the limit (one torque
#: analysed each): the crossing bracketed to 1/4 of the grid's interval
LTE_BISECTIONS = 2

#: two torques closer than this share of the larger are one (the run's own is kept)
_SAME_TORQUE = 1e-9


def lte_range_torques(torques: Sequence[float], design: float = math.inf,
                      n: int = LTE_TORQUES) -> tuple[float, ...]:
    """The torques at which an analysis' LTE p-p is judged: ``n`` evenly spaced from its
    lightest torque to its heaviest one up to the design torque, and its own torques
    between them.

    Parameters
    ----------
    torques : sequence of float, shape (m,) — [N·m]
        The torques analysed (any order; non-finite ones left out).
    design : float, optional — [N·m]
        The design torque (the rating's ``design_torque``): the range ends at it where the
        analysis runs above it (default infinite: at the heaviest torque analysed).
    n : int, optional
        Evenly spaced torques, both ends included, ≥ 2 (default :data:`LTE_TORQUES`).

    Returns
    -------
    tuple of float — [N·m]
        Ascending; empty where no torque analysed is at or below ``design`` (the verdict
        judges none). One torque where the range is one torque. A torque within 1e-9 of a
        larger one's magnitude of an analysed torque is that torque.

    Raises
    ------
    ValueError
        ``n`` below 2, or ``design`` NaN.

    Notes
    -----
    With two analysed torques, the light and the design torque of a synthesised case,
    these are ``numpy.linspace(light, design, n)``: the torques ``ltca synthesize``'s
    deflection note analyses (issue 71).
    """
    if int(n) < 2:
        raise ValueError(f"lte_range_torques: n must be >= 2, got {n}")
    if math.isnan(design):
        raise ValueError("lte_range_torques: design torque NaN")
    t = np.sort(np.asarray([x for x in np.asarray(torques, float).ravel()
                            if math.isfinite(x)], float))
    if t.size == 0 or t[0] > design:
        return ()
    low, high = float(t[0]), min(float(t[-1]), float(design))
    if high <= low:
        return (low,)
    grid = [float(x) for x in np.linspace(low, high, int(n))]
    own = [float(x) for x in t if low <= x <= high]
    out = list(own)
    for g in grid:
        if not any(abs(g - x) <= _SAME_TORQUE * max(abs(g), abs(x)) for x in own):
            out.append(g)
    return tuple(sorted(out))


def bisected(torques: Sequence[float], lte: Sequence[float], limit: float,
             analyse: Callable[[float], float], bisections: int = LTE_BISECTIONS
             ) -> tuple[tuple[float, ...], tuple[float, ...], tuple[float, ...]]:
    """The LTE p-p at more torques where it first exceeds ``limit``: the middle of the
    interval that brackets the crossing analysed, ``bisections`` times.

    Parameters
    ----------
    torques : sequence of float, shape (n,) — [N·m]
        Ascending.
    lte : sequence of float, shape (n,) — [µrad]
        The LTE p-p at each.
    limit : float — [µrad]
    analyse : callable
        ``analyse(torque) -> LTE p-p`` [N·m → µrad] (NaN where it has none).
    bisections : int, optional
        Default :data:`LTE_BISECTIONS`.

    Returns
    -------
    torques, lte : tuple of float — [N·m], [µrad]
        Ascending, the new torques among them.
    added : tuple of float — [N·m]
        The torques analysed, in the order analysed.

    Raises
    ------
    ValueError
        ``torques`` and ``lte`` of different lengths.

    Notes
    -----
    The crossing is the first one from below
    (:func:`contact.study.lte_within.within_torque`); nothing is analysed where the LTE
    keeps the limit at every torque, exceeds it at the first already, or a value up to
    the crossing is not finite. Bisection: each step halves the bracket.
    """
    t, y = [float(x) for x in torques], [float(x) for x in lte]
    if len(t) != len(y):
        raise ValueError(f"bisected: {len(t)} torques and {len(y)} LTE values")
    added: list[float] = []
    for _ in range(int(bisections)):
        above = [i for i, v in enumerate(y) if v > limit]
        if not above or above[0] == 0 or not all(math.isfinite(v) for v in y[:above[0]]):
            break
        i = above[0]
        mid = 0.5 * (t[i - 1] + t[i])
        t.insert(i, mid)
        y.insert(i, float(analyse(mid)))
        added.append(mid)
    return tuple(t), tuple(y), tuple(added)


def lte_range(ltca: xr.Dataset, case, *, design: float = math.inf,
              flank: str | None = None, options=None, easeoff=None,
              transitions: tuple[float, float] | None = None,
              n: int = LTE_TORQUES, limit: float | None = None) -> dict[str, xr.Variable]:
    """The LTE p-p of an analysis at :func:`lte_range_torques`: the run's own values where
    it analysed the torque, the contact alone's (:func:`contact.ltca.loaded_tca`) between.

    Parameters
    ----------
    ltca : xarray.Dataset
        The run's ``/ltca``: ``lte_peak_to_peak`` [µrad] over ``torque`` [N·m].
    case : geometry.case.Case
        The case as run (its misalignment the run's).
    design : float, optional — [N·m]
        The rating's design torque (default infinite: every torque analysed is judged).
    flank, options, easeoff, transitions
        As the run's LTCA was given them (:func:`contact.ltca.loaded_tca`): the LTE
        between is the same analysis' at other torques.
    n : int, optional
        :func:`lte_range_torques`'s ``n`` (default :data:`LTE_TORQUES`).
    limit : float, optional — [µrad]
        The limit whose first crossing :func:`bisected` brackets closer (default
        :data:`contact.ltca.plausibility.LTE_LIMIT`, the verdict's).

    Returns
    -------
    dict of str to xarray.Variable
        Empty where no torque is judged (:func:`lte_range_torques` empty). Else
        ``lte_torque`` [N·m] (the coordinate, dimension ``lte_torque``, ascending: the
        :func:`lte_range_torques` and the :func:`bisected` ones),
        ``lte_range_peak_to_peak`` (lte_torque) [µrad] and ``lte_range_source``
        (lte_torque) [1]: 0 where the value is the run's own ``lte_peak_to_peak``, 1 where
        the contact alone was analysed at the torque (NaN there where a roll position has
        no certified contact solution: no LTE to judge).

    Raises
    ------
    InputError
        From :func:`contact.ltca.loaded_tca` (bad options).
    ValueError
        From :func:`lte_range_torques`.

    Notes
    -----
    Seed §3.3–3.4 (the LTCA, its LTE p-p over the mesh cycles, Eq. 3.14); issue 71. The
    pass solves the contact QPs of every roll position at each new torque, as the run's
    LTCA: its CPU is the LTCA's per torque (docs/verdicts.md, "The LTE between the run's
    torques").
    """
    from contact.ltca.mesh_cycle import loaded_tca

    own_t = np.asarray(ltca["torque"].values, float)
    own_y = np.asarray(ltca["lte_peak_to_peak"].values, float)
    judged = lte_range_torques(own_t, design, n)
    if not judged:
        return {}
    # the run's own torques (lte_range_torques keeps them as they are)
    own = dict(zip(own_t.tolist(), own_y.tolist(), strict=True))

    def analyse(ts: list[float]) -> np.ndarray:
        ds = loaded_tca(case, ts, flank=flank, options=options, easeoff=easeoff,
                        transitions=transitions)
        certified = np.asarray(ds["found"].values, bool).all(axis=-1)
        return np.where(certified, np.asarray(ds["lte_peak_to_peak"].values, float),
                        math.nan)

    new = [t for t in judged if t not in own]
    alone = dict(zip(new, analyse(new).tolist(), strict=True)) if new else {}
    values = [own[t] if t in own else alone[t] for t in judged]
    if limit is None:
        from contact.ltca.plausibility import LTE_LIMIT

        limit = LTE_LIMIT
    judged, values, _ = bisected(judged, values, float(limit),
                                 lambda t: float(analyse([t])[0]))
    source = [0 if t in own else 1 for t in judged]
    dim = ("lte_torque",)
    return {
        "lte_torque": xr.Variable(dim, np.asarray(judged, float), {
            "units": "N m", "long_name": "pinion torques the LTE peak-to-peak is judged at "
            "(from the lightest analysed torque to the heaviest up to the design torque)"}),
        "lte_range_peak_to_peak": xr.Variable(dim, np.asarray(values, float), {
            "units": "urad", "long_name": "peak-to-peak loaded transmission error at "
            "lte_torque",
            "source": "the run's lte_peak_to_peak at its own torques; between them the "
            "contact alone (contact.ltca.loaded_tca: the run's options, ease-off and "
            "transitions, no friction, FE stress or mesh interface), "
            f"{int(n)} torques evenly spaced from the lightest to the heaviest judged, the "
            f"interval where it first exceeds {float(limit):g} urad bisected "
            f"{LTE_BISECTIONS} times (contact.ltca.lte_range; issue 71)"}),
        "lte_range_source": xr.Variable(dim, np.asarray(source, np.int8), {
            "units": "1", "long_name": "where lte_range_peak_to_peak comes from",
            "flag_values": np.asarray([0, 1], np.int8),
            "flag_meanings": "run_torque contact_alone"}),
    }
