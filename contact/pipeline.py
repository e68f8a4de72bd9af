"""The whole analysis of a case as one DataTree: geometry → ease-off/UTCA → LTCA.

Like pvlib's ``ModelChain`` this only wires the stage functions together; each stage
can be called on its own. The tree's groups are ``/geometry`` (``/geometry/pinion/
concave`` …), ``/easeoff``, ``/utca`` and ``/ltca``; the root records the case (as
TOML text), the toolkit version and the operating conditions, so the netCDF file alone
says how it was produced.

The bundled cases and the default case are :mod:`contact.catalogue`'s; the efficiency map
over operating points runs on the study engine (:func:`contact.study.efficiency.efficiency_map`).
"""

from __future__ import annotations

import dataclasses
import logging
import math
import os
from collections.abc import Mapping

import numpy as np
import xarray as xr

from contact import catalogue
from contact.chain import (
    AnalysisChain,
    ChainState,
    StepChoice,
    geometry_datasets,  # noqa: F401 (the geometry step's; callers' name)
    resolve_chain,
    run_chain,
)
from contact.ltca import LTCAOptions
from contact.ltca.summary import certification, edge_load_share
from contact.qp.solvers import solver_name
from friction.operating import OperatingConditions
from geometry import __version__
from geometry.case import Case
from geometry.core.blas import blas_threads
from geometry.core.bounds import check_torques
from geometry.core.caches import Same, memoised
from geometry.core.errors import InputError
from geometry.core.text import plain_number
from geometry.pair.assembly import Misalignment

__all__ = [
    "LIGHT_LOAD",
    "MISALIGNMENT_ATTRS",
    "case_torques",
    "coast_flank_torques",
    "flank_torques",
    "floor_torque",
    "misalignment_attrs",
    "operating_conditions",
    "resolve_deviations",
    "result_summary",
    "run_analysis",
]

#: root attributes of an analysis file holding its misalignment, once (units in the names;
#: the groups' ``misalignment`` attribute refers to them)
MISALIGNMENT_ATTRS = tuple(f"misalignment_{k}" for k in Misalignment().labelled())
#: what the groups of an analysis tree say instead of repeating the misalignment
MISALIGNMENT_REFERENCE = "see the root group's attributes " + ", ".join(MISALIGNMENT_ATTRS)

#: The seed's Table 3.1 operating points: pinion torques [N·m] and misalignment
#: |ΔE| = 0.15 mm, |ΔP| = 0.12 mm, ΔG = 0, ΔΣ = 0. The text extraction lost the signs of
#: the seed's ΔE, ΔP (Table 3.1, Figs. 2.11, 3.6, 3.7). In the toolkit's convention
#: (docs/machine.md) we read ΔE = −0.15, ΔP = +0.12: of the four sign choices it is the one
#: for which the seed's two other cases of Table 3.1 / Fig. 3.7 move the pattern as
#: described there — (−0.08, +0.05) towards toe and root, (−0.26, +0.13) towards the heel
#: (tests/test_ltca_seed.py) — and for which its Fig. 2.11 shifts (ΔE 0.08 → toe, ΔE 0.15 →
#: heel) need opposite signs of ΔE, as they do.
#:
#: These are the ``[operating]`` table of the default case (``cases/kolivand2009_fm_11x41
#: .toml``, from its basic file), so ``ltca run``, ``ltca run kolivand2009_fm_11x41`` and
#: ``run_analysis()`` all run them; pass ``misalignment=Misalignment()`` for the aligned pair.
SEED_TABLE_3_1 = {
    "torque": (50.0, 250.0, 500.0),
    "misalignment": Misalignment(delta_E=-0.15, delta_P=0.12),
}

log = logging.getLogger(__name__)


def resolve_deviations(c: Case, deviations) -> tuple | None:
    """The (pinion, gear) SurfaceDeviations of :func:`run_analysis`'s ``deviations``.

    Parameters
    ----------
    c : geometry.case.Case
    deviations : (pinion, gear), False or None
        As :func:`run_analysis`: None reads the case's ``[deviations]`` files.

    Returns
    -------
    (SurfaceDeviation or None, SurfaceDeviation or None) or None
        None for the theoretical surfaces only.

    Raises
    ------
    InputError
        A malformed pair or an unreadable deviation file.
    """
    if deviations is None:
        files = c.deviations
        deviations = None if files is None else (files.pinion, files.gear)
    if deviations is None or deviations is False:
        return None
    if not isinstance(deviations, (tuple, list)) or len(deviations) != 2:
        raise InputError("deviations: must be a (pinion, gear) pair of SurfaceDeviation, "
                         f"file path or None, or False; got {deviations!r}")
    from contact.utca.deviation_files import read_deviations

    out = tuple(
        read_deviations(d, member) if isinstance(d, (str, os.PathLike)) else d
        for d, member in zip(deviations, ("pinion", "gear"), strict=True)
    )
    return None if all(d is None for d in out) else out


def misalignment_attrs(misalignment: Misalignment) -> dict[str, float]:
    """The root attributes that hold a file's misalignment, once: ``misalignment_delta_E_mm``,
    ``…_delta_P_mm``, ``…_delta_G_mm`` [mm] and ``…_delta_Sigma_deg`` [deg]
    (:meth:`geometry.pair.assembly.Misalignment.labelled`)."""
    return {f"misalignment_{k}": v for k, v in misalignment.labelled().items()}


def operating_conditions(case: Case, **override) -> OperatingConditions | None:
    """The efficiency stage's conditions of a case: its ``[operating]`` table
    (``Case.operating``), fields of ``override`` (not None) replacing its values.

    Returns
    -------
    friction.operating.OperatingConditions or None
        None where the pinion speed (the case's or the override) is 0: no efficiency stage.

    Raises
    ------
    InputError, ModelUnavailableError
        An unknown lubricant or friction model, a value out of range (named).
    """
    speed = override.get("pinion_speed")
    speed = case.operating.pinion_speed if speed is None else speed
    if speed == 0:
        return None
    return OperatingConditions.from_point(case.operating, **{**override, "pinion_speed": speed})


def result_summary(name: str, groups: dict[str, xr.Dataset]) -> str:
    """The ACDD ``summary`` of an analysis file: what was run and its result per torque.

    Parameters
    ----------
    name : str
        The case name.
    groups : dict of str to xarray.Dataset
        The analysis groups by path (``/ltca``, optionally ``/friction``,
        ``/mesh_interface``).

    Returns
    -------
    str
        One sentence per torque: LTE mean and peak-to-peak [µrad], peak pressure of the
        flanks and of the edges [MPa], the edges' share of the torque [%], the efficiency
        [%], the mean mesh stiffness [N/µm] and the peak root stress of both members
        [MPa] where the groups hold them (the text spells the units as UDUNITS does,
        ``urad``, ``N/um``, so that a catalogue shows them as the file's variables do);
        the FE level of a root stress on a named cheaper model with its accuracy
        (:func:`contact.ltca.root_stress.fe_level_note`).
    """
    lt = groups["/ltca"]
    fr = groups.get("/friction")
    mi = groups.get("/mesh_interface")
    parts = [f"Loaded tooth contact analysis of {name} (hypoid-ltca)."]
    share = edge_load_share(lt) if "segment_kind" in lt.variables else None
    # the variables' values, not DataArrays (each filters /ltca's 15 coordinates; issue 75)
    val = {k: lt.variables[k].values for k in ("lte_mean", "lte_peak_to_peak",
                                               "pressure_max_flank", "pressure_max_edge")}
    for i, t in enumerate(lt.variables["torque"].values):
        text = (f"T_p {plain_number(t)} N m: LTE mean {float(val['lte_mean'][i]):.1f} urad, "
                f"peak-to-peak {float(val['lte_peak_to_peak'][i]):.1f} urad; peak "
                f"pressure flank {float(val['pressure_max_flank'][i]):.0f} MPa, edge "
                f"{float(val['pressure_max_edge'][i]):.0f} MPa")
        if share is not None:
            text += f", edges carry {100 * share[i]:.1f} % of the torque"
        if fr is not None and "efficiency_mean" in fr:
            eff = float(fr.variables["efficiency_mean"].values[i])
            text += f"; efficiency {100 * eff:.2f} %"
        if mi is not None and "mesh_stiffness_mean" in mi:
            text += (f"; mesh stiffness {float(mi.variables['mesh_stiffness_mean'].values[i]):.0f}"
                     " N/um")
        if "root_stress_max" in lt:
            # the variable and the member labels, not DataArray selections (issue 75)
            rs = lt.variables["root_stress_max"].transpose("torque", "member").values[i]
            members = [str(m) for m in lt.variables["member"].values]
            text += (f"; peak root stress pinion {float(rs[members.index('pinion')]):.0f} "
                     f"MPa, gear {float(rs[members.index('gear')]):.0f} MPa")
        parts.append(text + ".")
    from contact.ltca.root_stress import fe_level_note

    level = fe_level_note(lt)  # a root stress on a named cheaper FE model: said, with its
    if level is not None:  # accuracy (nothing for the default model)
        parts.append(level[0].upper() + level[1:] + ".")
    if fr is not None:
        a = fr.attrs
        parts.append(f"Efficiency at {a.get('pinion_speed_rpm', float('nan')):g} rpm, "
                     f"{a.get('lubricant', '')} at {a.get('inlet_temperature_degC', 0):g} "
                     f"degC, Rq {a.get('roughness_rq_um', 0):g} um, friction model "
                     f"{a.get('friction_model', '')}.")
    return " ".join(parts)


def _fe_level_options(case: Case, fe_level: str | None, fe_options):
    """The FE options of :func:`run_analysis`'s root stress where ``fe_level`` is given
    (``FEOptions.at_level(fe_level)``), else ``fe_options`` as given (None: the root-stress
    step takes the case's level); the case's ``[root_stress]`` table checked either way.

    Raises
    ------
    InputError
        A bad ``[root_stress]`` table or ``fe_level`` (named, with the levels), or
        ``fe_level`` beside FE options given.
    """
    from contact.compliance.fe.options import LEVELS, FEOptions, fe_level_of
    from geometry.core.validation import one_of

    fe_level_of(case)  # refused before any work where bad
    if fe_level is None:
        return fe_options
    one_of("fe_level", fe_level, LEVELS)
    if fe_options is not None:
        raise InputError("fe_level: FE options were given too (root_stress, or steps' "
                         "with_root_stress); give one of the two")
    return FEOptions.at_level(fe_level)


def _point_as_run(c: Case, torques, operating: OperatingConditions | None):
    """The case's OperatingPoint with the torques and efficiency conditions actually run."""
    t = [torques] if np.ndim(torques) == 0 else list(torques)
    kw = {"torque": tuple(float(x) for x in t)}
    if operating is None:
        kw["pinion_speed"] = 0.0
    else:
        kw.update(pinion_speed=operating.pinion_speed, lubricant=os.fspath(operating.lubricant),
                  temperature=operating.temperature, roughness=operating.roughness,
                  friction_model=operating.friction_model_name)
    return dataclasses.replace(c.operating, **kw)


@memoised(maxsize=8)
def _case_as_run(case: Same, point):
    """``dataclasses.replace(case.obj, operating=point)``, the same object for the same
    case object and operating point: the case as run keeps its TOML text and teeth key
    (made once per case object, ~0.5 ms each), so an analysis repeated at the same
    torques does not make them again (issue 75); its teeth key is the case's
    (:meth:`~geometry.case.Case.replaced`: a study's points share the study case's)."""
    return case.obj.replaced(operating=point)


def check_analysis_arguments(case, torque, misalignment, flank, options, **flags) -> None:
    """Refuse a bad argument of :func:`run_analysis` (and of the studies that take the
    same) before any work, in one sentence naming it, what was given and what is accepted
    (the CLI's refusals, for the API).

    Raises
    ------
    InputError
        A ``case`` of another type, a bad torque (:func:`check_torques`), a
        ``misalignment`` that is no Misalignment, a ``flank`` other than ``"drive"``,
        ``"coast"`` (or a pinion flank name), ``options`` that are no LTCAOptions, a flag
        that is not a bool.
    """
    from contact.utca.easeoff import FLANK_ROLES, MATING_FLANK

    if not (case is None or isinstance(case, (Case, str, os.PathLike))):
        raise InputError("case: must be a geometry.case.Case, the path of a case file, the "
                         f"name of a bundled case or None (the default case), got "
                         f"{type(case).__name__} {case!r}")
    if torque is not None:
        check_torques(torque)
    if misalignment is not None and not isinstance(misalignment, Misalignment):
        raise InputError("misalignment: must be a geometry.pair.assembly.Misalignment or None "
                         f"(the case's), got {type(misalignment).__name__} {misalignment!r}")
    flanks = [*FLANK_ROLES, *MATING_FLANK]
    if flank is not None and flank not in flanks:
        raise InputError(f"flank: must be 'drive' or 'coast' (or a pinion flank name, "
                         f"'concave' or 'convex'), got {flank!r}")
    if options is not None and not isinstance(options, LTCAOptions):
        raise InputError("options: must be a contact.ltca.LTCAOptions or None (the defaults), "
                         f"got {type(options).__name__} {options!r}")
    for name, value in flags.items():
        if name == "progress" and value == "lines":  # plain progress lines
            continue
        if not isinstance(value, (bool, np.bool_)):
            raise InputError(f"{name}: must be True or False, got {value!r}")


#: run_analysis's on/off keywords and the named configuration that replaces each
_SWITCH_REPLACEMENT = {
    "geometry": "AnalysisChain.analysis().with_geometry(...)",
    "mesh_interface": "AnalysisChain.analysis().with_mesh_interface(...)",
    "root_stress": "AnalysisChain.analysis().with_root_stress(...) (True, False or the "
                   "FEOptions)",
    "operating": "AnalysisChain.analysis().without('efficiency')",
}


def _warn_switches(**given) -> None:
    """A DeprecationWarning per on/off keyword of :func:`run_analysis` given (issue 72
    item 5: the chain is configured one way, by ``steps``)."""
    import warnings

    for name, value in given.items():
        if value is None or (name == "operating" and value is False):
            continue
        what = "operating=False" if name == "operating" else f"{name}=..."
        warnings.warn(f"run_analysis({what}) is deprecated: give the chain as "
                      f"steps={_SWITCH_REPLACEMENT[name]} (docs/api.md, 'The analysis "
                      "chain')", DeprecationWarning, stacklevel=4)


#: the light torque's share of the design torque [1]: the pattern is developed and judged
#: at 10–20 % of the design torque, as on a roll tester under light brake load (the
#: development's default ``DevelopmentTargets.light_load``; issue 71: no edge contact at
#: 15 % of the design torque, on each flank at its own design torque)
LIGHT_LOAD = 0.15


def floor_torque(torque: float) -> float:
    """A development's torque rounded down for the case it writes: to 0.1 N·m from
    1 N·m up, to four significant digits from 1000 N·m up, below 1 N·m to two
    significant digits.

    Rounded down because the design torque is the rating's capacity by default, at which
    S_H = S_H,min exactly (rounded up it would fail the rating by round-off). The
    earlier ``f"{floor(10 t) / 10:.4g}"`` rounded 5769.55 up to 5770 N·m; the
    relative rounding below 1 N·m keeps a small gear's torques (a module-1.6 spiral bevel
    carries ~2 N·m, its light torque 0.3 N·m, a capacity step 0.05 N·m) above zero: the
    absolute 0.1 N·m alone made them 0 and the analysis refused them.

    Parameters
    ----------
    torque : float — [N·m], finite and > 0

    Returns
    -------
    float — [N·m], in (0, torque]

    Raises
    ------
    ValueError
        ``torque`` not finite or not > 0.

    Notes
    -----
    Source: this project's rounding rule (no standard prescribes one); from 1000 N·m up the
    same 4-digit floor as :func:`contact.load_capacity.iso10300.capacity.floor_capacity`.
    """
    t = float(torque)
    if not (math.isfinite(t) and t > 0):
        raise ValueError(f"torque: must be finite and > 0 [N m], got {torque!r}")
    e = math.floor(math.log10(t))
    step = max(-1, e - 3) if t >= 1.0 else e - 1  # decimal exponent of the kept last digit
    n = math.floor(t / 10.0 ** step * (1.0 + 1e-12))
    while n > 1 and float(f"{n}e{step}") > t:
        n -= 1
    return float(f"{n}e{step}")


def case_torques(light_load: float, torque: float) -> list[float]:
    """The development's (light, design) torques [N·m] as the case it writes runs them:
    ``light_load`` × ``torque`` and ``torque``, each rounded down by
    :func:`floor_torque`, so that the development scores its designs at the very torques
    ``ltca run`` analyses the case at (before, the light torque was scored unrounded:
    40.02 N·m where the case ran at 40.0, issue 71).

    Parameters
    ----------
    light_load : float — [1], the light torque as a fraction of the design torque, > 0
    torque : float — [N·m], the design torque, finite and > 0

    Returns
    -------
    list[float] — [N·m], [light, design], each in (0, its unrounded value]

    Raises
    ------
    ValueError
        A torque not finite or not > 0 (:func:`floor_torque`).

    Notes
    -----
    Source: this project's rounding rule (:func:`floor_torque`).
    """
    return [floor_torque(float(light_load) * float(torque)), floor_torque(torque)]


def coast_flank_torques(torques, coast: float, design: float) -> tuple[float, ...]:
    """The coast flank's torques [N·m]: the drive side's ``torques`` taken at the same
    shares of the coast side's own design torque ``coast`` as of the design torque
    ``design`` — each torque ``t`` below ``design`` to ``t`` × ``coast`` / ``design``
    rounded down (:func:`floor_torque`, as the case's torques are), each at or above it to
    ``coast`` (repeats dropped, the order kept) — where ``coast`` is below ``design`` and a
    torque is above ``coast``; else ``torques`` as given. "At or above ``design``" is at or
    above ``design`` rounded down as the case writes its torques (``floor_torque(design)``):
    a given design torque of five digits, 2923.2 N·m, is written to ``[operating]`` as
    2923 N·m, which is the design torque, not a share of it (before, 2923 × 2694 / 2923.2
    = 2693.8 was rounded down to 2693 N·m, below the coast design torque 2694 N·m the
    development had checked; issue 71, round 25b).

    A synthesised case runs at the development's light torque ``light_load`` × ``design``
    and at ``design`` (:func:`case_torques`): its coast flank so runs at ``light_load`` ×
    ``coast`` (rounded down once more) and at ``coast``, its pattern judged at the same
    light share of its own design torque as the drive's — the user's ``[development]
    light_load`` as the default :data:`LIGHT_LOAD` — wherever the coast design torque is
    below the drive's (issue 71: no edge contact at 15 % of the design torque, on each
    flank at its own). Before, the drive's light torque was kept wherever it was below
    ``coast`` (a 150 N·m coast design torque judged at 45 N·m, 30 % of it, under a
    300 N·m drive) and the coast's own light torque, always 15 %, only added where none
    was (coastlight80). Torques the coast side carries (none above ``coast``) stand as
    given: they are the user's, not shares of a design torque.

    Parameters
    ----------
    torques : sequence of float — [N·m], the drive side's torques (light first), each > 0
    coast : float — [N·m], the coast side's design torque, finite and > 0
    design : float — [N·m], the (drive side's) design torque, finite and > 0

    Returns
    -------
    tuple of float — [N·m]
        Each in (0, ``coast``] where scaled; ``torques`` (as floats) otherwise.

    Raises
    ------
    ValueError
        ``coast`` or ``design`` not finite or not > 0; a torque not finite or not > 0.

    Notes
    -----
    Source: this project's light-torque rule (:data:`LIGHT_LOAD`, :func:`case_torques`:
    the pattern developed and judged at 10–20 % of the design torque, each flank at its
    own), the coast side's design torque of ``ltca synthesize`` (docs/rating.md); the
    share ``t`` / ``design`` taken to 12 significant digits before the rounding down, so
    that a float's round-off (22.499999999999996 for 22.5) does not lose 0.1 N·m.
    """
    c, d = float(coast), float(design)
    for name, value in (("coast", c), ("design", d)):
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"{name}: must be finite and > 0 [N m], got {value!r}")
    given = tuple(float(t) for t in torques)
    for t in given:
        if not (math.isfinite(t) and t > 0):
            raise ValueError(f"torques: each must be finite and > 0 [N m], got {t!r}")
    if c >= d or not given or max(given) <= c:
        return given
    top = floor_torque(d)  # the design torque as the case's [operating] torques write it
    return tuple(dict.fromkeys(c if t >= top else floor_torque(float(f"{t * c / d:.12g}"))
                               for t in given))


def flank_torques(case: Case, flank: str | None = None) -> tuple[tuple[float, ...], str]:
    """The pinion torques [N·m] an analysis of ``flank`` runs at by default, and why.

    The case's ``[operating]`` torques (``Case.operating.torque``) are the drive side's:
    a synthesised case's are the development's light and design torque. The coast side
    has its own design torque where the case's ``[rating]`` gives a ``coast_design_torque``
    below its ``design_torque`` (its ISO 10300 long-life capacity, or the coast flank's
    static, plastic or root-stress capacity at its developed bearing, which ``ltca
    synthesize`` writes; docs/rating.md): where a torque of the case is above it, the coast
    flank is analysed at the case's torques taken at the same shares of the coast design
    torque as of the design torque (those at or above the design torque at the coast
    design torque; :func:`coast_flank_torques`) — a synthesised case's coast flank at its
    own light torque (the development's ``light_load`` × it, rounded down) and its own
    design torque, never above it, as its development judged it (issue 71: each flank
    checked at its own design torque, no edge contact at 15 % of it).

    Parameters
    ----------
    case : geometry.case.Case
    flank : str, optional
        ``"drive"`` (default), ``"coast"`` or a pinion flank name (``"concave"``,
        ``"convex"``; the coast one where it is not the case's drive flank).

    Returns
    -------
    torques : tuple of float — [N·m]
    why : str
        Empty where the torques are the case's own; else one sentence saying to which
        torques they were taken and why.
    """
    torques = tuple(float(t) for t in case.operating.torque)
    if flank is None or flank == "drive" or flank == case.pair.drive_flank:
        return torques, ""
    rating = case.extra.get("rating") or {}
    coast, design = rating.get("coast_design_torque"), rating.get("design_torque")
    if (coast is None or design is None or not 0.0 < float(coast) < float(design)
            or max(torques) <= float(coast)):
        return torques, ""
    limited = coast_flank_torques(torques, float(coast), float(design))
    if limited == torques:
        return torques, ""
    plural = "s" if len(torques) > 1 else ""
    return limited, (f"the case's [operating] torque{plural} "
                     f"{', '.join(map(plain_number, torques))} N m taken at the same "
                     f"shares of its [rating] coast_design_torque "
                     f"{plain_number(coast)} N m (the coast side's own design torque) as of "
                     f"the design torque {plain_number(design)} N m, rounded down: "
                     f"{', '.join(map(plain_number, limited))} N m (none above the coast "
                     "design torque; a light torque at the same share of each flank's "
                     "design torque)")


def _datatree(groups: dict[str, xr.Dataset]) -> xr.DataTree:
    """``xr.DataTree.from_dict(groups)``, built node by node: each node is made once and
    the children attached to their parents from the root down, without copies (from_dict
    copies each node twice more on the way in: ≈ 5 of its 14 ms in a warm analysis, issue
    75), each node's alignment with its parents checked once (attached from the deepest
    up, a subtree's nodes are checked again at every level above them). The same tree
    (``identical``, the groups in the same order); a parent no group names is an empty
    group, as from_dict makes it; anything but Datasets goes to from_dict."""
    if not all(isinstance(ds, xr.Dataset) for ds in groups.values()):
        return xr.DataTree.from_dict(groups)
    norm = {"/" + path.strip("/"): ds for path, ds in groups.items()}
    if len(norm) != len(groups):
        return xr.DataTree.from_dict(groups)  # two names of one group: its refusal
    for path in list(norm):  # parents no group names: empty groups after the named ones
        while path != "/":
            path = path.rpartition("/")[0] or "/"
            norm.setdefault(path, None)
    made = {path: xr.DataTree(dataset=ds) for path, ds in norm.items()}
    children: dict[str, dict[str, xr.DataTree]] = {}
    # siblings in the order of ``groups`` (sorted() is stable; a level's paths all have
    # the same depth)
    for path in sorted(norm, key=lambda p: p.count("/") - (p == "/"), reverse=True):
        if path != "/":
            parent, _, name = path.rpartition("/")
            children.setdefault(parent or "/", {})[name] = made[path]
    # the root first: a node attached to a parent in the tree is checked against it and
    # the parents above once, and it has no children yet to check again
    for path in sorted(children, key=lambda p: p.count("/") - (p == "/")):
        made[path].children = children[path]
    return made["/"]


@blas_threads()  # small dense matrices: one BLAS thread (geometry.core.blas)
def run_analysis(
    case: Case | str | os.PathLike[str] | None = None,
    torque=None,
    *,
    misalignment: Misalignment | None = None,
    flank: str | None = None,
    options: LTCAOptions | None = None,
    operating: OperatingConditions | bool | None = None,
    deviations: tuple | bool | None = None,
    geometry: bool | None = None,
    progress: bool | str = False,
    theoretical: bool = True,
    mesh_interface: bool | None = None,
    root_stress: bool | FEOptions | None = None,  # noqa: F821 (FEOptions: imported lazily)
    steps: AnalysisChain | Mapping[str, StepChoice] | None = None,
    fe_level: str | None = None,
) -> xr.DataTree:
    """Run the analysis chain of a case — geometry, ease-off UTCA, LTCA, root stress, mesh
    interface, efficiency, load capacity (:class:`contact.AnalysisChain`) — and return one
    DataTree: by default the same groups and variables ``ltca run`` writes.

    Parameters
    ----------
    case : Case, path, bundled name, or None
        None runs the bundled default case (:data:`DEFAULT_CASE`, whose ``[operating]``
        table holds the seed's Table 3.1 conditions, :data:`SEED_TABLE_3_1`).
    torque : float or sequence — [N·m], optional
        Pinion torques; default the case's ``[operating]`` torques
        (``Case.operating.torque``; 50, 250, 500 where the table gives none), on the coast
        flank none above the coast side's design torque where the case's ``[rating]`` gives
        a ``coast_design_torque`` below its ``design_torque`` (:func:`flank_torques`).
    misalignment : geometry.pair.assembly.Misalignment, optional
        Default: the case's own (its ``[operating]`` ΔE, ΔP, ΔG, ΔΣ; ``Case.misalignment``).
    flank : str, optional
        ``"drive"`` (default) or ``"coast"``.
    options : contact.ltca.LTCAOptions, optional
        LTCA settings, the solver among them (``LTCAOptions.solver``, default our exact
        ``active_set``); default ``LTCAOptions()``.
    operating : friction.operating.OperatingConditions, False or None
        The conditions of the efficiency stage (pinion speed [rpm], lubricant, oil inlet
        temperature [degC], roughness Rq [µm], friction model; ``/friction``,
        :func:`friction.efficiency.efficiency_analysis`). None (default): the case's
        ``[operating]`` table (:func:`operating_conditions`; no efficiency stage where its
        ``pinion_speed`` is 0); False: no efficiency stage (deprecated, issue 72: give
        ``steps=AnalysisChain.analysis().without("efficiency")``).
    deviations : (pinion, gear), False or None
        Measured or wear deviations of the (pinion, gear) flanks in contact
        (:mod:`contact.utca.deviations`, seed ch. 4): each a SurfaceDeviation [mm], a
        CSV/netCDF file path (:func:`contact.utca.deviation_files.read_deviations`) or None.
        The main groups then hold the deviated surfaces' results and
        ``/theoretical/{easeoff,utca,ltca}`` the theoretical ones, side by side;
        ``/easeoff`` gains ``ease_off_change`` [µm]. None (default) uses the case's
        ``[deviations]`` table if it has one (``Case.deviations``); ``False`` or
        ``(None, None)`` ignores it (theoretical surfaces only).
    geometry : bool, optional
        Include the four generated flanks as ``/geometry`` (the ``geometry`` step; default
        on). False skips the step, as ``steps={"geometry": None}``. Deprecated (issue 72,
        DeprecationWarning): give ``steps=AnalysisChain.analysis().with_geometry(...)``.
    progress : bool or "lines"
        Progress bar over the LTCA roll positions and the unit loads of a first FE build,
        or plain lines with the rate and the remaining time (``"lines"``, as ``ltca run``
        prints when not on a terminal: :mod:`geometry.core.progress`).
    theoretical : bool
        With deviations, also analyse the theoretical surfaces (``/theoretical``,
        default True); False skips them (studies keep only the deviated results, which
        are the same either way).
    mesh_interface : bool, optional
        Add ``/mesh_interface`` (the ``mesh_interface`` step; default on): mesh point, line
        of action, mesh stiffness and transmission-error excitation for dynamic models
        (:func:`contact.ltca.mesh_interface.mesh_interface`). False skips it. Deprecated
        (issue 72): give ``steps=AnalysisChain.analysis().with_mesh_interface(...)``.
    root_stress : bool or contact.compliance.fe.FEOptions, optional
        The ``root_stress`` step: the tooth-root stress of both members in ``/ltca``
        (``root_stress`` [MPa] over (torque, roll, member, tooth, fillet_point),
        ``root_stress_max`` [MPa] over (torque, member);
        :func:`contact.ltca.root_stress.root_stress`) with the default FE model (with
        ``options.compliance == "fe"``: the compliance's FE model,
        ``options.fe_options()``), or with the FE model's options given here. On by
        default, as in ``ltca run`` (it was off before issue 63): a design's first run
        builds its FE influence coefficients, ~15–20 s per member, later runs read them
        from the cache (~1 s); False skips the step. Deprecated (issue 72): give
        ``steps=AnalysisChain.analysis().with_root_stress(True | False | FEOptions)``.
        Without FE options given here or in ``steps``, the root stress is computed on the
        FE level the case names (``[root_stress] fe_level``: the cases ``ltca synthesize``
        writes name ``"coarse10"``; absent, the default model), or ``fe_level``'s.
    steps : contact.AnalysisChain or mapping, optional
        The chain's steps (:mod:`contact.chain`): an :class:`contact.AnalysisChain`, or
        the steps that differ from its defaults, each a name
        (:func:`contact.chain.available_steps`), a callable ``f(state)`` of a
        :class:`contact.chain.ChainState` that adds its group(s) to ``state.groups``, or
        None to skip an optional step — e.g. ``{"load_capacity": None}``. The keywords
        ``geometry``, ``mesh_interface``, ``root_stress`` (False skips, True runs) and
        ``operating=False`` (no ``efficiency`` step) apply on top of it. The
        ``load_capacity`` step writes ``/rating`` (ISO 10300 Method B1, or the method the
        case's ``[rating] method`` names where the steps name none, at the run's torques
        and pinion speed, from the case's ``[design]`` and ``[rating]`` tables) and, with
        ``/friction``, ``/rating/flash_temperature``; without those tables or a speed it
        writes nothing and the root attribute ``load_capacity_not_run`` says why.
    fe_level : str, optional
        The FE model of the root stress by its level
        (:data:`contact.compliance.fe.options.LEVELS`: ``"default"``, ``"coarse"``,
        ``"coarse10"``) instead of the case's ``[root_stress] fe_level`` — ``"default"``
        refines a new design's coarse root stress to the default model (``ltca run
        --fe-level``). Not with FE options given (``root_stress`` or ``steps``). A root
        stress on a level other than the default says so in ``/ltca``
        (``root_stress_max`` attributes ``fe_level``, ``fe_level_accuracy``), the file's
        summary and the verdict's notes.

    Returns
    -------
    xarray.DataTree
        Groups ``/geometry``, ``/easeoff``, ``/utca``, ``/ltca`` (with the root stress),
        ``/mesh_interface``, ``/friction`` (with operating conditions), ``/rating`` and
        ``/rating/flash_temperature`` (where the case can be rated) — those of the steps
        run; root attributes ``case``, ``inputs``
        (the case as TOML, its
        ``[operating]`` table as run), the misalignment once (:data:`MISALIGNMENT_ATTRS`:
        ``misalignment_delta_E_mm`` … ``misalignment_delta_Sigma_deg``; the groups'
        ``misalignment`` attribute refers to them), per-stage times ``time_*_s``,
        ``<step>_not_run`` for an optional step that gave no group (why), and
        ``analysis_status`` (``"ok"``, ``"uncertified"``: some roll positions without a
        certified contact solution, ``"failed"``: some torque without any) with
        ``analysis_status_reason``, the sentence that says where and why
        (:func:`contact.ltca.summary.certification`). A failed or uncertified analysis is
        returned, not raised, so that its file can be written and read; ``ltca run``
        then exits with status 1. Its efficiency is NaN where the contact is not certified
        (:func:`friction.efficiency.efficiency_analysis`).

    Raises
    ------
    InputError
        Bad case, torque, misalignment, flank, options, flags, steps, operating conditions,
        FE level (``fe_level`` or the case's ``[root_stress]`` table, named with the
        accepted levels) or ``[rating]``/``[design]`` table (with the load-capacity
        step), refused before any work (the message names the argument, what was given and what
        is accepted; torques and operating conditions against
        :data:`geometry.core.bounds.PHYSICAL_BOUNDS`, the oil temperature against the oil's
        range).
    PluginError
        A solver, friction or compliance model of the user's that raised or returned what
        its contract refuses (named; docs/extending.md).

    Notes
    -----
    Seed ch. 2 (geometry, ease-off), ch. 3 (UTCA, LTCA), ch. 4 (deviations), ch. 5
    (efficiency); ISO 10300-1/-2/-3:2014 Method B1 (rating), ISO/TS 6336-20 (flash
    temperature). The chain after pvlib's ``ModelChain`` (docs/api.md, "The analysis
    chain").

    Examples
    --------
    The contact alone, as a study's hot loop runs it::

        tree = run_analysis(None, [250.0], steps=AnalysisChain.contact_only())
    """
    _warn_switches(geometry=geometry, mesh_interface=mesh_interface,
                   root_stress=root_stress, operating=operating is False)
    flags = {k: v for k, v in (("geometry", geometry), ("mesh_interface", mesh_interface))
             if v is not None}
    check_analysis_arguments(case, torque, misalignment, flank, options,
                             progress=progress, theoretical=theoretical, **flags)
    c = catalogue.resolve_case(case)
    if misalignment is not None:
        c = c.replaced(misalignment=misalignment)
    fe_options = None
    if root_stress not in (None, False, True):
        from contact.compliance.fe import FEOptions
        from contact.compliance.fe.options import level_hint

        if not isinstance(root_stress, FEOptions):
            raise InputError("root_stress: must be True, False or a "
                             f"contact.compliance.fe.FEOptions, got {root_stress!r}"
                             f"{level_hint(root_stress)}")
        fe_options = root_stress
    if operating is not None and operating is not False and not isinstance(
            operating, OperatingConditions):
        raise InputError("operating: must be a friction.operating.OperatingConditions, False "
                         f"or None, got {operating!r}")
    from contact.load_capacity.methods import case_method

    chosen = case_method(c)  # the case's [rating] method, where the steps name none
    if chosen is not None and (steps is None or (isinstance(steps, Mapping)
                                                 and "load_capacity" not in steps)):
        steps = {**(steps or {}), "load_capacity": chosen}
    chain = resolve_chain(steps, geometry=geometry, mesh_interface=mesh_interface,
                          root_stress=None if root_stress is None else root_stress is not False,
                          efficiency=False if operating is False else None)
    if fe_options is None:
        fe_options = chain.fe_options
    if fe_level is not None or "root_stress" in c.extra:  # (skfem imported only then)
        fe_options = _fe_level_options(c, fe_level, fe_options)
    torques = flank_torques(c, flank)[0] if torque is None else torque
    opts = options or LTCAOptions()
    if chain.efficiency is None:
        operating = None
    elif operating is None:
        operating = operating_conditions(c)
    if operating is not None:  # the oil's range before the work, not after the LTCA
        operating.check_oil_temperature()
    # the case as run: its [operating] table (in the file's ``inputs``) records what ran
    c = _case_as_run(Same(c), _point_as_run(c, torques, operating))
    state = run_chain(chain, ChainState(
        case=c, torque=torques, flank=flank, options=opts, operating=operating,
        deviations=resolve_deviations(c, deviations), theoretical=theoretical,
        progress=progress, fe_options=fe_options))
    tree, times = state.groups, state.times
    ltca_ds = tree["/ltca"]
    # the misalignment is stored once, at the root: the groups' ``misalignment`` refers to
    # it (set on the tree's nodes below, whose attributes are the tree's own copies)
    refer = [path for path, ds in tree.items() if "misalignment" in ds.attrs]
    root = xr.Dataset(
        attrs={
            "title": f"hypoid-ltca analysis of {c.name}",
            "case": c.name,
            "case_source": c.source,
            "toolkit_version": __version__,
            "solver": solver_name(opts.solver),
            **misalignment_attrs(c.misalignment),
            **{f"time_{k}_s": v for k, v in times.items()},
            **{f"{k}_not_run": why for k, why in state.not_run.items()},
        }
    )
    root.attrs["summary"] = result_summary(c.name, tree)
    cert = certification(ltca_ds)
    root.attrs["analysis_status"] = cert.status
    root.attrs["analysis_status_reason"] = cert.reason
    tree["/"] = root
    out = _datatree(tree)
    for path in refer:
        out[path].attrs["misalignment"] = MISALIGNMENT_REFERENCE
    out.attrs["inputs"] = c.to_toml()
    if cert.status != "ok":
        log.warning("%s (/ltca status)", cert.reason)
    return out
