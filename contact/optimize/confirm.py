"""Confirming an optimiser's design as ``ltca run`` will analyse its written case.

The optimiser ranks designs at its own sampling (the ``[optimize]`` table's
``rolls_per_cycle``/``segments``, or coarser ones given on the command line), without the
rating and without the FE root-stress model. What it reports as met must hold where the
user looks next: ``ltca run`` of the written case. :func:`confirm_design` therefore analyses
a chosen design with :func:`contact.pipeline.run_analysis` at ``ltca run``'s defaults (its
sampling, the problem's solver and compliance model, the case's ``[operating]`` table, the
ISO 10300 rating) at every misalignment and torque of the problem, re-evaluates the
problem's constraints there, takes the analysis's verdict
(:func:`contact.study.verdicts.verdict`) and builds the FE mesh of the pinion's tooth at the
root-stress model's settings (:func:`contact.compliance.fe.solid.build_tooth_solid`, the
mapping's Jacobian check; ≈ 2–4 s, no solve), so that a case the FE model cannot mesh is
never written (``ltca run``'s root stress and ``ltca duty-cycle`` would fail on it).

Public names
------------
BEARING_CHECKS   verdict checks a bearing change answers
Confirmation     what the confirmation of one design found
confirm_design   confirm one evaluated design
"""

from __future__ import annotations

import dataclasses
import logging
import time
from dataclasses import dataclass

import numpy as np

from contact.optimize.objective import METRICS, Evaluation, constraint_names, score

__all__ = ["BEARING_CHECKS", "Confirmation", "confirm_design"]

log = logging.getLogger(__name__)

#: the verdict's checks a bearing change answers (as ``ltca run``'s next steps)
BEARING_CHECKS = ("implausible", "plastic_edges", "edge_pressure", "edge_contact",
                  "flank_pressure")


@dataclass(frozen=True)
class Confirmation:
    """The confirmation of one design (:func:`confirm_design`).

    Attributes
    ----------
    index : int
        The design's evaluation number.
    x : ndarray (n_var,) — [file units]
    metrics : dict of str → ndarray (n_mis, n_torque)
        :data:`contact.optimize.objective.METRICS` at ``ltca run``'s sampling.
    constraints : ndarray (n_con,)
        The problem's normalised constraints there (≤ 0 met; inf where not computed).
    violated : tuple of str
        Names of the constraints not met (:func:`constraint_names`).
    severity : str
        The verdict of the ``ltca run``-equivalent analysis, worst over the misalignments
        (``"pass"``, ``"attention"``, ``"fail"``; ``""`` when it did not run).
    findings : tuple of str
        The verdict's failing findings (one sentence each).
    mesh : str
        Empty, or why the FE mesh of the pinion's tooth cannot be built.
    seconds : float
        Wall time [s].
    bearing_fail : bool
        A failing finding is one of :data:`BEARING_CHECKS`.
    attention : tuple of str
        The verdict's ATTENTION findings (one sentence each): printed where the verdict is
        ATTENTION, so that a design whose constraints are met but whose verdict is worse
        than PASS says why (round 27: the FH 6×43 at Σ 80°, PASS as synthesised, was
        confirmed "ltca run's verdict ATTENTION" without the reason, its pattern reaching
        the gear's tip at the design torque).
    start_severity : str
        The start case's verdict confirmed the same way (``""`` where not known, e.g. the
        start's own confirmation): a design whose verdict is worse than it is not accepted
        (round 27: the optimiser wrote an ATTENTION design for a PASS start).
    """

    index: int
    x: np.ndarray
    metrics: dict
    constraints: np.ndarray
    violated: tuple[str, ...]
    severity: str
    findings: tuple[str, ...]
    mesh: str
    seconds: float
    bearing_fail: bool = False
    attention: tuple[str, ...] = ()
    start_severity: str = ""

    @property
    def worse_than_start(self) -> bool:
        """The verdict is worse than the start's (both known): PASS → ATTENTION or FAIL,
        ATTENTION → FAIL (:data:`contact.study.verdicts.SEVERITIES`, mildest first)."""
        from contact.study.verdicts import SEVERITIES

        if self.severity not in SEVERITIES or self.start_severity not in SEVERITIES:
            return False
        return SEVERITIES.index(self.severity) > SEVERITIES.index(self.start_severity)

    @property
    def met(self) -> bool:
        """Every constraint of the problem met at ``ltca run``'s sampling."""
        return not self.violated

    @property
    def accepted(self) -> bool:
        """Constraints met, the FE mesh built, no bearing finding of ``ltca run``'s verdict
        a FAIL (a capacity FAIL is the gear set's, which no flank setting answers), and the
        verdict no worse than the start's (:attr:`worse_than_start`)."""
        return (self.met and not self.mesh and not self.bearing_fail
                and not self.worse_than_start)

    def summary(self) -> str:
        """One line: what the confirmation found."""
        if self.mesh:
            return f"rejected: the FE model cannot mesh its pinion tooth ({self.mesh})"
        parts = ["constraints met" if self.met else
                 "not met: " + ", ".join(self.violated)]
        if self.severity:
            why = self.findings if self.severity == "fail" else (
                self.attention if self.severity == "attention" else ())
            parts.append(f"ltca run's verdict {self.severity.upper()}"
                         + (f" ({'; '.join(why)})" if why else ""))
        if self.worse_than_start:
            parts.append(f"worse than the start's {self.start_severity.upper()}: not "
                         "accepted")
        return "; ".join(parts)


def confirm_design(shared, ev: Evaluation, *, root_stress_options=None) -> Confirmation:
    """Analyse one evaluated design as ``ltca run`` analyses its written case.

    Parameters
    ----------
    shared : contact.optimize.run.SharedDesign
        The start case, the problem, the variable names.
    ev : contact.optimize.objective.Evaluation
        The design (its values ``ev.x`` in file units).
    root_stress_options : contact.compliance.fe.FEOptions, optional
        The FE model whose mesh is checked; default the root-stress step's
        (``FEOptions()``, or the compliance's own with ``compliance="fe"``).

    Returns
    -------
    Confirmation
        Never raises for a failing design: an analysis that fails leaves the constraints
        at inf (not met) and says why in ``findings``.

    Notes
    -----
    Sampling and models are :class:`contact.ltca.LTCAOptions`' defaults (``ltca run``'s:
    20 rolls per cycle, 24 segments, Ritz 6 × 21) with the problem's solver and
    compliance model; the misalignments and torques are the problem's; the case's
    deviations are not applied (as in the optimisation). The verdict is
    :func:`contact.study.verdicts.verdict` of each analysis (docs/verdicts.md).
    """
    from contact.chain import AnalysisChain
    from contact.compliance.fe import FEOptions
    from contact.compliance.fe.solid import build_tooth_solid
    from contact.ltca import LTCAOptions
    from contact.optimize.variables import case_at
    from contact.pipeline import run_analysis
    from contact.study.summary import point_summary
    from contact.study.verdicts import SEVERITIES, verdict
    from geometry.core.errors import LTCAError, raise_if_interrupted

    t0 = time.perf_counter()
    problem = shared.problem
    x = np.asarray(ev.x, float)
    nm, nt = len(problem.misalignments), len(problem.torque)
    metrics = {k: np.full((nm, nt), np.nan) for k in METRICS}
    names = constraint_names(problem)
    if shared.start is not None and np.array_equal(x, shared.start):
        case = shared.case
    else:
        case = case_at(shared.case, shared.pinion_flank, shared.names, x,
                       relief_start=shared.relief_start, basic=shared.basic)
    mesh = ""
    fe = root_stress_options
    if fe is None:
        fe = (problem.options.fe_options() if problem.options.compliance == "fe"
              else FEOptions())
    try:
        build_tooth_solid(case, "pinion", fe)
    except (LTCAError, ValueError, ArithmeticError) as exc:
        mesh = str(exc).splitlines()[0]
    except Exception as exc:  # an InputError of the FE model (e.g. its rim): no mesh either
        raise_if_interrupted(exc)
        mesh = f"{type(exc).__name__}: {exc}".splitlines()[0]
    if mesh:
        return Confirmation(ev.index, x, metrics, np.full(len(names), np.inf), names, "",
                            (), mesh, time.perf_counter() - t0)
    opts = LTCAOptions(solver=problem.options.solver, compliance=problem.options.compliance)
    severity, findings, bearing, attention = SEVERITIES[0], [], False, []
    try:
        for im, mis in enumerate(problem.misalignments):
            c = dataclasses.replace(case, misalignment=mis)
            tree = run_analysis(c, list(problem.torque), flank=problem.flank, options=opts,
                                deviations=False,
                                steps=AnalysisChain.analysis().without("geometry",
                                                                       "root_stress"))
            s = point_summary(tree, c)
            for k in METRICS:
                metrics[k][im] = s[k]
            v = verdict(tree)
            if SEVERITIES.index(v.severity) > SEVERITIES.index(severity):
                severity = v.severity
            for f in v.findings:
                if f.severity == "fail":
                    findings.append(f.reason)
                    bearing = bearing or f.check in BEARING_CHECKS
                elif f.severity == "attention":
                    attention.append(f.reason)
        _, g, _ = score(problem, metrics)
    except Exception as exc:  # the confirmation of one design never stops the command
        raise_if_interrupted(exc)
        log.info("confirmation of design %d failed: %s", ev.index, exc)
        g = np.full(len(names), np.inf)
        severity, findings = "", [f"the analysis failed: {type(exc).__name__}: {exc}"
                                  .splitlines()[0]]
    violated = tuple(n for n, gi in zip(names, g, strict=True) if not gi <= 0.0)
    return Confirmation(ev.index, x, metrics, np.asarray(g, float), violated, severity,
                        tuple(dict.fromkeys(findings)), "", time.perf_counter() - t0,
                        bearing, tuple(dict.fromkeys(attention)))
