"""Stand-in analyses for the development's check steps (tests/test_development.py,
tests/test_development_coast.py): the setup those tests share.

A check step (contact.optimize.development_check) analyses each design it tries with
``contact.optimize.development_evaluate.analyse_design``; the tests replace it by a
stand-in ``fake(case, torques, misalignment=None, options=None, teeth=None,
pinion_key=(), flank="drive")`` whose metrics follow a law the test states (numbers
measured on a real design, cited in each test), so that a step's choices are checked
without an LTCA. :func:`stand_in` installs the stand-in and returns the targets, the
development setup (light and design torque, centre v) and a scorer of the design the
check chose, the start a step is handed. :func:`law_evaluation` is the checked design of
a law's metrics that the steps' own tests (tests/test_development_given_root.py,
tests/test_development_pitting_step.py) hand their step and its stand-in returns.
"""

from __future__ import annotations

import dataclasses
import types
from collections.abc import Callable, Iterable, Mapping
from typing import Any

import numpy as np

from contact.optimize import development as dev
from contact.optimize.development import DevelopmentTargets, development_score
from contact.optimize.development_result import DevelopmentEvaluation

#: the flank region a law's metrics are scored over (u toe to heel, v root to tip: the
#: whole flank, ``development_score``'s ``grid``)
FLANK_GRID = (0.0, 1.0, 0.0, 1.0)

#: what the check steps call for each design they analyse (replaced by the stand-in)
ANALYSE = "contact.optimize.development_evaluate.analyse_design"


def metrics(**over) -> dict[str, np.ndarray]:
    """Metrics at (light, design) torque of a design meeting every default target; the
    keyword arguments replace single metrics (each a pair, light then design torque)."""
    m = {"pattern_toe_u": [0.2, 0.15], "pattern_heel_u": [0.7, 0.8],
         "pattern_root_v": [0.3, 0.25], "pattern_tip_v": [0.85, 0.9],
         "pattern_centre_u": [0.45, 0.5], "pattern_centre_v": [0.6, 0.6],
         "edge_load_share": [0.0, 0.01], "plastic_share": [0.0, 0.0],
         "lte_peak_to_peak": [20.0, 30.0], "pressure_max_flank": [900.0, 1500.0],
         "lte_spread": [0.0, 0.1]}
    m.update(over)
    return {k: np.asarray(v, float) for k, v in m.items()}


def checked(values, metrics, targets, centre_v) -> dev.DevelopmentEvaluation:
    """A design the check chose (index 3, checked at ltca run's sampling): ``values``
    scored on ``metrics`` against ``targets`` (:func:`development_score`)."""
    full = development_score(metrics, targets, centre_v=centre_v)
    return dev.DevelopmentEvaluation(3, values, metrics, full[0], full[1], full[2], "", 0.0,
                                     full=full, checked=True)


def seen_designs(law: Callable[..., Any]) -> tuple[list[dict], Callable[..., Any]]:
    """(the designs analysed at the nominal mounting, a stand-in analysis): ``fake`` calls
    ``law(case, torques, misalignment, **kw)`` and records ``dict(case)`` of each call
    without a misalignment (the designs a step tried, its tolerance checks apart)."""
    seen: list[dict] = []

    def fake(case, torques, misalignment=None, **kw):
        if misalignment is None:
            seen.append(dict(case))
        return law(case, torques, misalignment, **kw)

    return seen, fake


def stand_in(monkeypatch, fake: Callable[..., Any], torques: Iterable[float],
             centre_v: float = 0.6, targets: DevelopmentTargets | None = None,
             options: Any = None):
    """Install ``fake`` as the development's analysis and return what a check step takes.

    Parameters
    ----------
    monkeypatch : pytest.MonkeyPatch
        The test's, which undoes the replacement after it.
    fake : callable
        The stand-in for ``analyse_design``: ``fake(case, torques, ...)`` returns
        ``(metrics, limits)``.
    torques : iterable of float
        The development's light and design torque, N·m (the setup's ``"torques"``).
    centre_v : float
        The pattern centre's target height (fraction of the working depth) the setup
        carries and the start is scored at.
    targets : DevelopmentTargets, optional
        The development targets; the defaults when not given.
    options : optional
        Passed to ``fake`` as ``options=`` when the start is scored (e.g. the check's
        sampling, ``development.CHECK_LTCA``); not passed when None.

    Returns
    -------
    targets : DevelopmentTargets
    setup : dict
        ``{"torques": [...], "centre_v": centre_v}``.
    chosen : callable
        ``chosen(values)``: the design with bearing ``values`` as the check chose it,
        scored (:func:`checked`) on the stand-in's metrics at ``values``.
    """
    monkeypatch.setattr(ANALYSE, fake)
    targets = DevelopmentTargets() if targets is None else targets
    setup = {"torques": list(torques), "centre_v": centre_v}
    extra = {} if options is None else {"options": options}

    def chosen(values):
        return checked(values, fake(values, [], **extra)[0], targets, centre_v)

    return targets, setup, chosen


def counted_builds(monkeypatch) -> list[str]:
    """Replace the development's FE build of both flanks
    (``contact.optimize.development_root.both_flanks_built``) by a stand-in that builds
    nothing and records the FE level of each case it is handed
    (:func:`contact.compliance.fe.options.fe_level_of`); returns that record."""
    from contact.compliance.fe.options import fe_level_of
    from contact.optimize import development_root

    levels: list[str] = []

    def build(case, earlier=None, say=None):
        levels.append(fe_level_of(case))
        return {}

    monkeypatch.setattr(development_root, "both_flanks_built", build)
    return levels


def law_evaluation(values: Mapping[str, float], metrics: Mapping[str, np.ndarray],
                   targets: DevelopmentTargets, centre_v: float,
                   pressure_limit: float = 2400.0) -> DevelopmentEvaluation:
    """The design with bearing ``values`` as a check step holds it (index 0, checked at
    ltca run's sampling, a case named ``law``): ``metrics`` (a law's, at light and design
    torque) scored against ``targets`` over :data:`FLANK_GRID` at the setup's centre v and
    the flank's pressure limit [MPa] (:func:`development_score`)."""
    full = development_score(metrics, targets, FLANK_GRID, centre_v=centre_v,
                             pressure_limit=pressure_limit)
    return DevelopmentEvaluation(0, dict(values), metrics, full[0], full[1], full[2], "", 0.0,
                                 case=types.SimpleNamespace(name="law"), full=full,
                                 checked=True)


def lte_law_fake(law, torques: Iterable[float], seen: list | None = None
                 ) -> Callable[..., Any]:
    """An ``analysed`` stand-in whose LTE p-p is ``law`` ((torque [N·m], LTE [µrad]) pairs,
    ascending), linear between, every other metric :func:`metrics`' (the light torque's
    value at the first torque, the design torque's at the rest); ``torques`` where called
    with none; each call's torques appended to ``seen``."""
    t, y = np.array(law, float).T
    default = list(torques)

    def fake(case, torques, misalignment=None, options=None, teeth=None, pinion_key=(),
             flank="drive"):
        torques = list(torques) or default
        if seen is not None:
            seen.append(tuple(torques))
        lte = np.interp(torques, t, y)
        return (metrics(**{k: [v[0]] + [v[-1]] * (len(torques) - 1) for k, v in
                           metrics().items()} | {"lte_peak_to_peak": lte}),
                (0.0, 1.0, 0.0, 1.0, 2400.0))
    return fake


def lte_law_start(monkeypatch, law, torques: Iterable[float], values: Mapping[str, float]):
    """(targets, setup, best, seen) of a development stand-in (:func:`stand_in`) whose LTE
    follows ``law`` (:func:`lte_law_fake`), its checked design ``values`` at ``torques``
    (light, design [N·m]), the design torque the ISO capacity; ``seen`` emptied."""
    import dataclasses

    seen: list = []
    torques = list(torques)
    fake = lte_law_fake(law, torques, seen)
    targets, setup, _ = stand_in(monkeypatch, fake, torques)
    setup["source"] = "the ISO 10300 capacity, the pinion torque at which ..."
    best = checked(dict(values), fake(None, torques)[0], targets, 0.6)
    best = dataclasses.replace(best, case=dict(values))
    seen.clear()
    return targets, setup, best, seen


@dataclasses.dataclass(frozen=True)
class WindowResult:
    """The fields of a DevelopmentResult that
    ``development_written_lte.redeveloped_in_window`` reads and replaces (tests/
    test_development_written_lte.py, tests/test_development_window_missed.py), and its
    ``case``, whose capacity ``development._redeveloped_after_cut`` checks (tests/
    test_development_lte_after_cut.py), and its ``seconds`` (the run's own CPU time,
    which ``development._at_written_lte`` replaces by the whole development's: tests/
    test_development_window_middle.py)."""
    best: object
    lte_range: dict | None
    torque: tuple[float, float]
    basic: object = "given"
    torque_source: str = "[synthesis] design_torque of the basic file"
    torque_lowered: bool = False
    lte_torque: float = float("nan")
    case: object = "case"
    coast: dict | None = None
    seconds: float = 0.0
