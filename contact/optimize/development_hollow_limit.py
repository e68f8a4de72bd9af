"""What limits a hollow profile on a written drive flank whose LTE misses the development's
target above the load sharing's floor: the edge, the plastic share or the flank peak
against the local pitting limit, said on ``ltca synthesize``'s drive LTE line (issue 71:
"``ltca synthesize`` meets every development target on the drive flank").

Where the written bearing's LTE misses the target ``max_lte`` but its load sharing's floor
(:mod:`contact.optimize.development_lte_floor`) is below it, the bearing, not the contact
ratio, misses; the lever that lowers both torques' LTE there is a slightly hollow pinion
profile (negative ``profile_crowning``: each pair's contact spread over more of the depth,
so the entering and leaving pairs share the load earlier). What stops it is its edges: the
profile's ends come forward and load the tooth's tip and root. :func:`hollow_probes`
synthesises the written drive prescriptions with the profile crowning of
:data:`HOLLOW_PROBES` (× the size scale) and analyses each as ``ltca run`` does (its
sampling, the development's metrics); :func:`hollow_text` names, for each, the LTE it
reaches and what it costs: the edge carrying the most of the torque (against
``max_edge_share``), the plastic share, the flank peak and where it sits in the depth
against the local pitting limit at the design torque (above it the design torque would be
cut, :func:`contact.optimize.development_pitting.pitting_pressure_limit`) and the static
strength.

Measured (``benchmarks/development_levers.py --from-case --check --tolerance --edges``,
``ltca run``'s sampling, 2026-11-29, branch lte97; docs/synthesis.md, "The 13×33's hollow
profile against the edge levers") on the FM hypoid 13×33 at Σ 85° of
benchmarks/data/unseen_designs (written: path −80°, ellipse 0.75, tip relief 12 µm from
0.85, root relief 40 µm from 0.2, ``te_level`` 10; LTE 16 / 53 µrad at 59 / 393.5 N m,
flank peak 1562 MPa, local pitting limit 1630 MPa there): −5 µm 17.5 / 42.8 µrad, flank
peak 2038 MPa; −8 µm 25.4 / 38.2, edge 2.3 %, plastic 0.5 %, 2423 MPa. Every combination
with the edge levers that brings both torques to 40 µrad (the ellipse 0.8–0.85, −5 to −8
µm) keeps the flank peak at 1656–3192 MPa (1974 and above but one, not tolerant), at v
0.86–1.0 of the gear's depth; the root relief deep enough to bring it under the local
pitting limit (45–50 µm) gives the LTE back (40–46 µrad), and the ellipse 0.8–0.85 that
reaches 40 µrad loses the toe and the heel at ΔE ± 0.05 mm.

Public names
------------
HOLLOW_PROBES, HOLLOW_STEP, HollowProbe, checked_contact, probe_of, hollow_probes,
hollow_text
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Collection, Mapping, Sequence
from typing import Any

import numpy as np

__all__ = ["HOLLOW_PROBES", "HOLLOW_STEP", "HollowProbe", "checked_contact", "hollow_probes",
           "hollow_text", "probe_of"]

#: [µm at a mean normal module of 3 mm and above; × the size scale] the profile crownings
#: probed (negative: hollow): on the 13×33 −5 µm lowered the design torque's LTE 53 → 43
#: µrad, −8 µm to 38 (module docstring); the check's hollow steps try −3 to −6
HOLLOW_PROBES = (-5.0, -8.0)

#: [µm at a mean normal module of 3 mm and above; × the size scale] where the written
#: profile is hollow already, it is probed this much hollower too (before the hollower of
#: :data:`HOLLOW_PROBES`): the FM spiral bevel 7x29 written at −5 µm read 33 / 41 µrad at
#: 4.7 / 31.7 N m; −6 µm 31 / 40 µrad with the flank peak 1600 MPa within its local
#: pitting limit 1606 MPa, −8 µm 27 / 38 µrad at 1625 MPa above it (docs/synthesis.md)
HOLLOW_STEP = 1.0


@dataclasses.dataclass(frozen=True)
class HollowProbe:
    """One hollow profile on the written drive bearing, analysed at its two torques.

    Attributes
    ----------
    crowning : float — [µm]
        The profile crowning probed (negative: hollow).
    lte : (float, float) — [µrad]
        LTE p-p at the light and the design torque.
    edge_share : float — [1]
        Share of the torque the edges carry at the design torque.
    edge_shares : dict str → float — [1]
        The same per edge kind (:data:`contact.ltca.edges.EDGE_KINDS`).
    plastic : float — [1]
        The largest share on segments at their pressure limit, either torque.
    flank_peak : float — [MPa]
        The flank peak pressure at the design torque (the development's).
    peak_v : float — [1]
        Depth of the pressure envelope's peak at the design torque on the gear grid, root
        cone 0 → face cone 1 (the gear's root is the pinion's tip).
    pitting_limit : float — [MPa]
        The flank peak at which S_H,loc reaches S_Hmin at the design torque (inf: none).
    static : float — [MPa]
        The static strength (inf: no material named).
    """

    crowning: float
    lte: tuple[float, float]
    edge_share: float
    edge_shares: Mapping[str, float]
    plastic: float
    flank_peak: float
    peak_v: float
    pitting_limit: float
    static: float


def probe_of(ltca: Any, case: Any, crowning: float, pitting_limit: float,
             static: float) -> HollowProbe:
    """A :class:`HollowProbe` from the ``/ltca`` dataset of one design at (light, design).

    Parameters
    ----------
    ltca : xarray.Dataset
        ``/ltca`` of the design analysed at the light and the design torque (ascending).
    case : geometry.case.Case
        The design's case (the development's metrics read its blank).
    crowning : float — [µm]
        The profile crowning of the design.
    pitting_limit : float — [MPa]
        The local pitting limit of the flank peak at the design torque.
    static : float — [MPa]
        The static strength.

    Returns
    -------
    HollowProbe

    Raises
    ------
    KeyError, InputError
        A dataset without the LTCA's variables (:func:`contact.ltca.summary.
        edge_load_share`).
    """
    from contact.ltca.edges import EDGE_KINDS
    from contact.ltca.summary import edge_load_share
    from contact.optimize.development_evaluate import ltca_metrics

    m = ltca_metrics(ltca, case)
    kinds = [str(k) for k in np.unique(np.asarray(ltca["segment_kind"].values).astype(str))]
    shares = {k: float(np.nan_to_num(edge_load_share(ltca, kinds=(k,))[-1]))
              for k in EDGE_KINDS if k in kinds}
    env = ltca["pressure_envelope"].transpose("torque", "u", "v")
    last = np.nan_to_num(np.asarray(env.values, float)[-1])
    v = np.asarray(ltca["v"].values, float)
    peak_v = float(v[np.unravel_index(int(np.argmax(last)), last.shape)[1]])
    lte = np.asarray(m["lte_peak_to_peak"], float)
    return HollowProbe(
        crowning=float(crowning), lte=(float(lte[0]), float(lte[-1])),
        edge_share=float(np.nan_to_num(m["edge_load_share"][-1])), edge_shares=shares,
        plastic=float(np.max(m["plastic_share"])),
        flank_peak=float(m["pressure_max_flank"][-1]), peak_v=peak_v,
        pitting_limit=float(pitting_limit), static=float(static))


def checked_contact(case: Any, values: Mapping[str, float], torques: Sequence[float],
                    teeth: Any) -> Any:
    """The drive flank of ``case`` analysed as ``ltca run`` reads a written case: its
    sampling (:data:`~contact.optimize.development_evaluate.CHECK_LTCA`), the shell teeth
    ``teeth`` keeps for the bearing of ``values``, the contact analysis alone, no
    deviations — the one analysis a hollow probe (:func:`hollow_probes`) and a design of
    the step after the cut (:func:`~contact.optimize.development_hollow_further.
    analysed_further`) read.

    Parameters
    ----------
    case : geometry.case.Case
        The design's case.
    values : mapping
        Its drive prescriptions [file units: µm, deg, 1] (their bearing keys the teeth).
    torques : (float, float) — [N·m]
        The light and the design pinion torque.
    teeth : contact.optimize.development_evaluate.KeptTeeth
        The kept shell teeth.

    Returns
    -------
    xarray.DataTree
        The analysis tree (its ``/ltca``).

    Raises
    ------
    InputError, ValueError, KeyError, ArithmeticError
        From the analysis.

    Notes
    -----
    Source: issue 71; the check sampling of :mod:`contact.optimize.development_evaluate`.
    """
    from contact.chain import AnalysisChain
    from contact.optimize.development_evaluate import CHECK_LTCA, bearing_key
    from contact.pipeline import run_analysis

    options = dataclasses.replace(CHECK_LTCA,
                                  compliance=teeth.compliance(bearing_key(dict(values))))
    return run_analysis(case, [float(t) for t in torques], flank="drive", options=options,
                        deviations=False, steps=AnalysisChain.contact_only())


def hollow_probes(basic: Any, values: Mapping[str, float], torques: Sequence[float],
                  written: Any = None, crownings: Sequence[float] | None = None
                  ) -> list[HollowProbe]:
    """The written drive bearing with each hollow profile of :data:`HOLLOW_PROBES`,
    synthesised as written and analysed as ``ltca run`` does.

    Parameters
    ----------
    basic : geometry.synthesis.basic_design.BasicDesign
        The basic design with the developed prescriptions
        (:attr:`contact.optimize.development.DevelopmentResult.basic`).
    values : mapping
        The drive flank's written prescriptions [file units: µm, deg, 1].
    torques : (float, float) — [N·m]
        The light and the design pinion torque.
    written : geometry.case.Case, optional
        The written case: its ``[rating]`` gives the local pitting limit at the design
        torque (default: each probe's own case).
    crownings : sequence of float, optional — [µm]
        The crownings probed, as given (default :data:`HOLLOW_PROBES` × the design's
        size scale).

    Returns
    -------
    list of HollowProbe
        One per crowning that could be synthesised and analysed (a failure is logged and
        left out).

    Raises
    ------
    ValueError
        ``torques`` not two with 0 < light < design.

    Notes
    -----
    Cost: one synthesis (steps 3–6 once, memoised) and one analysis at ``ltca run``'s
    sampling per crowning; 2 × ≈ 3 s CPU on the 13×33 (module docstring). Source of the
    lever: Stadtfeld, *Gleason Bevel Gear Technology*, 2014 (profile crowning);
    Litvin & Fuentes, *Gear Geometry and Applied Theory*, 2nd ed., 2004, §9.4.
    """
    import logging

    from contact.optimize.development_evaluate import KeptTeeth, static_strength
    from contact.optimize.development_pitting import pitting_pressure_limit
    from geometry.core.errors import InputError
    from geometry.synthesis.basic_design import with_flank_options
    from geometry.synthesis.case_synthesis import synthesize

    light, design = (float(t) for t in torques)
    if not 0.0 < light < design:
        raise ValueError(f"hollow_probes: torques must satisfy 0 < light < design, got "
                         f"{light} / {design} N m")
    if crownings is None:
        scale = float(basic.size_scale())
        crownings = [round(c * scale, 4) for c in HOLLOW_PROBES]
    flank = basic.options.drive_flank
    memo: dict = {}
    teeth = KeptTeeth()
    out = []
    for c in crownings:
        design_values = dict(values) | {"profile_crowning": float(c)}
        try:
            case = synthesize(with_flank_options(basic, flank, design_values), memo=memo)[0]
            tree = checked_contact(case, design_values, (light, design), teeth)
            limit = pitting_pressure_limit(written if written is not None else case, design)
            out.append(probe_of(tree["/ltca"].to_dataset(), case, c, limit,
                                static_strength(tree)))
        except (InputError, ValueError, KeyError, ArithmeticError) as exc:
            logging.getLogger("contact.optimize.development").info(
                "the hollow profile %g um not analysed: %s", c, exc)
    return out


def _costs(p: HollowProbe, max_edge_share: float) -> list[str]:
    """What one probe misses, in words: the edge load, the plastic share, the flank peak
    against the local pitting limit and the static strength."""
    out = []
    if p.edge_share > max_edge_share:
        kind = max(p.edge_shares, key=p.edge_shares.get) if p.edge_shares else "edges"
        out.append(f"the edges carry {100 * p.edge_share:.1f} % of the torque (limit "
                   f"{100 * max_edge_share:g} %; the {kind.replace('_', ' ')} "
                   f"{100 * p.edge_shares.get(kind, math.nan):.1f} %)")
    if p.plastic > 0.0:
        out.append(f"plastic {100 * p.plastic:.1f} %")
    where = ("towards the gear's tip, the pinion's root" if p.peak_v > 0.5
             else "towards the gear's root, the pinion's tip")
    if p.flank_peak > p.static:
        out.append(f"the flank peak {p.flank_peak:.0f} MPa at v {p.peak_v:.2f} ({where}) "
                   f"above the static strength {p.static:.0f} MPa")
    elif p.flank_peak > p.pitting_limit:
        out.append(f"the flank peak {p.flank_peak:.0f} MPa at v {p.peak_v:.2f} ({where}) "
                   f"above the local pitting limit {p.pitting_limit:.0f} MPa at the design "
                   "torque (it would cut the design torque)")
    return out


def hollow_text(probes: Sequence[HollowProbe], target: float,
                max_edge_share: float, tried: Collection[float] = ()) -> str:
    """The hollow profile's reach and what limits it, in words, for ``ltca synthesize``'s
    drive LTE line (after the load sharing's floor).

    Parameters
    ----------
    probes : sequence of HollowProbe
        :func:`hollow_probes`' records.
    target : float — [µrad]
        The development's LTE target ``max_lte``.
    max_edge_share : float — [1]
        The development's edge target.
    tried : collection of float, optional — [µm]
        The crownings the development's step after a design-torque cut tried
        (:mod:`contact.optimize.development_hollow_further`) and did not keep: a free
        probe among them is said so.

    Returns
    -------
    str
        "" where there is no probe; else, e.g., "; a hollow profile lowers it (-5 um:
        17/43 urad, -8 um: 25/38 urad) but the profile's ends it loads limit it: at -5
        um the flank peak 2038 MPa at v 0.86 (…) above the local pitting limit 1630 MPa
        …; at -8 um the
        edges carry 2.3 % of the torque (limit 2 %; the pinion edge 1.6 %), plastic 0.5
        %, …"; a probe within the target that costs none of these is said first ("…: at
        -6 um no edge, plastic or flank-peak cost (…); hollower, the profile's ends it
        loads limit it: …").

    Raises
    ------
    Nothing; a pure function of its inputs.

    Notes
    -----
    Source: module docstring. The target is never relaxed.
    """
    if not probes:
        return ""
    reach = ", ".join(f"{p.crowning:g} um: {p.lte[0]:.0f}/{p.lte[1]:.0f} urad" for p in probes)
    free, limited = [], []
    for p in probes:
        costs = _costs(p, max_edge_share)
        if costs:
            limited.append(f"at {p.crowning:g} um " + ", ".join(costs))
        elif max(p.lte) <= target:
            said = ("tried by the development after the design torque was cut and not "
                    "kept: its other targets or the mounting tolerance" if any(
                        abs(p.crowning - c) <= 1e-4 for c in tried)
                    else "not a step of the development; its other targets and the "
                    "mounting tolerance decide")
            free.append(f"at {p.crowning:g} um no edge, plastic or flank-peak cost ({said})")
    if not free and not limited:
        return f"; a hollow profile ({reach}) does not reach {target:g} urad either"
    text = f"; a hollow profile lowers it ({reach})"
    if free:
        text += ": " + "; ".join(free)
    if limited:
        text += ("; hollower, the profile's ends it loads limit it: " if free
                 else " but the profile's ends it loads limit it: ") + "; ".join(limited)
    return text
